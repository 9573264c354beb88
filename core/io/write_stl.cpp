// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_stl.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "core/errors.h"
#include "core/io/text_reader.h"
#include "core/io/text_writer.h"

namespace meshfair::io {

namespace {

// Unit normal of the triangle (a, b, c), or 0 0 0 when it has no area.
Vec3 triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const Vec3 v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0) || !std::isfinite(length))
        return {0, 0, 0};
    return {n[0] / length, n[1] / length, n[2] / length};
}

// Calls visit(f, v0, v1, v2) for each triangle of the fan of every face f from its first
// corner.
template <typename Visit>
void for_each_fan_triangle(const Mesh& mesh, Visit&& visit)
{
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const auto face = mesh.face(f);
        for (size_t k = 1; k + 1 < face.size(); ++k)
            visit(f, face[0], face[k], face[k + 1]);
    }
}

void append_vector(std::string& out, const Vec3& p)
{
    for (int c = 0; c < 3; ++c)
    {
        out += ' ';
        append_double(out, p[c]);
    }
}

// The text of a facet besides its corners' coordinates: keywords, indentation, line
// ends and at most 25 characters per normal component ("-2.2250738585072014e-308").
constexpr size_t kFacetTextBytes = 14 + 3 * 25 + 16 + 3 * 13 + 23;

void write_ascii(const Mesh& mesh, std::string& out)
{
    // A vertex is a corner of about six triangles: format its coordinates once.
    std::string coordinates;
    std::vector<size_t> starts{0};
    starts.reserve(static_cast<size_t>(mesh.vertex_count()) + 1);
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        append_vector(coordinates, mesh.position(i));
        starts.push_back(coordinates.size());
    }
    // Reserving the whole text up front avoids copying hundreds of megabytes as it grows.
    size_t size = 0;
    for_each_fan_triangle(mesh, [&](Index, Index a, Index b, Index c) {
        size += kFacetTextBytes;
        for (const Index v : {a, b, c})
            size += starts[static_cast<size_t>(v) + 1] - starts[static_cast<size_t>(v)];
    });
    out.reserve(out.size() + size + 64);
    out += "solid meshfair\n";
    for_each_fan_triangle(mesh, [&](Index, Index a, Index b, Index c) {
        out += "  facet normal";
        append_vector(out, triangle_normal(mesh.position(a), mesh.position(b), mesh.position(c)));
        out += "\n    outer loop\n";
        for (const Index v : {a, b, c})
        {
            const auto k = static_cast<size_t>(v);
            out += "      vertex";
            out.append(coordinates, starts[k], starts[k + 1] - starts[k]);
            out += '\n';
        }
        out += "    endloop\n  endfacet\n";
    });
    out += "endsolid meshfair\n";
}

template <typename T>
void append_little_endian(std::string& out, T value)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
        for (size_t k = 0; k < sizeof(T) / 2; ++k)
            std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
    out.append(bytes, sizeof(T));
}

void append_float(std::string& out, double value)
{
    append_little_endian(out, static_cast<float>(value));
}

void write_binary(const Mesh& mesh, const Property* attribute, std::string& out)
{
    // Binary STL stores float32: a finite double beyond its range would become inf and
    // make a file that no reader accepts.
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    for (size_t k = 0; k < mesh.positions.size(); ++k)
        if (!(std::abs(mesh.positions[k]) <= kFloatMax))
            throw InvalidInputError("write_stl: vertex " + std::to_string(k / 3) +
                                    " has a coordinate beyond the float32 range of binary STL; "
                                    "write ASCII STL instead");
    std::int64_t triangles = 0;
    for (Index f = 0; f < mesh.face_count(); ++f)
        triangles += mesh.face_size(f) - 2;

    // The header must not start with "solid", or readers may take the file for ASCII.
    std::string header = "MeshFair binary STL";
    header.resize(80, ' ');
    out.reserve(out.size() + 84 + 50 * static_cast<size_t>(triangles));
    out += header;
    append_little_endian(out, static_cast<std::uint32_t>(triangles));
    for_each_fan_triangle(mesh, [&](Index f, Index a, Index b, Index c) {
        const Vec3 pa = mesh.position(a), pb = mesh.position(b), pc = mesh.position(c);
        for (const Vec3& p : {triangle_normal(pa, pb, pc), pa, pb, pc})
            for (int k = 0; k < 3; ++k)
                append_float(out, p[k]);
        // A polygon's triangles share its attribute bytes.
        append_little_endian(
            out, attribute ? static_cast<std::uint16_t>(attribute->values[static_cast<size_t>(f)])
                           : std::uint16_t{0});
    });
}

} // namespace

void write_stl(const Mesh& mesh, const MeshAttributes& attributes, Encoding encoding,
               std::string& out, std::vector<std::string>& notes)
{
    // A binary STL's attribute bytes hold an unsigned 16-bit value per triangle.
    const Property* attribute = nullptr;
    if (encoding != Encoding::Ascii)
        if (const Property* p = attributes.face.find(kStlAttribute);
            p && p->type == ValueType::UInt16)
            attribute = p;
    Unwritten unwritten(encoding == Encoding::Ascii ? "ASCII STL" : "STL");
    unwritten.add_table(attributes.vertex, {});
    unwritten.add_table(attributes.face, {attribute});
    unwritten.add_elements(attributes.other_elements);
    if (!attributes.texcoords.empty())
        unwritten.add("OBJ per-corner values", "texture coordinates (vt)");
    if (!attributes.normals.empty())
        unwritten.add("OBJ per-corner values", "normals (vn; facet normals are written instead)");
    for (const ObjStatement& s : attributes.statements)
        unwritten.add("OBJ groups, objects, smoothing groups and materials", "'" + s.text + "'");
    if (!attributes.comments.empty())
        unwritten.add("PLY header comments", std::to_string(attributes.comments.size()));
    unwritten.flush(notes);

    std::vector<char> in_a_face(static_cast<size_t>(mesh.vertex_count()), 0);
    std::int64_t polygons = 0;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        polygons += mesh.face_size(f) > 3 ? 1 : 0;
        for (const Index v : mesh.face(f))
            in_a_face[static_cast<size_t>(v)] = 1;
    }
    if (const auto isolated = std::count(in_a_face.begin(), in_a_face.end(), 0); isolated > 0)
        notes.push_back("STL cannot hold vertices without faces; " +
                        count_of(isolated, "vertex is", "vertices are") + " not written");
    if (polygons > 0)
        notes.push_back("STL holds triangles: " + count_of(polygons, "polygon", "polygons") +
                        " of more than 3 sides written as fans of triangles from their first "
                        "corner");

    // STL has one binary layout, little endian; every binary encoding selects it.
    if (encoding == Encoding::Ascii)
        write_ascii(mesh, out);
    else
        write_binary(mesh, attribute, out);
}

} // namespace meshfair::io
