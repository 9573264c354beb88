// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>

#include "core/solver/jacobi_system.h"

namespace meshfair {

//! \brief Generalized Jacobi displacements \cite taubin_2012 ("The Jacobi Iteration"):
//! dx_i = A_i^{-1} r_i for every free vertex i, with A_i = diagonal[i] I (+ block_i
//! through its inverse when `use_blocks`). Entries of non-free vertices are not
//! written. Linear time, no allocation.
void jacobi_displacements(const JacobiSystem& system, std::span<const Index> free_vertices,
                          bool use_blocks, std::span<Scalar> dx);

//! \brief Plain gradient-descent direction dx_i = r_i = -1/2 dE/dx_i (the paper's
//! "Descent Algorithms", which it contrasts with Laplacian smoothing).
void gradient_displacements(const JacobiSystem& system, std::span<const Index> free_vertices,
                            std::span<Scalar> dx);

//! \brief The exact line search for a quadratic energy: with E(x + l dx) =
//! E(x) - 2 l r^T dx + l^2 Q(dx), the minimizer is l* = r^T dx / Q(dx). Returns 0 when
//! Q(dx) is not positive (dx = 0: nothing to do).
Scalar optimal_step(Scalar rhs_dot_dx, Scalar quadratic);

//! r^T dx over the free vertices.
Scalar rhs_dot(const JacobiSystem& system, std::span<const Index> free_vertices,
               std::span<const Scalar> dx);

//! |r| over the free vertices (system.rhs), the same for any thread count.
Scalar rhs_norm(const JacobiSystem& system, std::span<const Index> free_vertices);

//! The largest |dx_i| over the free vertices.
Scalar largest_displacement(std::span<const Index> free_vertices, std::span<const Scalar> dx);

//! \brief Inverts each free vertex's A_i = diagonal[i] I + block_i into system.inverse:
//! beside the blocks when keep_blocks (they are rebuilt and inverted again, in joint
//! mode), else in place, the blocks then becoming the inverses (no second 6 #V array).
//! False when some A_i is not positive definite in double precision.
bool invert_blocks(JacobiSystem& system, std::span<const Index> free_vertices, bool keep_blocks);

//! x_i += lambda dx_i for every free vertex.
void apply_displacements(std::span<const Index> free_vertices, std::span<const Scalar> dx,
                         Scalar lambda, std::span<Scalar> x);

//! \brief The stopping rule for tolerance > 0: true when the relative decrease
//! (before - after) / before falls below `tolerance` (an increase included), or when
//! `before` is 0. A tolerance of 0 disables early stopping.
bool converged(Scalar before, Scalar after, Scalar tolerance);

} // namespace meshfair
