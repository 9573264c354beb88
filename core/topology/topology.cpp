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

} // namespace

Topology build_topology(const Mesh& mesh)
{
    Topology t;
    t.vertex_count = mesh.vertex_count();
    t.face_count = mesh.face_count();
    const Index corners = mesh.corner_count();

    // Primal edges: one get/insert per face corner, as the paper builds the edge array.
    EdgeGraph graph(static_cast<size_t>(corners));
    t.corner_edge.resize(corners);
    t.corner_face.resize(corners);
    std::vector<Index> face_count_of_edge;
    face_count_of_edge.reserve(corners);
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
            t.corner_face[begin + k] = f;
        }
    }
    t.edge_vertices = graph.release_pairs();
    const Index edges = t.edge_count();

    // F(e): faces per edge in face order.
    t.edge_face_offsets = offsets_from_counts(face_count_of_edge);
    t.edge_faces.resize(t.edge_face_offsets.back());
    {
        std::vector<Index> fill(t.edge_face_offsets.begin(), t.edge_face_offsets.end() - 1);
        for (Index c = 0; c < corners; ++c)
            t.edge_faces[fill[t.corner_edge[c]]++] = t.corner_face[c];
    }
    for (Index e = 0; e < edges; ++e)
        switch (t.edge_kind(e))
        {
            case EdgeKind::Boundary:
                ++t.boundary_edge_count;
                break;
            case EdgeKind::Regular:
                ++t.regular_edge_count;
                break;
            case EdgeKind::Singular:
                ++t.singular_edge_count;
                break;
        }

    // V(i): neighbours in edge order.
    {
        std::vector<Index> valence(t.vertex_count, 0);
        for (Index e = 0; e < edges; ++e)
        {
            ++valence[t.edge_vertices[2 * e]];
            ++valence[t.edge_vertices[2 * e + 1]];
        }
        t.vertex_offsets = offsets_from_counts(valence);
        t.vertex_neighbors.resize(t.vertex_offsets.back());
        std::vector<Index> fill(t.vertex_offsets.begin(), t.vertex_offsets.end() - 1);
        for (Index e = 0; e < edges; ++e)
        {
            const Index i = t.edge_vertices[2 * e], j = t.edge_vertices[2 * e + 1];
            t.vertex_neighbors[fill[i]++] = j;
            t.vertex_neighbors[fill[j]++] = i;
        }
    }

    // Corners of each vertex, in face order.
    {
        std::vector<Index> count(t.vertex_count, 0);
        for (Index c = 0; c < corners; ++c)
            ++count[mesh.face_vertices[c]];
        t.vertex_corner_offsets = offsets_from_counts(count);
        t.vertex_corners.resize(corners);
        std::vector<Index> fill(t.vertex_corner_offsets.begin(), t.vertex_corner_offsets.end() - 1);
        for (Index c = 0; c < corners; ++c)
            t.vertex_corners[fill[mesh.face_vertices[c]]++] = c;
    }

    // Dual graph E*: the same get/insert structure over pairs of faces.
    {
        EdgeGraph dual(static_cast<size_t>(t.regular_edge_count));
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
        std::vector<Index> fill(t.face_neighbor_offsets.begin(), t.face_neighbor_offsets.end() - 1);
        for (Index d = 0; d < t.dual_edge_count(); ++d)
        {
            const Index f = t.dual_edge_faces[2 * d], g = t.dual_edge_faces[2 * d + 1];
            t.face_neighbors[fill[f]++] = g;
            t.face_neighbors[fill[g]++] = f;
        }
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
    for (Index e = 0; e < topology.edge_count(); ++e)
    {
        const Index a = find(topology.edge_vertices[2 * e]);
        const Index b = find(topology.edge_vertices[2 * e + 1]);
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
