// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/recipe/recipe.h"
#include "core/topology/topology.h"

namespace meshfair::test {

//! \brief The minimizer of a recipe's energy over `free_vertices`, the other vertices held
//! at x_start: E(x) = x^T A x - 2 b^T x + c is assembled independently of the energy terms
//! (edge, soft, centroid and normal terms with the input normals held fixed, each element
//! weighing mu * weights[k]; the bending term's squared umbrellas from the faces alone),
//! then solved by Eigen's sparse Cholesky (LDL^T): the reference the Jacobi iteration must
//! reach.
//! \pre the soft, centroid and normal sets list their elements (no "all"); soft and
//! centroid targets are the recipe's or the input's; normals are the input's.
std::vector<Scalar> direct_minimizer(const Mesh& m, const Topology& t, const Recipe& r,
                                     std::span<const Scalar> x_start,
                                     std::span<const Index> free_vertices);

} // namespace meshfair::test
