// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_obj.h"

#include <tiny_obj_loader.h>

#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/face_builder.h"
#include "core/io/text_reader.h"

namespace meshfair::io {

namespace {

// What the line scan finds: exact coordinates and, per face, its resolved indices
// and line, before normalization.
struct ObjScan
{
    std::vector<double> positions;
    std::vector<Index> offsets{0};
    std::vector<Index> indices;
    std::vector<std::int64_t> face_lines;
    std::int64_t ignored_lines = 0; // l, p, curves, surfaces
    std::int64_t unknown_lines = 0;
    std::string first_unknown;
};

// Resolves one face corner token ("7", "7/1", "7//3", "-2/1/1") against the number of
// vertices defined so far. Forward references (positive indices past the vertices
// read so far) are legal in OBJ and checked against the final count by the caller.
std::int64_t corner_index(const LineReader& reader, std::string_view token,
                          std::int64_t vertices_so_far)
{
    const std::string_view vertex_part = token.substr(0, token.find('/'));
    if (vertex_part.empty())
        reader.fail_at(token, "face corner '" + std::string(token) + "' has no vertex index");
    const std::int64_t raw = parse_integer(reader, vertex_part, "vertex index");
    if (raw == 0)
        reader.fail_at(token, "vertex index 0 (OBJ indices start at 1, or count back from -1)");
    if (raw < 0)
    {
        const std::int64_t resolved = vertices_so_far + raw;
        if (resolved < 0)
            reader.fail_at(token, "vertex index " + std::to_string(raw) +
                                      " reaches before the first vertex (" +
                                      std::to_string(vertices_so_far) +
                                      " vertices are defined before this line)");
        return resolved;
    }
    if (raw > kMaxElements)
        reader.fail_at(token, "vertex index " + std::to_string(raw) + " is out of range");
    return raw - 1;
}

ObjScan scan(std::string_view data, const std::string& name)
{
    ObjScan s;
    LineReader reader(data, name);
    std::int64_t forward_line = 0, forward_column = 0, forward_max = -1;
    while (reader.next())
    {
        Tokenizer tokens(reader.line());
        const std::string_view keyword = tokens.next();
        if (keyword.empty() || keyword.front() == '#')
            continue;
        if (keyword == "v")
        {
            if (s.positions.size() / 3 >= static_cast<size_t>(kMaxElements))
                reader.fail("more vertices than MeshFair supports");
            for (const char* axis : {"x", "y", "z"})
            {
                const std::string_view t = tokens.next();
                if (t.empty())
                    reader.fail(std::string("vertex has no ") + axis + " coordinate");
                s.positions.push_back(parse_double(reader, t, std::string(axis) + " coordinate"));
            }
            // An optional w or r g b may follow; they must still be numbers.
            for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next())
                parse_double(reader, t, "vertex value");
        }
        else if (keyword == "f")
        {
            const std::int64_t nv = static_cast<std::int64_t>(s.positions.size() / 3);
            size_t corners = 0;
            for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next(), ++corners)
            {
                const std::int64_t index = corner_index(reader, t, nv);
                if (index >= nv && index > forward_max)
                {
                    forward_max = index;
                    forward_line = reader.line_number();
                    forward_column = reader.column_of(t);
                }
                s.indices.push_back(static_cast<Index>(index));
            }
            if (corners < 3)
                reader.fail("face has " + std::to_string(corners) +
                            " vertices (a face needs at least 3)");
            if (s.indices.size() > static_cast<size_t>(kMaxElements))
                reader.fail("more face corners than MeshFair supports");
            s.offsets.push_back(static_cast<Index>(s.indices.size()));
            s.face_lines.push_back(reader.line_number());
        }
        else if (keyword == "l" || keyword == "p" || keyword == "curv" || keyword == "curv2" ||
                 keyword == "surf")
        {
            ++s.ignored_lines;
        }
        else if (keyword != "vt" && keyword != "vn" && keyword != "vp" && keyword != "g" &&
                 keyword != "o" && keyword != "s" && keyword != "usemtl" && keyword != "mtllib")
        {
            if (s.unknown_lines++ == 0)
                s.first_unknown = "'" + std::string(keyword.substr(0, 20)) + "' at line " +
                                  std::to_string(reader.line_number());
        }
    }
    const std::int64_t nv = static_cast<std::int64_t>(s.positions.size() / 3);
    if (forward_max >= nv)
    {
        throw FormatError(SourceLocation::text(name, forward_line, forward_column),
                          "vertex index " + std::to_string(forward_max + 1) +
                              " is past the last vertex (the file defines " + std::to_string(nv) +
                              ")");
    }
    return s;
}

[[noreturn]] void disagree(const std::string& name, const std::string& what)
{
    throw FormatError(SourceLocation::whole(name),
                      "tinyobjloader reads this file differently: " + what);
}

// tinyobjloader gives the face structure (groups and objects concatenated in file
// order); the scan above must agree with it face by face.
void cross_check(std::string_view data, const std::string& name, const ObjScan& s)
{
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // tinyobjloader splits lines at LF only and does not know the byte-order mark:
    // give it the text with both normalized as the line scan read them.
    std::string text(data.starts_with("\xEF\xBB\xBF") ? data.substr(3) : data);
    for (size_t k = 0; k < text.size(); ++k)
        if (text[k] == '\r' && (k + 1 == text.size() || text[k + 1] != '\n'))
            text[k] = '\n';
    // Materials are irrelevant here; an empty material text keeps it off the disk.
    if (!reader.ParseFromString(text, std::string(), config))
        throw FormatError(SourceLocation::whole(name), "tinyobjloader: " + reader.Error());
    const auto& attrib = reader.GetAttrib();
    if (attrib.vertices.size() != s.positions.size())
        disagree(name, std::to_string(attrib.vertices.size() / 3) + " vertices instead of " +
                           std::to_string(s.positions.size() / 3));
    size_t face = 0, corner = 0;
    for (const auto& shape : reader.GetShapes())
    {
        size_t k = 0;
        for (const unsigned char n : shape.mesh.num_face_vertices)
        {
            if (face + 1 >= s.offsets.size() ||
                static_cast<size_t>(s.offsets[face + 1] - s.offsets[face]) != n)
                disagree(name, "face " + std::to_string(face) + " has another size");
            for (unsigned c = 0; c < n; ++c, ++k, ++corner)
                if (shape.mesh.indices[k].vertex_index != s.indices[corner])
                    disagree(name, "face " + std::to_string(face) + " has other vertices");
            ++face;
        }
    }
    if (face + 1 != s.offsets.size())
        disagree(name, std::to_string(face) + " faces instead of " +
                           std::to_string(s.offsets.size() - 1));
}

} // namespace

Mesh read_obj(std::string_view data, const std::string& name, ReadReport& report)
{
    report.format = Format::Obj;
    report.encoding = Encoding::Ascii;
    ObjScan s = scan(data, name);
    // tinyobjloader stores face sizes in an unsigned char; longer polygons are read by
    // the scan alone.
    bool has_long_faces = false;
    for (size_t f = 0; f + 1 < s.offsets.size(); ++f)
        has_long_faces = has_long_faces || s.offsets[f + 1] - s.offsets[f] > 255;
    if (!has_long_faces)
        cross_check(data, name, s);

    Mesh mesh;
    mesh.positions = std::move(s.positions);
    mesh.face_offsets.reserve(s.offsets.size());
    mesh.face_vertices.reserve(s.indices.size());
    NoteCounter collapsed;
    std::vector<Index> face;
    for (size_t f = 0; f + 1 < s.offsets.size(); ++f)
    {
        face.assign(s.indices.begin() + s.offsets[f], s.indices.begin() + s.offsets[f + 1]);
        const FaceCheck check = normalize_face(face);
        const auto where = SourceLocation::text(name, s.face_lines[f]);
        if (!check.ok)
            throw FormatError(where, check.problem);
        collapsed.add(check.collapsed, where.to_string());
        mesh.add_face(face);
    }
    report_collapsed(collapsed, report.notes);
    if (s.ignored_lines > 0)
        report.notes.push_back("ignored " + std::to_string(s.ignored_lines) +
                               " line, point, curve or surface statements");
    if (s.unknown_lines > 0)
        report.notes.push_back("ignored " + std::to_string(s.unknown_lines) +
                               " lines with unknown keywords (first: " + s.first_unknown + ")");
    return mesh;
}

} // namespace meshfair::io
