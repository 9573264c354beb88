// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Read, write in every format and encoding, read back, compare. Steering: the reader is
// chosen from the content (sniff_format), so seeds of every format work unchanged.
// OBJ, OFF and PLY must give the mesh back bit for bit, written with the attributes the
// file held (converted to the other formats, never refused); in the file's own format the
// attributes must come back as they were (normals kept, NaN equal to NaN; a PLY's
// comments gain MeshFair's own). STL fan-triangulates, welds
// equal positions and (binary) stores float32: the read-back triangles must be the fan
// triangles of the faces, corner for corner, at the same (float32-rounded) positions;
// refusing the file back is allowed only when welding makes a triangle degenerate, and
// refusing to write binary STL only for coordinates beyond the float32 range.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "tests/fuzz/fuzz_support.h"

namespace meshfair::fuzz {
namespace {

Vec3 rounded(const Vec3& p, bool to_float)
{
    if (!to_float)
        return p;
    return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

bool beyond_float(const Mesh& mesh)
{
    for (const double x : mesh.positions)
        if (std::abs(x) > std::numeric_limits<float>::max())
            return true;
    return false;
}

void check_stl(const Mesh& mesh, io::Encoding encoding)
{
    const bool binary = encoding != io::Encoding::Ascii;
    const std::string what = binary ? "binary STL" : "ASCII STL";
    std::string data;
    try
    {
        data = io::write_mesh_data(mesh, io::Format::Stl, io::WriteOptions{encoding});
    }
    catch (const InvalidInputError& e)
    {
        if (binary && beyond_float(mesh))
            return;
        fail(what + " write refused: " + e.what());
    }
    // The fan triangles of every face, as written.
    std::vector<std::array<Vec3, 3>> fan;
    bool degenerate = false;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const auto face = mesh.face(f);
        for (size_t k = 1; k + 1 < face.size(); ++k)
        {
            const std::array<Vec3, 3> t{rounded(mesh.position(face[0]), binary),
                                        rounded(mesh.position(face[k]), binary),
                                        rounded(mesh.position(face[k + 1]), binary)};
            degenerate = degenerate || t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
            fan.push_back(t);
        }
    }
    const auto back = read_or_refuse(data, io::Format::Stl);
    if (!back)
    {
        if (degenerate)
            return;
        fail(what + " written from a mesh without degenerate triangles is refused");
    }
    if (back->face_count() != static_cast<Index>(fan.size()))
        fail(what + ": " + std::to_string(back->face_count()) + " triangles read back, " +
             std::to_string(fan.size()) + " written");
    for (Index t = 0; t < back->face_count(); ++t)
    {
        const auto face = back->face(t);
        if (face.size() != 3)
            fail(what + ": triangle " + std::to_string(t) + " read back as a polygon");
        for (size_t k = 0; k < 3; ++k)
            if (back->position(face[k]) != fan[static_cast<size_t>(t)][k])
                fail(what + ": triangle " + std::to_string(t) + " corner " + std::to_string(k) +
                     " moved");
    }
}

// Attribute equality with NaN equal to NaN (a PLY's float properties may hold it).
bool same_values(const std::vector<double>& a, const std::vector<double>& b)
{
    if (a.size() != b.size())
        return false;
    for (size_t k = 0; k < a.size(); ++k)
        if (!(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k]))))
            return false;
    return true;
}

bool same_table(const io::Element& a, const io::Element& b)
{
    if (a.name != b.name || a.count != b.count || a.properties.size() != b.properties.size())
        return false;
    for (size_t k = 0; k < a.properties.size(); ++k)
    {
        const io::Property &p = a.properties[k], &q = b.properties[k];
        if (p.name != q.name || p.type != q.type || p.is_list != q.is_list ||
            (p.is_list && (p.count_type != q.count_type || p.offsets != q.offsets)) ||
            !same_values(p.values, q.values))
            return false;
    }
    return true;
}

bool same_attributes(const io::MeshAttributes& a, const io::MeshAttributes& b)
{
    if (!same_table(a.vertex, b.vertex) || !same_table(a.face, b.face) ||
        a.other_elements.size() != b.other_elements.size())
        return false;
    for (size_t k = 0; k < a.other_elements.size(); ++k)
        if (!same_table(a.other_elements[k], b.other_elements[k]))
            return false;
    return a.texcoords == b.texcoords && a.normals == b.normals && a.statements == b.statements &&
           a.comments == b.comments;
}

void check_exact(const Mesh& mesh, const io::MeshAttributes& attributes, io::Format source,
                 io::Format format, io::Encoding encoding)
{
    const std::string what =
        std::string(io::format_name(format)) + " " + std::string(io::encoding_name(encoding));
    const io::WriteOptions options{encoding, io::Normals::Keep};
    std::string data;
    try
    {
        data = io::write_mesh_data(mesh, format, options, &attributes);
    }
    catch (const std::exception& e)
    {
        fail(what + ": write with the attributes refused: " + e.what());
    }
    io::MeshAttributes back_attributes;
    const auto back = read_or_refuse(data, format, nullptr, &back_attributes);
    if (!back)
    {
        // Read again without catching, so the report shows the reader's message.
        try
        {
            io::read_mesh_data(data, format, "roundtrip");
        }
        catch (const std::exception& e)
        {
            fail(what + ": written file refused: " + e.what());
        }
    }
    if (back->vertex_count() != mesh.vertex_count())
        fail(what + ": " + std::to_string(back->vertex_count()) + " vertices read back, " +
             std::to_string(mesh.vertex_count()) + " written");
    if (!identical(*back, mesh))
        fail(what + ": the mesh read back differs from the mesh written");
    if (format != source)
        return;
    io::MeshAttributes expected = attributes;
    if (format == io::Format::Ply && std::find(expected.comments.begin(), expected.comments.end(),
                                               "comment MeshFair") == expected.comments.end())
        expected.comments.insert(expected.comments.begin(), "comment MeshFair");
    if (!same_attributes(back_attributes, expected))
        fail(what + ": the attributes read back differ from those written");
}

int test_one_input(const std::uint8_t* data, size_t size)
{
    if (size > kMaxInput)
        return 0;
    const std::string_view text = as_text(data, size);
    const io::Format source = sniff_format(text);
    io::MeshAttributes attributes;
    const auto mesh = read_or_refuse(text, source, nullptr, &attributes);
    if (!mesh)
        return 0;
    check_exact(*mesh, attributes, source, io::Format::Obj, io::Encoding::Ascii);
    check_exact(*mesh, attributes, source, io::Format::Off, io::Encoding::Ascii);
    for (const auto e :
         {io::Encoding::Ascii, io::Encoding::BinaryLittleEndian, io::Encoding::BinaryBigEndian})
        check_exact(*mesh, attributes, source, io::Format::Ply, e);
    check_stl(*mesh, io::Encoding::Ascii);
    check_stl(*mesh, io::Encoding::BinaryLittleEndian);
    return 0;
}

} // namespace
} // namespace meshfair::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    return meshfair::fuzz::test_one_input(data, size);
}
