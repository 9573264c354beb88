// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair {

//! \brief A breadth-first numbering of the vertices over the primal graph: order[k] is
//! the index of the k-th vertex visited. Each component is visited from its lowest-indexed
//! vertex, components in order of that vertex; a vertex's neighbours are taken face by
//! face (its corners in face order, the previous then the next corner of each); isolated
//! vertices take their turn like one-vertex components. Needs no Topology: it runs on the
//! faces, before any topology of the mesh is built.
//!
//! Why: a Jacobi sweep reads every neighbour of each vertex. In breadth-first order the
//! neighbours of consecutive vertices lie in a narrow band of the position array (the
//! width of a BFS level), so the sweep streams memory; in the random orders that scanners
//! and exporters produce, each neighbour is a cache miss.
//! Linear time; deterministic.
std::vector<Index> breadth_first_order(const Mesh& mesh);

//! \brief The numbering MeshFair solves in: vertices in breadth_first_order, faces sorted
//! (stably) by their first vertex in that order, so that the faces a sweep over the
//! vertices touches are also near each other in memory. Files, recipes and reports keep
//! the file's numbering; only the solver's copy of the mesh is renumbered.
struct LocalityOrder
{
    std::vector<Index> vertex_order; //!< internal vertex k is file vertex vertex_order[k]
    std::vector<Index> face_order;   //!< internal face g is file face face_order[g]
    std::vector<Index> vertex_index; //!< inverse: file vertex i is internal vertex_index[i]
    std::vector<Index> face_index;   //!< inverse: file face f is internal face_index[f]
};

//! \pre validate_mesh(mesh) holds. Linear time.
LocalityOrder locality_order(const Mesh& mesh);

//! \brief The mesh in the internal numbering: vertices and faces reordered, corners of
//! each face in their order (orientation kept). Reads vertex_order, vertex_index and
//! face_order (not face_index).
Mesh reorder_mesh(const Mesh& mesh, const LocalityOrder& order);

//! \brief The order that undoes `order`: reorder_mesh(reorder_mesh(m, order),
//! inverse_order(order)) == m exactly, so a program can renumber its one copy of the mesh
//! in place for the solver and back for the file. Takes the order by value (move it in:
//! the four arrays change roles, nothing is copied).
LocalityOrder inverse_order(LocalityOrder order);

//! \brief Internal positions (3 #V) back into the file's vertex order.
void positions_to_file_order(std::span<const Scalar> internal, const LocalityOrder& order,
                             std::span<Scalar> file);

//! \brief The inverse of a permutation: inverse[order[k]] = k.
//! \pre order is a permutation of [0, order.size()).
std::vector<Index> inverse_permutation(std::span<const Index> order);

//! \brief The mesh with its vertices renumbered: new vertex k is old vertex order[k].
//! Faces keep their order and corners their order within each face (so orientation is
//! kept); only the vertex indices in them change.
//! \pre order is a permutation of [0, mesh.vertex_count()).
Mesh renumber_vertices(const Mesh& mesh, std::span<const Index> order);

} // namespace meshfair
