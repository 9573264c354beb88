// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief A breadth-first numbering of the vertices over the primal graph: order[k] is
//! the index of the k-th vertex visited. Each component is visited from its lowest-indexed
//! vertex, components in order of that vertex, neighbours in V(i) order; isolated
//! vertices take their turn like one-vertex components.
//!
//! Why: a Jacobi sweep reads every neighbour of each vertex. In breadth-first order the
//! neighbours of consecutive vertices lie in a narrow band of the position array (the
//! width of a BFS level), so the sweep streams memory; in the random orders that scanners
//! and exporters produce, each neighbour is a cache miss.
//! Linear time; deterministic.
std::vector<Index> breadth_first_order(const Topology& topology);

//! \brief The inverse of a permutation: inverse[order[k]] = k.
//! \pre order is a permutation of [0, order.size()).
std::vector<Index> inverse_permutation(std::span<const Index> order);

//! \brief The mesh with its vertices renumbered: new vertex k is old vertex order[k].
//! Faces keep their order and corners their order within each face (so orientation is
//! kept); only the vertex indices in them change.
//! \pre order is a permutation of [0, mesh.vertex_count()).
Mesh renumber_vertices(const Mesh& mesh, std::span<const Index> order);

} // namespace meshfair
