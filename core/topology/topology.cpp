// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/topology/topology.h"

#include <algorithm>
#include <numeric>

#include "core/topology/edge_graph.h"

namespace meshfair {

EdgeKind Topology::edge_kind(Index e) const
{
    const Index n = edge_face_count(e);
    return n == 1 ? EdgeKind::Boundary : n == 2 ? EdgeKind::Regular : EdgeKind::Singular;
}

namespace {

// Turns per-item counts into CSR offsets (exclusive prefix sum, size + 1).
std::vector<Index> offsets_from_counts(const std::vector<Index>& counts)
{
    std::vector<Index> offsets(counts.size() + 1, 0);
    std::partial_sum(counts.begin(), counts.end(), offsets.begin() + 1);
    return offsets;
}

//! Counts one edge with n_e = `faces` as boundary, regular or singular.
void count_edge(Topology& t, size_t faces)
{
    ++(faces == 1   ? t.boundary_edge_count
       : faces == 2 ? t.regular_edge_count
                    : t.singular_edge_count);
}

//! The other ends of the face edges at vertex i, sorted, an end j repeated once per face
//! of the edge (i, j): the corners of i contribute their next and previous vertices.
void edge_ends(const Mesh& mesh, const Topology& t, Index i, std::vector<Index>& ends)
{
    ends.clear();
    for (const Index c : t.corners_of_vertex(i))
    {
        const CornerNeighbors n = corner_neighbors(mesh, t, c);
        ends.push_back(n.next);
        ends.push_back(n.previous);
    }
    std::sort(ends.begin(), ends.end());
}

//! Corners of each vertex (in face order) and the face of each corner.
void build_corners(const Mesh& mesh, Topology& t)
{
    const Index corners = mesh.corner_count();
    t.corner_face.resize(corners);
    for (Index f = 0; f < t.face_count; ++f)
        std::fill(t.corner_face.begin() + mesh.face_offsets[f],
                  t.corner_face.begin() + mesh.face_offsets[f + 1], f);
    std::vector<Index> count(t.vertex_count, 0);
    for (Index c = 0; c < corners; ++c)
        ++count[mesh.face_vertices[c]];
    t.vertex_corner_offsets = offsets_from_counts(count);
    t.vertex_corners.resize(corners);
    std::vector<Index>& fill = count;
    std::copy(t.vertex_corner_offsets.begin(), t.vertex_corner_offsets.end() - 1, fill.begin());
    for (Index c = 0; c < corners; ++c)
        t.vertex_corners[fill[mesh.face_vertices[c]]++] = c;
}

//! V(i) (increasing) and the edge counts from the corners: an edge (i, j) with n_e
//! faces appears n_e times among the ends at i (faces have distinct vertices).
void build_neighbors_and_counts(const Mesh& mesh, Topology& t)
{
    std::vector<Index> ends;
    std::vector<Index> valence(t.vertex_count, 0);
    for (Index i = 0; i < t.vertex_count; ++i)
    {
        edge_ends(mesh, t, i, ends);
        for (size_t k = 0; k < ends.size();)
        {
            size_t run = k + 1;
            while (run < ends.size() && ends[run] == ends[k])
                ++run;
            ++valence[i];
            if (ends[k] > i) // each edge once, from its lower end
            {
                count_edge(t, run - k);
            }
            k = run;
        }
    }
    t.vertex_offsets = offsets_from_counts(valence);
    valence = {};
    t.vertex_neighbors.resize(t.vertex_offsets.back());
    for (Index i = 0; i < t.vertex_count; ++i)
    {
        edge_ends(mesh, t, i, ends);
        const auto last = std::unique(ends.begin(), ends.end());
        std::copy(ends.begin(), last, t.vertex_neighbors.begin() + t.vertex_offsets[i]);
    }
}

//! The primal edges E, corner_edge and F(e): one get/insert per face corner, as the
//! paper builds the edge array.
void build_edges(const Mesh& mesh, Topology& t)
{
    const Index corners = mesh.corner_count();
    EdgeGraph graph(static_cast<size_t>(corners));
    t.corner_edge.resize(corners);
    std::vector<Index> face_count_of_edge;
    face_count_of_edge.reserve(static_cast<size_t>(corners));
    for (Index f = 0; f < t.face_count; ++f)
    {
        const Index begin = mesh.face_offsets[f], n = mesh.face_size(f);
        for (Index k = 0; k < n; ++k)
        {
            const Index i = mesh.face_vertices[begin + k];
            const Index j = mesh.face_vertices[begin + (k + 1) % n];
            Index e = graph.get(i, j);
            if (e == kInvalidIndex)
            {
                e = graph.insert(i, j);
                face_count_of_edge.push_back(1); // n_e starts at 1 on insert
            }
            else
            {
                ++face_count_of_edge[e]; // and grows each time get() finds the edge
            }
            t.corner_edge[begin + k] = e;
        }
    }
    t.edge_vertices = graph.release_pairs();

    // F(e): faces per edge in face order.
    t.edge_face_offsets = offsets_from_counts(face_count_of_edge);
    t.edge_faces.resize(t.edge_face_offsets.back());
    std::vector<Index> fill(t.edge_face_offsets.begin(), t.edge_face_offsets.end() - 1);
    for (Index c = 0; c < corners; ++c)
        t.edge_faces[fill[t.corner_edge[c]]++] = t.corner_face[c];
}

//! V(i) (increasing) and the edge counts from the edge list and F(e): cheaper than
//! build_neighbors_and_counts once the edges exist, and the same result.
void neighbors_and_counts_from_edges(Topology& t)
{
    const auto edges = static_cast<Index>(t.edge_vertices.size() / 2);
    std::vector<Index> valence(t.vertex_count, 0);
    for (Index e = 0; e < edges; ++e)
    {
        ++valence[t.edge_vertices[2 * e]];
        ++valence[t.edge_vertices[2 * e + 1]];
        count_edge(t, static_cast<size_t>(t.edge_face_count(e)));
    }
    t.vertex_offsets = offsets_from_counts(valence);
    t.vertex_neighbors.resize(t.vertex_offsets.back());
    std::vector<Index>& fill = valence;
    std::copy(t.vertex_offsets.begin(), t.vertex_offsets.end() - 1, fill.begin());
    for (Index e = 0; e < edges; ++e)
    {
        const Index i = t.edge_vertices[2 * e], j = t.edge_vertices[2 * e + 1];
        t.vertex_neighbors[fill[i]++] = j;
        t.vertex_neighbors[fill[j]++] = i;
    }
    for (Index i = 0; i < t.vertex_count; ++i)
        std::sort(t.vertex_neighbors.begin() + t.vertex_offsets[i],
                  t.vertex_neighbors.begin() + t.vertex_offsets[i + 1]);
}

//! The dual graph E*: the same get/insert structure over pairs of faces.
void build_dual(Topology& t)
{
    EdgeGraph dual(static_cast<size_t>(t.regular_edge_count));
    const auto edges = static_cast<Index>(t.edge_vertices.size() / 2);
    for (Index e = 0; e < edges; ++e)
        if (t.edge_kind(e) == EdgeKind::Regular)
        {
            const auto faces = t.faces_of_edge(e);
            dual.insert(faces[0], faces[1]);
        }
    t.dual_edge_faces = dual.release_pairs();
    std::vector<Index> count(t.face_count, 0);
    for (Index d = 0; d < t.dual_edge_count(); ++d)
    {
        ++count[t.dual_edge_faces[2 * d]];
        ++count[t.dual_edge_faces[2 * d + 1]];
    }
    t.face_neighbor_offsets = offsets_from_counts(count);
    t.face_neighbors.resize(t.face_neighbor_offsets.back());
    std::vector<Index>& fill = count;
    std::copy(t.face_neighbor_offsets.begin(), t.face_neighbor_offsets.end() - 1, fill.begin());
    for (Index d = 0; d < t.dual_edge_count(); ++d)
    {
        const Index f = t.dual_edge_faces[2 * d], g = t.dual_edge_faces[2 * d + 1];
        t.face_neighbors[fill[f]++] = g;
        t.face_neighbors[fill[g]++] = f;
    }
}

template <class T>
void release(std::vector<T>& v)
{
    std::vector<T>().swap(v);
}

} // namespace

Topology build_topology(const Mesh& mesh, TopologyParts parts)
{
    Topology t;
    t.vertex_count = mesh.vertex_count();
    t.face_count = mesh.face_count();
    t.parts = parts;
    // The corners are the base of every other part. V(i) and the edge counts come from
    // the edges when they are built anyway, else from the corners (no edge hash).
    build_corners(mesh, t);
    const bool dual = has_parts(parts, TopologyParts::Dual);
    if (dual || has_parts(parts, TopologyParts::Edges))
    {
        build_edges(mesh, t);
        neighbors_and_counts_from_edges(t);
    }
    else
        build_neighbors_and_counts(mesh, t);
    if (dual)
        build_dual(t);
    if (!has_parts(parts, TopologyParts::Edges))
    {
        release(t.edge_vertices);
        release(t.corner_edge);
        release(t.edge_face_offsets);
        release(t.edge_faces);
    }
    if (!has_parts(parts, TopologyParts::Corners))
    {
        release(t.vertex_corner_offsets);
        release(t.vertex_corners);
        release(t.corner_face);
    }
    if (!has_parts(parts, TopologyParts::Neighbors))
    {
        release(t.vertex_offsets);
        release(t.vertex_neighbors);
    }
    return t;
}

TopologySummary summarize(const Topology& topology)
{
    TopologySummary s;
    std::vector<Index> parent(topology.vertex_count);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&parent](Index v) {
        while (parent[v] != v)
        {
            parent[v] = parent[parent[v]]; // path halving
            v = parent[v];
        }
        return v;
    };
    for (Index i = 0; i < topology.vertex_count; ++i)
        for (const Index j : topology.neighbors(i))
        {
            const Index a = find(i), b = find(j);
            if (a != b)
                parent[std::max(a, b)] = std::min(a, b);
        }
    for (Index v = 0; v < topology.vertex_count; ++v)
    {
        if (find(v) == v)
            ++s.components;
        if (topology.valence(v) == 0)
            ++s.isolated_vertices;
    }
    return s;
}

} // namespace meshfair
