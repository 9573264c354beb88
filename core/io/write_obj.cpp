// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_obj.h"

#include "core/io/text_writer.h"

namespace meshfair::io {

namespace {

// Largest value of an integer colour type (uchar 255, ushort 65535, ...), 1 for fractions.
double colour_scale(ValueType type)
{
    switch (type)
    {
        case ValueType::Int8:
            return 127;
        case ValueType::UInt8:
            return 255;
        case ValueType::Int16:
            return 32767;
        case ValueType::UInt16:
            return 65535;
        case ValueType::Int32:
            return 2147483647;
        case ValueType::UInt32:
            return 4294967295.0;
        default:
            return 1;
    }
}

void append_entries(std::string& out, const char* keyword, const CornerValues& c)
{
    const auto d = static_cast<size_t>(c.dimension);
    for (size_t e = 0; e < c.values.size(); e += d)
    {
        out += keyword;
        for (size_t k = 0; k < d; ++k)
        {
            out += ' ';
            append_double(out, c.values[e + k]);
        }
        out += '\n';
    }
}

bool face_has(const CornerValues& c, Index begin, Index end)
{
    if (c.empty())
        return false;
    for (Index k = begin; k < end; ++k)
        if (c.corners[static_cast<size_t>(k)] == kInvalidIndex)
            return false;
    return true;
}

void append_statement(std::string& out, const ObjStatement& s)
{
    out += s.text;
    out += '\n';
}

} // namespace

void write_obj(const Mesh& mesh, const MeshAttributes& attributes, std::string& out,
               std::vector<std::string>& notes)
{
    Unwritten unwritten("OBJ");
    const Channels vertex = find_channels(attributes.vertex);
    const Property* texcoord_source = nullptr;
    CornerValues texcoords = corner_texcoords(mesh, attributes, &texcoord_source);
    CornerValues normals = corner_normals(mesh, attributes);
    // OBJ's numbers are finite: values that are not leave their kind out, with a note.
    const bool colours = vertex.has_colour() && all_finite(vertex.rgb[0]->values) &&
                         all_finite(vertex.rgb[1]->values) && all_finite(vertex.rgb[2]->values);
    if (vertex.has_colour() && !colours)
        notes.push_back(nonfinite_note("OBJ", "vertex colours"));
    if (!all_finite(texcoords.values))
    {
        notes.push_back(nonfinite_note("OBJ", "texture coordinates"));
        texcoords = {};
    }
    if (!all_finite(normals.values))
    {
        notes.push_back(nonfinite_note("OBJ", "normals"));
        normals = {};
    }

    std::vector<const Property*> written_vertex, written_face;
    if (vertex.has_colour())
        written_vertex.insert(written_vertex.end(), std::begin(vertex.rgb), std::end(vertex.rgb));
    if (attributes.normals.empty() && vertex.has_normal()) // written, or in a note
        written_vertex.insert(written_vertex.end(), std::begin(vertex.normal),
                              std::end(vertex.normal));
    if (texcoord_source)
    {
        if (texcoord_source->is_list)
            written_face.push_back(texcoord_source);
        else
            written_vertex.insert(written_vertex.end(), std::begin(vertex.uv), std::end(vertex.uv));
    }
    unwritten.add_table(attributes.vertex, written_vertex);
    unwritten.add_table(attributes.face, written_face);
    unwritten.add_elements(attributes.other_elements);
    unwritten.flush(notes);

    out += "# MeshFair: ";
    append_integer(out, mesh.vertex_count());
    out += " vertices, ";
    append_integer(out, mesh.face_count());
    out += " faces\n";
    for (const std::string& comment : attributes.comments)
    {
        out += "# ";
        out += comment;
        out += '\n';
    }
    // The statements before the first face at the top, where files name their material
    // libraries and first groups; the others before the faces they applied to.
    const auto& statements = attributes.statements;
    size_t next_statement = 0;
    for (; next_statement < statements.size() && statements[next_statement].before_face == 0;
         ++next_statement)
        append_statement(out, statements[next_statement]);
    double scale[3] = {1, 1, 1};
    if (colours)
        for (int c = 0; c < 3; ++c)
            scale[c] = colour_scale(vertex.rgb[c]->type);
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        out += "v";
        for (int c = 0; c < 3; ++c)
        {
            out += ' ';
            append_double(out, mesh.positions[3 * i + c]);
        }
        if (colours)
            for (int c = 0; c < 3; ++c)
            {
                out += ' ';
                append_double(out, vertex.rgb[c]->values[static_cast<size_t>(i)] / scale[c]);
            }
        out += '\n';
    }
    append_entries(out, "vt", texcoords);
    append_entries(out, "vn", normals);
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        for (; next_statement < statements.size() && statements[next_statement].before_face <= f;
             ++next_statement)
            append_statement(out, statements[next_statement]);
        const Index begin = mesh.face_offsets[f], end = mesh.face_offsets[f + 1];
        const bool has_t = face_has(texcoords, begin, end);
        const bool has_n = face_has(normals, begin, end);
        out += "f";
        for (Index k = begin; k < end; ++k)
        {
            out += ' ';
            append_integer(
                out, static_cast<std::int64_t>(mesh.face_vertices[static_cast<size_t>(k)]) + 1);
            if (has_t || has_n)
                out += '/';
            if (has_t)
                append_integer(
                    out, static_cast<std::int64_t>(texcoords.corners[static_cast<size_t>(k)]) + 1);
            if (has_n)
            {
                out += '/';
                append_integer(
                    out, static_cast<std::int64_t>(normals.corners[static_cast<size_t>(k)]) + 1);
            }
        }
        out += '\n';
    }
    for (; next_statement < statements.size(); ++next_statement)
        append_statement(out, statements[next_statement]);
}

} // namespace meshfair::io
