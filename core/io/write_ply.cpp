// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_ply.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>

#include "core/io/text_writer.h"

namespace meshfair::io {

namespace {

// Inlined: a write calls it for every value of the mesh.
template <typename T>
[[gnu::always_inline]] inline void append_binary(std::string& out, T value, bool is_big_endian)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (is_big_endian != (std::endian::native == std::endian::big))
        for (size_t k = 0; k < sizeof(T) / 2; ++k)
            std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
    out.append(bytes, sizeof(T));
}

// `value`'s bytes in the given order at `at`; returns the next byte.
template <typename T>
[[gnu::always_inline]] inline char* store(char* at, T value, bool is_big_endian)
{
    std::memcpy(at, &value, sizeof(T));
    if (is_big_endian != (std::endian::native == std::endian::big))
        std::reverse(at, at + sizeof(T));
    return at + sizeof(T);
}

// `bytes` more at the end of `out`, to be stored into.
char* grown(std::string& out, size_t bytes)
{
    const size_t size = out.size();
    out.resize(size + bytes);
    return out.data() + size;
}

// One value in its type: binary bytes, or text after a separating space.
class ValueWriter
{
public:
    ValueWriter(std::string& out, Encoding encoding)
        : out_(out),
          ascii_(encoding == Encoding::Ascii),
          big_(encoding == Encoding::BinaryBigEndian)
    {
    }

    void put(double v, ValueType type)
    {
        if (ascii_)
        {
            if (!row_start_)
                out_ += ' ';
            row_start_ = false;
            append_value(out_, v, type);
            return;
        }
        switch (type)
        {
            case ValueType::Int8:
                return append_binary(out_, static_cast<std::int8_t>(v), big_);
            case ValueType::UInt8:
                return append_binary(out_, static_cast<std::uint8_t>(v), big_);
            case ValueType::Int16:
                return append_binary(out_, static_cast<std::int16_t>(v), big_);
            case ValueType::UInt16:
                return append_binary(out_, static_cast<std::uint16_t>(v), big_);
            case ValueType::Int32:
                return append_binary(out_, static_cast<std::int32_t>(v), big_);
            case ValueType::UInt32:
                return append_binary(out_, static_cast<std::uint32_t>(v), big_);
            case ValueType::Float32:
                return append_binary(out_, static_cast<float>(v), big_);
            case ValueType::Float64:
                return append_binary(out_, v, big_);
        }
    }

    // Row `r` of a property.
    void put(const Property& p, Index r)
    {
        const auto row = static_cast<size_t>(r);
        if (!p.is_list)
            return put(p.values[row], p.type);
        const Index begin = p.offsets[row], end = p.offsets[row + 1];
        put(end - begin, p.count_type);
        for (Index k = begin; k < end; ++k)
            put(p.values[static_cast<size_t>(k)], p.type);
    }

    void end_row()
    {
        if (ascii_)
            out_ += '\n';
        row_start_ = true;
    }

private:
    std::string& out_;
    bool ascii_, big_;
    bool row_start_ = true;
};

void append_declaration(std::string& out, const Property& p)
{
    out += "property ";
    if (p.is_list)
    {
        out += "list ";
        out += value_type_name(p.count_type);
        out += ' ';
    }
    out += value_type_name(p.type);
    out += ' ';
    out += p.name;
    out += '\n';
}

void append_element(std::string& out, const std::string& name, Index count)
{
    out += "element ";
    out += name;
    out += ' ';
    append_integer(out, count);
    out += '\n';
}

// What the vertex and face elements get beside the mesh: the attribute tables' own
// properties and those converted from an OBJ's per-corner values.
struct Columns
{
    std::vector<const Property*> vertex, face;
    std::deque<Property> converted; // owns the converted columns (stable addresses)
};

Property& scalar_column(Columns& c, const char* name, Index rows)
{
    Property& p = c.converted.emplace_back();
    p.name = name;
    p.type = ValueType::Float64;
    p.values.resize(static_cast<size_t>(rows));
    return p;
}

void convert_normals(const Mesh& mesh, const CornerValues& normals, Columns& c,
                     std::vector<std::string>& notes)
{
    std::int64_t hard = 0;
    const std::vector<double> per_vertex = per_vertex_normals(mesh, normals, hard);
    if (hard > 0)
        notes.push_back(hard_edges_note("PLY", hard));
    const char* names[] = {"nx", "ny", "nz"};
    for (size_t a = 0; a < 3; ++a)
    {
        Property& p = scalar_column(c, names[a], mesh.vertex_count());
        for (size_t v = 0; v < p.values.size(); ++v)
            p.values[v] = per_vertex[3 * v + a];
        c.vertex.push_back(&p);
    }
}

void convert_texcoords(const Mesh& mesh, const CornerValues& t, Columns& c,
                       std::vector<std::string>& notes)
{
    const auto d = static_cast<size_t>(t.dimension);
    bool has_w = false;
    for (size_t k = 2; k < t.values.size() && d == 3; k += 3)
        has_w = has_w || t.values[k] != 0;
    if (has_w)
        notes.push_back(
            "PLY's texture coordinates are pairs: the third value (w) of the "
            "OBJ's texture coordinates is not written");
    std::vector<double> per_vertex;
    if (values_per_vertex(mesh, t, per_vertex))
    {
        const char* names[] = {"texture_u", "texture_v"};
        for (size_t a = 0; a < 2; ++a)
        {
            Property& p = scalar_column(c, names[a], mesh.vertex_count());
            for (size_t v = 0; v < p.values.size(); ++v)
                p.values[v] = a < d ? per_vertex[d * v + a] : 0.0; // u alone: v is 0
            c.vertex.push_back(&p);
        }
        return;
    }
    // Two values per corner in each face's list; a face without texture coordinates
    // gets an empty list.
    Property& p = c.converted.emplace_back();
    p.name = std::string(kCornerTexcoords);
    p.type = ValueType::Float64;
    p.is_list = true;
    p.offsets.push_back(0);
    Index longest = 0;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        bool complete = true;
        for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
            complete = complete && t.corners[static_cast<size_t>(k)] != kInvalidIndex;
        if (complete)
            for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
                for (size_t a = 0; a < 2; ++a)
                    p.values.push_back(
                        d > a
                            ? t.values[d * static_cast<size_t>(t.corners[static_cast<size_t>(k)]) +
                                       a]
                            : 0.0);
        p.offsets.push_back(static_cast<Index>(p.values.size()));
        longest = std::max(longest, p.offsets.back() - p.offsets[p.offsets.size() - 2]);
    }
    p.count_type = longest > 255 ? ValueType::UInt32 : ValueType::UInt8;
    c.face.push_back(&p);
}

} // namespace

void write_ply(const Mesh& mesh, const MeshAttributes& attributes, Encoding encoding,
               std::string& out, std::vector<std::string>& notes)
{
    bool has_long_faces = false;
    for (Index f = 0; f < mesh.face_count(); ++f)
        has_long_faces = has_long_faces || mesh.face_size(f) > 255;

    Columns columns;
    for (const Property& p : attributes.vertex.properties)
        columns.vertex.push_back(&p);
    for (const Property& p : attributes.face.properties)
        columns.face.push_back(&p);
    if (!attributes.normals.empty())
        convert_normals(mesh, attributes.normals, columns, notes);
    if (!attributes.texcoords.empty())
        convert_texcoords(mesh, attributes.texcoords, columns, notes);
    Unwritten unwritten("PLY");
    for (const ObjStatement& s : attributes.statements)
        unwritten.add("OBJ groups, objects, smoothing groups and materials", "'" + s.text + "'");
    unwritten.flush(notes);

    out += "ply\nformat ";
    out += encoding_name(encoding);
    out += " 1.0\n";
    bool signed_before = false;
    for (const std::string& comment : attributes.comments)
        signed_before = signed_before || comment == "comment MeshFair";
    if (!signed_before)
        out += "comment MeshFair\n";
    for (const std::string& comment : attributes.comments)
    {
        out += comment;
        out += '\n';
    }
    append_element(out, "vertex", mesh.vertex_count());
    out += "property double x\nproperty double y\nproperty double z\n";
    for (const Property* p : columns.vertex)
        append_declaration(out, *p);
    append_element(out, "face", mesh.face_count());
    out += has_long_faces ? "property list uint int vertex_indices\n"
                          : "property list uchar int vertex_indices\n";
    for (const Property* p : columns.face)
        append_declaration(out, *p);
    for (const Element& e : attributes.other_elements)
    {
        append_element(out, e.name, e.count);
        for (const Property& p : e.properties)
            append_declaration(out, p);
    }
    out += "end_header\n";

    if (encoding != Encoding::Ascii)
        out.reserve(out.size() + mesh.positions.size() * sizeof(double) +
                    static_cast<size_t>(mesh.face_count()) * (has_long_faces ? 4 : 1) +
                    mesh.face_vertices.size() * sizeof(std::int32_t));
    ValueWriter w(out, encoding);
    const bool is_big_endian = encoding == Encoding::BinaryBigEndian;
    // Binary positions or faces without attributes: one block each, stored in place (as
    // fast as the bytes can be written; a string append per value costs half as much again).
    if (encoding != Encoding::Ascii && columns.vertex.empty())
    {
        char* at = grown(out, mesh.positions.size() * sizeof(double));
        for (const double x : mesh.positions)
            at = store(at, x, is_big_endian);
    }
    else
        for (Index i = 0; i < mesh.vertex_count(); ++i)
        {
            for (int c = 0; c < 3; ++c)
                w.put(mesh.positions[3 * static_cast<size_t>(i) + static_cast<size_t>(c)],
                      ValueType::Float64);
            for (const Property* p : columns.vertex)
                w.put(*p, i);
            w.end_row();
        }
    if (encoding != Encoding::Ascii && columns.face.empty())
    {
        char* at = grown(out, static_cast<size_t>(mesh.face_count()) * (has_long_faces ? 4 : 1) +
                                  mesh.face_vertices.size() * sizeof(std::int32_t));
        for (Index f = 0; f < mesh.face_count(); ++f)
        {
            at = has_long_faces
                     ? store(at, static_cast<std::uint32_t>(mesh.face_size(f)), is_big_endian)
                     : store(at, static_cast<std::uint8_t>(mesh.face_size(f)), is_big_endian);
            for (const Index v : mesh.face(f))
                at = store(at, static_cast<std::int32_t>(v), is_big_endian);
        }
    }
    else
        for (Index f = 0; f < mesh.face_count(); ++f)
        {
            w.put(mesh.face_size(f), has_long_faces ? ValueType::UInt32 : ValueType::UInt8);
            for (const Index v : mesh.face(f))
                w.put(v, ValueType::Int32);
            for (const Property* p : columns.face)
                w.put(*p, f);
            w.end_row();
        }
    for (const Element& e : attributes.other_elements)
        for (Index r = 0; r < e.count && !e.properties.empty(); ++r) // empty rows hold nothing
        {
            for (const Property& p : e.properties)
                w.put(p, r);
            w.end_row();
        }
}

} // namespace meshfair::io
