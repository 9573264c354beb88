// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/select/mesh_select.h"

#include <algorithm>

#include "core/parallel/parallel.h"

namespace meshfair {

void apply_selection(SelectionMask& mask, std::span<const Index> elements, SelectOp op)
{
    if (op == SelectOp::Replace)
        std::fill(mask.begin(), mask.end(), 0);
    const char value = op == SelectOp::Subtract ? 0 : 1;
    for (const Index e : elements)
        mask[static_cast<size_t>(e)] = value;
}

std::vector<Index> selected_indices(const SelectionMask& mask)
{
    std::vector<Index> out;
    for (size_t k = 0; k < mask.size(); ++k)
        if (mask[k])
            out.push_back(static_cast<Index>(k));
    return out;
}

void invert_selection(SelectionMask& mask)
{
    for (char& m : mask)
        m = m ? 0 : 1;
}

// Vertex i's rule over itself and its neighbours; each vertex gathers its own flag, so the
// result does not depend on the thread count.
template <class Rule>
SelectionMask per_vertex(const Topology& t, const SelectionMask& in, Rule rule)
{
    SelectionMask out(in.size(), 0);
    parallel_for(t.vertex_count, [&](Index i) {
        const std::span<const Index> ring(
            t.vertex_neighbors.data() + t.vertex_offsets[i],
            static_cast<size_t>(t.vertex_offsets[i + 1] - t.vertex_offsets[i]));
        out[static_cast<size_t>(i)] = rule(in[static_cast<size_t>(i)], ring) ? 1 : 0;
    });
    return out;
}

SelectionMask grow_vertices(const Topology& t, const SelectionMask& v)
{
    return per_vertex(t, v, [&](char self, std::span<const Index> ring) {
        return self || std::any_of(ring.begin(), ring.end(), [&](Index j) { return v[j] != 0; });
    });
}

SelectionMask shrink_vertices(const Topology& t, const SelectionMask& v)
{
    return per_vertex(t, v, [&](char self, std::span<const Index> ring) {
        return self && std::all_of(ring.begin(), ring.end(), [&](Index j) { return v[j] != 0; });
    });
}

namespace {

// For every vertex: does one of its faces have the flag (any) / do all of them (all)?
SelectionMask vertex_touches(const Topology& t, const SelectionMask& faces, bool all)
{
    SelectionMask out(static_cast<size_t>(t.vertex_count), 0);
    parallel_for(t.vertex_count, [&](Index i) {
        bool any_face = false, every_face = true;
        for (Index k = t.vertex_corner_offsets[i]; k < t.vertex_corner_offsets[i + 1]; ++k)
        {
            const bool s = faces[static_cast<size_t>(t.face_of_corner(t.vertex_corners[k]))] != 0;
            any_face = any_face || s;
            every_face = every_face && s;
        }
        out[static_cast<size_t>(i)] = (all ? every_face : any_face) ? 1 : 0;
    });
    return out;
}

template <class Rule>
SelectionMask per_face(const Mesh& mesh, Rule rule)
{
    SelectionMask out(static_cast<size_t>(mesh.face_count()), 0);
    parallel_for(mesh.face_count(),
                 [&](Index f) { out[static_cast<size_t>(f)] = rule(f) ? 1 : 0; });
    return out;
}

} // namespace

SelectionMask grow_faces(const Mesh& mesh, const Topology& t, const SelectionMask& faces)
{
    const SelectionMask touched = vertex_touches(t, faces, false);
    return per_face(mesh, [&](Index f) {
        const std::span<const Index> face = mesh.face(f);
        return std::any_of(face.begin(), face.end(), [&](Index i) { return touched[i] != 0; });
    });
}

SelectionMask shrink_faces(const Mesh& mesh, const Topology& t, const SelectionMask& faces)
{
    const SelectionMask inner = vertex_touches(t, faces, true);
    return per_face(mesh, [&](Index f) {
        const std::span<const Index> face = mesh.face(f);
        return faces[static_cast<size_t>(f)] &&
               std::all_of(face.begin(), face.end(), [&](Index i) { return inner[i] != 0; });
    });
}

namespace {

// Every element reachable from the seeds; neighbours(e, visit) calls visit on each
// neighbour of e.
template <class Neighbours>
SelectionMask flood(size_t n, std::span<const Index> seeds, Neighbours neighbours)
{
    SelectionMask seen(n, 0);
    std::vector<Index> queue;
    const auto visit = [&](Index e) {
        if (!seen[static_cast<size_t>(e)])
        {
            seen[static_cast<size_t>(e)] = 1;
            queue.push_back(e);
        }
    };
    for (const Index s : seeds)
        visit(s);
    for (size_t head = 0; head < queue.size(); ++head)
        neighbours(queue[head], visit);
    return seen;
}

} // namespace

SelectionMask connected_vertices(const Topology& t, std::span<const Index> seeds)
{
    return flood(static_cast<size_t>(t.vertex_count), seeds, [&](Index i, const auto& visit) {
        for (Index k = t.vertex_offsets[i]; k < t.vertex_offsets[i + 1]; ++k)
            visit(t.vertex_neighbors[k]);
    });
}

SelectionMask connected_faces(const Mesh& mesh, const Topology& t, std::span<const Index> seeds)
{
    return flood(static_cast<size_t>(mesh.face_count()), seeds, [&](Index f, const auto& visit) {
        for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c)
        {
            const Index e = t.corner_edge[c];
            for (Index k = t.edge_face_offsets[e]; k < t.edge_face_offsets[e + 1]; ++k)
                visit(t.edge_faces[k]);
        }
    });
}

SelectionMask boundary_vertices(const Topology& t)
{
    SelectionMask out(static_cast<size_t>(t.vertex_count), 0);
    for (Index e = 0; e < t.edge_count(); ++e)
        if (t.edge_face_offsets[e + 1] - t.edge_face_offsets[e] == 1)
        {
            out[static_cast<size_t>(t.edge_vertices[2 * e])] = 1;
            out[static_cast<size_t>(t.edge_vertices[2 * e + 1])] = 1;
        }
    return out;
}

SelectionMask boundary_faces(const Mesh& mesh, const Topology& t)
{
    return per_face(mesh, [&](Index f) {
        for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c)
        {
            const Index e = t.corner_edge[c];
            if (t.edge_face_offsets[e + 1] - t.edge_face_offsets[e] == 1)
                return true;
        }
        return false;
    });
}

SelectionMask vertices_of_faces(const Mesh& mesh, const SelectionMask& faces)
{
    SelectionMask out(static_cast<size_t>(mesh.vertex_count()), 0);
    for (Index f = 0; f < mesh.face_count(); ++f)
        if (faces[static_cast<size_t>(f)])
            for (const Index i : mesh.face(f))
                out[static_cast<size_t>(i)] = 1;
    return out;
}

SelectionMask faces_of_vertices(const Mesh& mesh, const SelectionMask& vertices)
{
    return per_face(mesh, [&](Index f) {
        const std::span<const Index> face = mesh.face(f);
        return std::all_of(face.begin(), face.end(), [&](Index i) { return vertices[i] != 0; });
    });
}

} // namespace meshfair
