// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/topology/topology.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <utility>

#include "core/parallel/parallel.h"

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

//! Boundary, regular and singular edge counts, summed per thread and then added up
//! (integers: the same totals in any order).
struct EdgeCounts
{
    std::int64_t boundary = 0, regular = 0, singular = 0;
    //! Counts one edge with n_e = `faces`.
    void add(size_t faces) { ++(faces == 1 ? boundary : faces == 2 ? regular : singular); }
};

struct SharedEdgeCounts
{
    std::atomic<std::int64_t> boundary{0}, regular{0}, singular{0};
    void add(const EdgeCounts& c)
    {
        boundary += c.boundary;
        regular += c.regular;
        singular += c.singular;
    }
};

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

//! One face's side of an edge (i, j), i < j, seen from i: j, and the corner at which
//! the edge starts in that face (the corner whose next corner closes it).
struct UpperEnd
{
    Index j;
    Index corner;
    bool operator<(const UpperEnd& o) const { return j != o.j ? j < o.j : corner < o.corner; }
};

//! The face edges (i, j) with j > i, one entry per face of each edge, sorted by j and then
//! by corner (that is, by face). Every corner starts exactly one face edge and is listed
//! once, at the edge's lower end.
void upper_ends(const Mesh& mesh, const Topology& t, Index i, std::vector<UpperEnd>& ends)
{
    ends.clear();
    for (const Index c : t.corners_of_vertex(i))
    {
        const AdjacentCorners a = adjacent_corners(mesh, t, c);
        const Index next = mesh.face_vertices[a.next], previous = mesh.face_vertices[a.previous];
        if (next > i)
            ends.push_back({next, c}); // (i, next) starts at c
        if (previous > i)
            ends.push_back({previous, a.previous}); // (previous, i) starts at the previous corner
    }
    std::sort(ends.begin(), ends.end());
}

//! Calls f(begin, end) for each run of entries with equal key(entry) in sorted `items`.
template <class T, class Key, class F>
void for_each_run(const std::vector<T>& items, Key key, F&& f)
{
    for (size_t k = 0; k < items.size();)
    {
        size_t run = k + 1;
        while (run < items.size() && key(items[run]) == key(items[k]))
            ++run;
        f(k, run);
        k = run;
    }
}

constexpr auto end_vertex = [](const auto& end) { return end.j; };
constexpr auto itself = [](Index v) { return v; };

//! Corners of each vertex (in face order) and the face of each corner.
void build_corners(const Mesh& mesh, Topology& t)
{
    const Index corners = mesh.corner_count();
    if (!t.triangles)
    {
        t.corner_face.resize(corners);
        parallel_for(t.face_count, [&](Index f) {
            std::fill(t.corner_face.begin() + mesh.face_offsets[f],
                      t.corner_face.begin() + mesh.face_offsets[f + 1], f);
        });
    }
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
//! faces appears n_e times among the ends at i (faces have distinct vertices). Each
//! vertex on its own, in parallel: one pass counts, the second fills.
void build_neighbors_and_counts(const Mesh& mesh, Topology& t)
{
    std::vector<Index> valence(t.vertex_count, 0);
    SharedEdgeCounts total;
    parallel_ranges(t.vertex_count, [&](Index begin, Index end) {
        std::vector<Index> ends;
        EdgeCounts counts;
        for (Index i = begin; i < end; ++i)
        {
            edge_ends(mesh, t, i, ends);
            for_each_run(ends, itself, [&](size_t first, size_t last) {
                ++valence[i];
                if (ends[first] > i) // each edge once, from its lower end
                    counts.add(last - first);
            });
        }
        total.add(counts);
    });
    t.boundary_edge_count = static_cast<Index>(total.boundary.load());
    t.regular_edge_count = static_cast<Index>(total.regular.load());
    t.singular_edge_count = static_cast<Index>(total.singular.load());
    t.vertex_offsets = offsets_from_counts(valence);
    valence = {};
    t.vertex_neighbors.resize(t.vertex_offsets.back());
    parallel_ranges(t.vertex_count, [&](Index begin, Index end) {
        std::vector<Index> ends;
        for (Index i = begin; i < end; ++i)
        {
            edge_ends(mesh, t, i, ends);
            const auto last = std::unique(ends.begin(), ends.end());
            std::copy(ends.begin(), last, t.vertex_neighbors.begin() + t.vertex_offsets[i]);
        }
    });
}

//! The primal edges E, corner_edge and F(e), numbered as the paper's get/insert over the
//! faces numbers them (the order in which a traversal of the corners first meets each
//! edge; tested against EdgeGraph), without its hash table: each vertex sorts the edges
//! to its higher neighbours (upper_ends), so every access stays near the vertex. Three
//! parallel passes: mark each edge's first corner, number the edges by a prefix sum over
//! the corners, then write each edge from its lower end.
void build_edges(const Mesh& mesh, Topology& t)
{
    const Index corners = mesh.corner_count();
    // 1 at the first corner (in corner order) of each edge, then each edge's number there.
    std::vector<Index> edge_at(static_cast<size_t>(corners), 0);
    parallel_ranges(t.vertex_count, [&](Index begin, Index end) {
        std::vector<UpperEnd> ends;
        for (Index i = begin; i < end; ++i)
        {
            upper_ends(mesh, t, i, ends);
            for_each_run(ends, end_vertex,
                         [&](size_t first, size_t) { edge_at[ends[first].corner] = 1; });
        }
    });
    Index edges = 0;
    for (Index c = 0; c < corners; ++c)
    {
        const Index first = edge_at[c];
        edge_at[c] = edges;
        edges += first;
    }
    // Each edge from its lower end: its vertices, n_e, its corners and, per corner, its
    // place among the edge's faces (in face order).
    t.edge_vertices.resize(2 * static_cast<size_t>(edges));
    t.corner_edge.resize(corners);
    std::vector<Index> face_count(static_cast<size_t>(edges));
    // Then, per corner, its place among its edge's faces: edge_at is read at a run's
    // first corner only, by the one vertex that owns the run, before this overwrites it.
    std::vector<Index>& place = edge_at;
    parallel_ranges(t.vertex_count, [&](Index begin, Index end) {
        std::vector<UpperEnd> ends;
        for (Index i = begin; i < end; ++i)
        {
            upper_ends(mesh, t, i, ends);
            for_each_run(ends, end_vertex, [&](size_t first, size_t last) {
                const Index e = edge_at[ends[first].corner];
                t.edge_vertices[2 * static_cast<size_t>(e)] = i;
                t.edge_vertices[2 * static_cast<size_t>(e) + 1] = ends[first].j;
                face_count[e] = static_cast<Index>(last - first);
                for (size_t k = first; k < last; ++k)
                {
                    t.corner_edge[ends[k].corner] = e;
                    place[ends[k].corner] = static_cast<Index>(k - first);
                }
            });
        }
    });
    // F(e): faces per edge in face order.
    t.edge_face_offsets = offsets_from_counts(face_count);
    face_count = {};
    t.edge_faces.resize(t.edge_face_offsets.back());
    parallel_for(corners, [&](Index c) {
        t.edge_faces[t.edge_face_offsets[t.corner_edge[c]] + place[c]] = t.face_of_corner(c);
    });
}

//! The dual graph E*: pairs (f, g), f < g, of faces sharing a regular edge, a pair once
//! however many regular edges the faces share, numbered in the order of their first
//! shared edge (as the paper's get/insert over the edges numbers them); N*(f) in that
//! order. Parallel passes over the edges and the faces, like build_edges.
void build_dual(const Mesh& mesh, Topology& t)
{
    const auto edges = static_cast<Index>(t.edge_vertices.size() / 2);
    // The other face of regular edge e, seen from face f.
    const auto other = [&t](Index e, Index f) {
        const auto faces = t.faces_of_edge(e);
        return faces[0] == f ? faces[1] : faces[0];
    };
    // 1 at each regular edge that is the first one its two faces share, then the dual
    // edge's number there.
    std::vector<Index> dual_at(static_cast<size_t>(edges), 0);
    parallel_for(edges, [&](Index e) {
        if (t.edge_kind(e) != EdgeKind::Regular)
            return;
        const Index f = t.faces_of_edge(e)[0], g = t.faces_of_edge(e)[1];
        for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c)
        {
            const Index d = t.corner_edge[c];
            if (d < e && t.edge_kind(d) == EdgeKind::Regular && other(d, f) == g)
                return; // an earlier shared edge
        }
        dual_at[e] = 1;
    });
    Index duals = 0;
    for (Index e = 0; e < edges; ++e)
    {
        const Index first = dual_at[e];
        dual_at[e] = first ? duals : kInvalidIndex;
        duals += first;
    }
    t.dual_edge_faces.resize(2 * static_cast<size_t>(duals));
    parallel_for(edges, [&](Index e) {
        if (dual_at[e] == kInvalidIndex)
            return;
        const auto faces = t.faces_of_edge(e); // in face order: faces[0] < faces[1]
        t.dual_edge_faces[2 * static_cast<size_t>(dual_at[e])] = faces[0];
        t.dual_edge_faces[2 * static_cast<size_t>(dual_at[e]) + 1] = faces[1];
    });
    // N*(f): the dual edges at f, in dual-edge order. Each pair's first shared edge is an
    // edge of both faces, so a face finds all its dual edges among its own edges.
    const auto dual_edges_of = [&](Index f, std::vector<std::pair<Index, Index>>& out) {
        out.clear();
        for (Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c)
            if (const Index e = t.corner_edge[c]; dual_at[e] != kInvalidIndex)
                out.emplace_back(dual_at[e], other(e, f));
        std::sort(out.begin(), out.end());
    };
    std::vector<Index> count(t.face_count, 0);
    parallel_ranges(t.face_count, [&](Index begin, Index end) {
        std::vector<std::pair<Index, Index>> duals_of_f;
        for (Index f = begin; f < end; ++f)
        {
            dual_edges_of(f, duals_of_f);
            count[f] = static_cast<Index>(duals_of_f.size());
        }
    });
    t.face_neighbor_offsets = offsets_from_counts(count);
    count = {};
    t.face_neighbors.resize(t.face_neighbor_offsets.back());
    parallel_ranges(t.face_count, [&](Index begin, Index end) {
        std::vector<std::pair<Index, Index>> duals_of_f;
        for (Index f = begin; f < end; ++f)
        {
            dual_edges_of(f, duals_of_f);
            for (size_t k = 0; k < duals_of_f.size(); ++k)
                t.face_neighbors[t.face_neighbor_offsets[f] + static_cast<Index>(k)] =
                    duals_of_f[k].second;
        }
    });
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
    // Every face at least a triangle (validate_mesh): 3 #F corners means all triangles.
    t.triangles = mesh.face_vertices.size() == 3 * static_cast<size_t>(t.face_count);
    t.parts = parts;
    // The corners are the base of every other part. V(i) and the edge counts come from
    // the edges when they are built anyway, else from the corners (no edge hash).
    build_corners(mesh, t);
    build_neighbors_and_counts(mesh, t);
    const bool dual = has_parts(parts, TopologyParts::Dual);
    if (dual || has_parts(parts, TopologyParts::Edges))
        build_edges(mesh, t);
    if (dual)
        build_dual(mesh, t);
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
