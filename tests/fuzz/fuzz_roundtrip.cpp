// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Read, write in every format and encoding, read back, compare. Steering: the reader is
// chosen from the content (sniff_format), so seeds of every format work unchanged.
// OBJ, OFF and PLY must give the mesh back bit for bit. STL fan-triangulates, welds
// equal positions and (binary) stores float32: the read-back triangles must be the fan
// triangles of the faces, corner for corner, at the same (float32-rounded) positions;
// refusing the file back is allowed only when welding makes a triangle degenerate, and
// refusing to write binary STL only for coordinates beyond the float32 range.

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

void check_exact(const Mesh& mesh, io::Format format, io::Encoding encoding)
{
    const std::string what =
        std::string(io::format_name(format)) + " " + std::string(io::encoding_name(encoding));
    const std::string data = io::write_mesh_data(mesh, format, io::WriteOptions{encoding});
    const auto back = read_or_refuse(data, format);
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
}

int test_one_input(const std::uint8_t* data, size_t size)
{
    if (size > kMaxInput)
        return 0;
    const std::string_view text = as_text(data, size);
    const auto mesh = read_or_refuse(text, sniff_format(text));
    if (!mesh)
        return 0;
    check_exact(*mesh, io::Format::Obj, io::Encoding::Ascii);
    check_exact(*mesh, io::Format::Off, io::Encoding::Ascii);
    for (const auto e :
         {io::Encoding::Ascii, io::Encoding::BinaryLittleEndian, io::Encoding::BinaryBigEndian})
        check_exact(*mesh, io::Format::Ply, e);
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
