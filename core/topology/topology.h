// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>

#include <span>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair {

//! Kind of an edge by its number n_e of incident faces \cite taubin_2012.
enum class EdgeKind
{
    Boundary, //!< n_e = 1
    Regular,  //!< n_e = 2
    Singular  //!< n_e >= 3
};

//! Parts of a Topology that build_topology fills; the others are left empty. The edge
//! counts (Topology::edge_count, boundary / regular / singular) are always there.
enum class TopologyParts : unsigned
{
    Neighbors = 1, //!< V(i): vertex_offsets, vertex_neighbors
    Corners = 2,   //!< corners of each vertex and (unless all triangles) corner_face
    Edges = 4,     //!< the edge list, corner_edge and F(e)
    Dual = 8,      //!< E* and N*(f)
    All = 15
};
constexpr TopologyParts operator|(TopologyParts a, TopologyParts b)
{
    return static_cast<TopologyParts>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
//! True when every part of `wanted` is in `parts`.
constexpr bool has_parts(TopologyParts parts, TopologyParts wanted)
{
    return (static_cast<unsigned>(parts) & static_cast<unsigned>(wanted)) ==
           static_cast<unsigned>(wanted);
}

//! \brief Connectivity of a polygon mesh: the primal graph G = (V, E) with per-edge
//! faces F(e), vertex neighbourhoods V(i), and the dual graph E* \cite taubin_2012 ("The
//! Primal Graph of a Polygon Mesh", "Smoothing Face Normal Vectors").
//!
//! All lists are flat arrays; variable-length ones are CSR (offsets + items). Edges are
//! numbered in order of first appearance while traversing the faces, as the paper's
//! insert() assigns them. Non-manifold meshes, several components, isolated vertices and
//! meshes without faces are all valid. Built once per mesh connectivity.
struct Topology
{
    Index vertex_count = 0;
    Index face_count = 0;
    TopologyParts parts = TopologyParts::All; //!< which of the lists below are filled

    //! 2 #E vertex indices, edge e = (edge_vertices[2e], edge_vertices[2e+1]) with i < j.
    std::vector<Index> edge_vertices;
    //! For corner k of face f (position k in Mesh::face_vertices), the edge from that
    //! corner's vertex to the next corner's vertex of the same face (cyclically).
    std::vector<Index> corner_edge;
    //! True when every face is a triangle: corner c is then in face c / 3 and corner_face
    //! is left empty (24 bytes a vertex a scan's solver need not hold).
    bool triangles = false;
    //! Face owning each corner; empty when `triangles` (use face_of_corner).
    std::vector<Index> corner_face;
    //! F(e) in CSR form; n_e = edge_face_offsets[e+1] - edge_face_offsets[e].
    std::vector<Index> edge_face_offsets, edge_faces;
    //! V(i) in CSR form, each V(i) in increasing order; n_i = vertex_offsets[i+1] -
    //! vertex_offsets[i].
    std::vector<Index> vertex_offsets, vertex_neighbors;
    //! The corners at vertex i in CSR form (one per incident face).
    std::vector<Index> vertex_corner_offsets, vertex_corners;
    //! E*: 2 #E* face indices, pairs (f, g), f < g, of faces sharing a regular edge;
    //! two faces sharing several regular edges form one dual edge.
    std::vector<Index> dual_edge_faces;
    //! N*(f), the dual neighbours of face f, in CSR form; n*_f is its size.
    std::vector<Index> face_neighbor_offsets, face_neighbors;

    Index boundary_edge_count = 0;
    Index regular_edge_count = 0;
    Index singular_edge_count = 0;

    Index edge_count() const
    {
        return boundary_edge_count + regular_edge_count + singular_edge_count;
    }
    Index dual_edge_count() const { return static_cast<Index>(dual_edge_faces.size() / 2); }
    Index edge_face_count(Index e) const { return edge_face_offsets[e + 1] - edge_face_offsets[e]; }
    EdgeKind edge_kind(Index e) const;
    Index valence(Index i) const { return vertex_offsets[i + 1] - vertex_offsets[i]; }
    std::span<const Index> neighbors(Index i) const
    {
        return {vertex_neighbors.data() + vertex_offsets[i], static_cast<size_t>(valence(i))};
    }
    std::span<const Index> faces_of_edge(Index e) const
    {
        return {edge_faces.data() + edge_face_offsets[e], static_cast<size_t>(edge_face_count(e))};
    }
    std::span<const Index> corners_of_vertex(Index i) const
    {
        return {vertex_corners.data() + vertex_corner_offsets[i],
                static_cast<size_t>(vertex_corner_offsets[i + 1] - vertex_corner_offsets[i])};
    }
    //! The face of corner c (needs TopologyParts::Corners unless `triangles`).
    Index face_of_corner(Index c) const
    {
        return triangles ? static_cast<Index>(static_cast<std::uint32_t>(c) / 3u) : corner_face[c];
    }
    Index dual_valence(Index f) const
    {
        return face_neighbor_offsets[f + 1] - face_neighbor_offsets[f];
    }
    std::span<const Index> face_neighbors_of(Index f) const
    {
        return {face_neighbors.data() + face_neighbor_offsets[f],
                static_cast<size_t>(dual_valence(f))};
    }
};

//! \brief Builds the topology of `mesh`, or only the `parts` asked for (a solver needs
//! V(i) and, for the face terms, the corners: about a third of the whole). Every list is
//! exactly what the paper's construction gives (EdgeGraph's get / insert over the faces,
//! then over the regular edges for E*; tested against it), but computed vertex by vertex
//! and face by face from the corners, on every thread (parallel.h) and without a hash
//! table, whose random accesses made most of the time on large meshes. The result does not
//! depend on the thread count. Every part is the same whichever others are built.
//! \pre validate_mesh(mesh) holds.
Topology build_topology(const Mesh& mesh, TopologyParts parts = TopologyParts::All);

//! Summary counts beyond the edge classification, for reports.
struct TopologySummary
{
    Index components = 0;        //!< connected components of the primal graph, isolated
                                 //!< vertices included (each is one component)
    Index isolated_vertices = 0; //!< vertices with n_i = 0
};

//! \brief Counts connected components (union-find over V(i)) and isolated vertices.
//! \pre the topology has TopologyParts::Neighbors.
TopologySummary summarize(const Topology& topology);

//! The corners before and after corner c in its face (cyclically), as corner indices.
struct AdjacentCorners
{
    Index previous;
    Index next;
};
//! Inline: the face-normal term calls it (through corner_neighbors) for every corner of
//! every step.
inline AdjacentCorners adjacent_corners(const Mesh& mesh, const Topology& topology, Index corner)
{
    // Branches, not (k +- 1) % n: two integer divisions per corner were a measurable
    // part of the face-normal term's step.
    const Index f = topology.face_of_corner(corner);
    const Index first = mesh.face_offsets[f], last = mesh.face_offsets[f + 1] - 1;
    return {corner == first ? last : corner - 1, corner == last ? first : corner + 1};
}

//! \brief Corners before and after corner k in its face: the vertices joined to the
//! corner's vertex by the two edges of that face, V(f, i) in the paper.
struct CornerNeighbors
{
    Index previous;
    Index next;
};
inline CornerNeighbors corner_neighbors(const Mesh& mesh, const Topology& topology, Index corner)
{
    const AdjacentCorners a = adjacent_corners(mesh, topology, corner);
    return {mesh.face_vertices[a.previous], mesh.face_vertices[a.next]};
}

//! \brief The corner walk of the solver's sweeps: a corner's face and its neighbours in
//! that face, with a shortcut for meshes of triangles only (scans, mostly), where corner c
//! is in face c / 3 and its face starts at corner 3 f: a multiplication instead of the
//! loads of corner_face and the face's offsets, each a link in the chain of dependent
//! loads a corner costs. The same faces and neighbours either way.
class CornerWalk
{
public:
    CornerWalk(const Mesh& mesh, const Topology& topology)
        : mesh_(&mesh), corner_face_(topology.corner_face.data()), triangles_(topology.triangles)
    {
    }
    //! True when every face is a triangle.
    bool triangles() const { return triangles_; }
    //! The face of corner c (topology.corner_face[c]).
    Index face(Index c) const
    {
        return triangles_ ? static_cast<Index>(static_cast<std::uint32_t>(c) / 3u)
                          : corner_face_[c];
    }
    //! corner_neighbors(mesh, topology, c), f being c's face.
    CornerNeighbors neighbors(Index c, Index f) const
    {
        Index first, n;
        if (triangles_)
        {
            first = 3 * f;
            n = 3;
        }
        else
        {
            first = mesh_->face_offsets[f];
            n = mesh_->face_offsets[f + 1] - first;
        }
        // Arithmetic, not selects: where a corner sits in its face is unpredictable, and a
        // compiled branch mispredicted about twice per vertex.
        const Index previous = c - 1 + n * static_cast<Index>(c == first);
        const Index next = c + 1 - n * static_cast<Index>(c == first + n - 1);
        const Index* corners = mesh_->face_vertices.data();
        return {corners[previous], corners[next]};
    }

private:
    const Mesh* mesh_;
    const Index* corner_face_;
    bool triangles_;
};

//! r += share[3 f ..] for each corner of vertex i, f its face, where flag[f] != 0 (flag
//! nullptr: every face), in corner order: what a fused step's vertex takes of the
//! per-face values its faces computed once (a centroid residual, a normal term's share).
[[gnu::always_inline]] inline void add_corner_shares(const Topology& topology, CornerWalk walk,
                                                     const char* flag, const Scalar* share, Index i,
                                                     Scalar* r)
{
    // Locals, not r[]: a store through r could change share for the compiler.
    Scalar r0 = r[0], r1 = r[1], r2 = r[2];
    for (const Index c : topology.corners_of_vertex(i))
    {
        const Index f = walk.face(c);
        if (flag != nullptr && flag[f] == 0)
            continue;
        const Scalar* q = share + 3 * static_cast<std::ptrdiff_t>(f);
        r0 += q[0];
        r1 += q[1];
        r2 += q[2];
    }
    r[0] = r0;
    r[1] = r1;
    r[2] = r2;
}

} // namespace meshfair
