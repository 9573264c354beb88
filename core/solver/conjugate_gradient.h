// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/solver/sparse_cholesky.h"

namespace meshfair {

//! \brief A symmetric matrix by all of its rows (compressed sparse rows, both triangles):
//! what a product A x reads row by row, each row's sum in one order whatever the threads.
struct SymmetricRows
{
    std::int64_t size = 0;
    std::vector<std::int64_t> row_start; //!< size + 1
    std::vector<std::int64_t> column;
    std::vector<Scalar> value;
    //! The rows of a matrix given by its upper triangle (SparseCholesky's form).
    static SymmetricRows from_upper(const SymmetricMatrix& upper);
    //! y = A x, on every thread; the same bits for any thread count.
    void multiply(std::span<const Scalar> x, std::span<Scalar> y) const;
};

//! What a conjugate-gradient solve did.
struct ConjugateGradientResult
{
    int iterations = 0;
    //! |b - A x| / |b| at the end (0 when b = 0).
    Scalar relative_residual = 0;
};

//! \brief Preconditioned conjugate gradients for A x = b, A symmetric positive definite,
//! with the block-Jacobi preconditioner of A's diagonal blocks of `block` unknowns (1: the
//! diagonal; 3: a vertex's 3x3 block), inverted once by the caller (block_jacobi_inverse).
//! x is the starting point (warm start) and the result. Stops when |b - A x| <= tolerance
//! |b| or after max_iterations. Every sum is deterministic_sum's: the same bits for any
//! thread count.
ConjugateGradientResult conjugate_gradient(const SymmetricRows& a,
                                           std::span<const Scalar> inverse_blocks, int block,
                                           std::span<const Scalar> b, std::span<Scalar> x,
                                           Scalar tolerance, int max_iterations);

//! \brief The inverses of A's diagonal blocks of `block` (1 or 3) unknowns, stored densely
//! (block^2 values each, row-major); a block that is not positive definite gives
//! SolverError.
std::vector<Scalar> block_jacobi_inverse(const SymmetricRows& a, int block);

} // namespace meshfair
