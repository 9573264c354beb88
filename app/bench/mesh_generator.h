// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair::bench {

//! \brief Regular k-fold subdivision of a triangle mesh: every edge is cut into k equal
//! segments and every triangle into the k^2 triangles of its barycentric grid, with the
//! new points on the original flat triangles (the shape does not change, only the
//! sampling). #V' = #V + (k - 1) #E + (k - 1)(k - 2)/2 #F, #F' = k^2 #F.
//!
//! The natural order of the result: the original vertices, then each edge's interior
//! points (edges in Topology order, from the lower vertex index to the higher), then each
//! face's interior points; faces are the k^2 children of face 0, then of face 1, ...
//! Each child keeps its parent's orientation.
//! \pre every face is a triangle; k >= 1.
Mesh subdivide_triangles(const Mesh& mesh, int k);

//! \brief The smallest k for which subdivide_triangles(mesh, k) has at least
//! `min_vertices` vertices.
int subdivision_factor_for(const Mesh& mesh, std::int64_t min_vertices);

//! \brief A uniformly random permutation of [0, n) (Fisher-Yates over a 64-bit Mersenne
//! twister), the same for a given seed on every platform.
std::vector<Index> random_order(Index n, std::uint64_t seed);

} // namespace meshfair::bench
