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

//! \brief Preconditioned conjugate gradients for A x = b (conjugate_gradient, below) that can
//! stop and go on: iterate() runs some iterations, a later call continues the same
//! sequence, so that iterations spread over calls give the bits of one run of as many.
//! Each iterate leaves x the minimizer of the quadratic over the Krylov space so far. The
//! matrix, the inverted blocks and x must outlive it and stay unchanged between calls (x is
//! written by it only).
class ConjugateGradient
{
public:
    //! Starts at x (warm start); b is read here only.
    ConjugateGradient(const SymmetricRows& a, std::span<const Scalar> inverse_blocks, int block,
                      std::span<const Scalar> b, std::span<Scalar> x);
    //! At most max_iterations more, until |b - A x| <= tolerance |b|; the iterations and
    //! the relative residual since the start.
    ConjugateGradientResult iterate(Scalar tolerance, int max_iterations);
    //! Iterations since the start.
    int iterations() const { return iterations_; }

private:
    Scalar dot(std::span<const Scalar> u, std::span<const Scalar> v) const;
    void precondition(std::span<const Scalar> r, std::span<Scalar> z) const;

    const SymmetricRows* a_;
    std::span<const Scalar> inverse_;
    int block_;
    std::span<Scalar> x_;
    std::vector<Scalar> r_, z_, p_, ap_;
    Scalar b_norm_ = 0, r_norm_ = 0, rz_ = 0;
    int iterations_ = 0;
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
