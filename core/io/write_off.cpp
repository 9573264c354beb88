// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_off.h"

#include "core/io/text_writer.h"

#include <algorithm>

namespace meshfair::io {

namespace {

// Values a vertex (or face) line carries after its positions (or indices): a column of
// the attribute tables, or of per-vertex values converted from per-corner ones.
struct Column
{
    const std::vector<double>* values;
    size_t stride = 1, offset = 0;
    ValueType type = ValueType::Float64;
    bool is_colour = false;
    double at(Index row) const { return (*values)[stride * static_cast<size_t>(row) + offset]; }
};

void add_channels(std::vector<Column>& columns, const Property* const* ps, int n, bool is_colour,
                  std::vector<const Property*>& written)
{
    for (int k = 0; k < n; ++k)
        if (ps[k])
        {
            columns.push_back({&ps[k]->values, 1, 0, ps[k]->type, is_colour});
            written.push_back(ps[k]);
        }
}

// Per-corner texture coordinates as per-vertex columns (u and v), or a note naming them.
bool add_per_vertex(std::vector<Column>& columns, const Mesh& mesh, const CornerValues& c,
                    std::vector<double>& storage, std::vector<std::string>& notes)
{
    if (c.empty())
        return false;
    if (!values_per_vertex(mesh, c, storage))
    {
        notes.push_back(
            "OFF holds one texture coordinate pair per vertex: the texture "
            "coordinates, which differ between the faces of some vertices (seams) "
            "or are missing on some faces, are not written");
        return false;
    }
    if (c.dimension == 1) // u alone: v is 0
    {
        std::vector<double> pairs(2 * storage.size(), 0.0);
        for (size_t v = 0; v < storage.size(); ++v)
            pairs[2 * v] = storage[v];
        storage = std::move(pairs);
    }
    const size_t stride =
        storage.size() / std::max<size_t>(1, static_cast<size_t>(mesh.vertex_count()));
    for (size_t a = 0; a < 2; ++a)
        columns.push_back({&storage, stride, a, ValueType::Float64, false});
    return true;
}

void append_row(std::string& out, const std::vector<Column>& columns, Index row)
{
    for (const Column& c : columns)
    {
        out += ' ';
        append_value(out, c.at(row), c.type, c.is_colour);
    }
}

} // namespace

void write_off(const Mesh& mesh, const MeshAttributes& attributes, std::string& out,
               std::vector<std::string>& notes)
{
    Unwritten unwritten("OFF");
    const Channels vertex = find_channels(attributes.vertex);
    const Channels face = find_channels(attributes.face);
    std::vector<const Property*> written_vertex, written_face;
    std::vector<Column> normal_columns, colour_columns, texture_columns, face_columns;
    std::vector<double> normal_storage, texture_storage;

    const bool has_normals = vertex.has_normal() || !attributes.normals.empty();
    if (vertex.has_normal())
        add_channels(normal_columns, vertex.normal, 3, false, written_vertex);
    else if (has_normals)
    {
        std::int64_t hard = 0;
        normal_storage = per_vertex_normals(mesh, attributes.normals, hard);
        if (hard > 0)
            notes.push_back(hard_edges_note("OFF", hard));
        for (size_t a = 0; a < 3; ++a)
            normal_columns.push_back({&normal_storage, 3, a, ValueType::Float64, false});
    }
    if (vertex.has_colour())
    {
        add_channels(colour_columns, vertex.rgb, 3, true, written_vertex);
        add_channels(colour_columns, &vertex.alpha, 1, true, written_vertex);
    }
    bool has_texture = vertex.has_uv();
    if (has_texture)
        add_channels(texture_columns, vertex.uv, 2, false, written_vertex);
    else
    {
        const Property* source = nullptr;
        const CornerValues t = corner_texcoords(mesh, attributes, &source);
        has_texture = add_per_vertex(texture_columns, mesh, t, texture_storage, notes);
        if (source && source->is_list) // written, or named in the note
            written_face.push_back(source);
    }
    if (face.has_colour())
    {
        add_channels(face_columns, face.rgb, 3, true, written_face);
        add_channels(face_columns, &face.alpha, 1, true, written_face);
    }
    else if (const Property* index = attributes.face.find("colormap_index"))
        add_channels(face_columns, &index, 1, false, written_face);
    // OFF's numbers are finite: a kind with a value that is not is left out, with a note.
    const auto keep_finite = [&](std::vector<Column>& columns, const char* what) {
        for (const Column& c : columns)
            if (!all_finite(*c.values))
            {
                notes.push_back(nonfinite_note("OFF", what));
                columns.clear();
                return;
            }
    };
    keep_finite(normal_columns, "vertex normals");
    keep_finite(colour_columns, "vertex colours");
    keep_finite(texture_columns, "texture coordinates");
    keep_finite(face_columns, "face colours");
    unwritten.add_table(attributes.vertex, written_vertex);
    unwritten.add_table(attributes.face, written_face);
    unwritten.add_elements(attributes.other_elements);
    for (const ObjStatement& s : attributes.statements)
        unwritten.add("OBJ groups, objects, smoothing groups and materials", "'" + s.text + "'");
    unwritten.flush(notes);

    if (!texture_columns.empty())
        out += "ST";
    if (!colour_columns.empty())
        out += "C";
    if (!normal_columns.empty())
        out += "N";
    out += "OFF\n";
    for (const std::string& comment : attributes.comments)
    {
        out += "# ";
        out += comment;
        out += '\n';
    }
    append_integer(out, mesh.vertex_count());
    out += ' ';
    append_integer(out, mesh.face_count());
    // The edge count is optional information that readers ignore; 0 is customary.
    out += " 0\n";
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        for (int c = 0; c < 3; ++c)
        {
            if (c > 0)
                out += ' ';
            append_double(out, mesh.positions[3 * static_cast<size_t>(i) + static_cast<size_t>(c)]);
        }
        append_row(out, normal_columns, i);
        append_row(out, colour_columns, i);
        append_row(out, texture_columns, i);
        out += '\n';
    }
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        append_integer(out, mesh.face_size(f));
        for (const Index v : mesh.face(f))
        {
            out += ' ';
            append_integer(out, v);
        }
        append_row(out, face_columns, f);
        out += '\n';
    }
}

} // namespace meshfair::io
