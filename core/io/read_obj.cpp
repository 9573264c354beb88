// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_obj.h"

#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/face_builder.h"
#include "core/io/text_reader.h"

namespace meshfair::io {

namespace {

// What the scan counts besides the mesh, for the read report.
struct ObjTally
{
    std::int64_t ignored_lines = 0;   // l, p, curves, surfaces
    std::int64_t attribute_lines = 0; // vt, vn, vp
    std::int64_t grouping_lines = 0;  // g, o, s
    std::int64_t material_lines = 0;  // mtllib, usemtl
    std::int64_t vertex_extras = 0;   // v lines with w or a colour after x y z
    std::string first_vertex_extra;
    std::int64_t unknown_lines = 0;
    std::string first_unknown;
    NoteCounter collapsed;
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

void read_vertex(const LineReader& reader, Tokenizer& tokens, Mesh& mesh, ObjTally& tally)
{
    if (mesh.positions.size() / 3 >= static_cast<size_t>(kMaxVertices))
        reader.fail("more vertices than MeshFair supports");
    for (const char* axis : {"x", "y", "z"})
    {
        const std::string_view t = tokens.next();
        if (t.empty())
            reader.fail(std::string("vertex has no ") + axis + " coordinate");
        mesh.positions.push_back(parse_double(reader, t, std::string(axis) + " coordinate"));
    }
    // An optional w or r g b may follow; they must still be numbers.
    std::string_view t = tokens.next();
    if (!t.empty() && tally.vertex_extras++ == 0)
        tally.first_vertex_extra = reader.here(reader.column_of(t)).to_string();
    for (; !t.empty(); t = tokens.next())
        parse_double(reader, t, "vertex value");
}

void add_notes(const ObjTally& t, ReadReport& report)
{
    report_collapsed(t.collapsed, report.notes);
    if (t.ignored_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.ignored_lines) +
                               " line, point, curve or surface statements");
    if (t.vertex_extras > 0)
        report.notes.push_back("ignored the values after x y z (w or a colour) on " +
                               count_of(t.vertex_extras, "vertex line", "vertex lines") +
                               " (first at " + t.first_vertex_extra + ")");
    if (t.attribute_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.attribute_lines) +
                               " texture-coordinate, normal and parameter lines (vt, vn, vp) and "
                               "the faces' texture and normal indices");
    if (t.grouping_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.grouping_lines) +
                               " group, object and smoothing-group lines (g, o, s); faces keep "
                               "the file's order");
    if (t.material_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.material_lines) +
                               " material lines (mtllib, usemtl); no material file is opened");
    if (t.unknown_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.unknown_lines) +
                               " lines with unknown keywords (first: " + t.first_unknown + ")");
}

} // namespace

Mesh read_obj(std::string_view data, const std::string& name, ReadReport& report)
{
    report.format = Format::Obj;
    report.encoding = Encoding::Ascii;
    // One pass straight into the mesh: faces are normalized as they are read, so no
    // per-face bookkeeping outlives its line.
    Mesh mesh;
    ObjTally tally;
    LineReader reader(data, name);
    std::vector<Index> face;
    std::int64_t forward_line = 0, forward_column = 0, forward_max = -1;
    while (reader.next())
    {
        Tokenizer tokens(reader.line());
        const std::string_view keyword = tokens.next();
        if (keyword.empty() || keyword.front() == '#')
            continue;
        if (keyword == "v")
        {
            read_vertex(reader, tokens, mesh, tally);
        }
        else if (keyword == "f")
        {
            const std::int64_t nv = mesh.vertex_count();
            face.clear();
            for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next())
            {
                const std::int64_t index = corner_index(reader, t, nv);
                if (index >= nv && index > forward_max)
                {
                    forward_max = index;
                    forward_line = reader.line_number();
                    forward_column = reader.column_of(t);
                }
                face.push_back(static_cast<Index>(index));
            }
            if (face.size() < 3)
                reader.fail("face has " +
                            count_of(static_cast<std::int64_t>(face.size()), "vertex", "vertices") +
                            " (a face needs at least 3)");
            const FaceCheck check = normalize_face(face);
            if (!check.ok)
                reader.fail(check.problem, reader.column_of(keyword));
            if (check.collapsed > 0)
                tally.collapsed.add(check.collapsed,
                                    reader.here(reader.column_of(keyword)).to_string());
            if (mesh.face_vertices.size() + face.size() > static_cast<size_t>(kMaxElements))
                reader.fail("more face corners than MeshFair supports");
            mesh.add_face(face);
        }
        else if (keyword == "l" || keyword == "p" || keyword == "curv" || keyword == "curv2" ||
                 keyword == "surf")
        {
            ++tally.ignored_lines;
        }
        else if (keyword == "vt" || keyword == "vn" || keyword == "vp")
        {
            ++tally.attribute_lines;
        }
        else if (keyword == "g" || keyword == "o" || keyword == "s")
        {
            ++tally.grouping_lines;
        }
        else if (keyword == "mtllib" || keyword == "usemtl")
        {
            ++tally.material_lines;
        }
        else if (tally.unknown_lines++ == 0)
        {
            tally.first_unknown = "'" + std::string(keyword.substr(0, 20)) + "' at line " +
                                  std::to_string(reader.line_number());
        }
    }
    if (forward_max >= mesh.vertex_count())
        throw FormatError(SourceLocation::text(name, forward_line, forward_column),
                          "vertex index " + std::to_string(forward_max + 1) +
                              " is past the last vertex (the file defines " +
                              std::to_string(mesh.vertex_count()) + ")");
    add_notes(tally, report);
    return mesh;
}

} // namespace meshfair::io
