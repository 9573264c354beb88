// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/solver/conjugate_gradient.h"
#include "core/solver/sparse_cholesky.h"

namespace meshfair {

//! The free vertices' system is not positive definite in double precision.
class NotPositiveDefiniteError : public SolverError
{
public:
    NotPositiveDefiniteError(const std::string& what, bool factored)
        : SolverError(what), factored_(factored)
    {
    }
    //! True when the factorization found it (else the conjugate gradients' preconditioner).
    bool factored() const { return factored_; }

private:
    bool factored_;
};

//! \brief A d = r over the free vertices, A symmetric positive definite (the steps of the
//! direct and implicit methods): factored once by sparse Cholesky (SparseCholesky), then
//! solved as often as r changes; or solved by conjugate gradients preconditioned by A's
//! diagonal blocks (the paper's Jacobi blocks), when they are asked for, when the factor
//! would not fit the budget, or when CHOLMOD fails (a note says why).
class FreeSystemSolver
{
public:
    //! `block`: 3 when the unknowns are 3 per vertex (A has 3x3 blocks), 1 when A is the
    //! same for the three coordinates (one unknown per vertex, three right-hand sides).
    //! `budget_bytes`: the largest factor taken (0: half the physical memory).
    //! `analysed`: a factorization kept from an earlier system (take_factorization); when A
    //! has its pattern (a weight changed, not the free set nor the terms), A is factored on
    //! its analysis, which is not done again (libigl's min_quad_with_fixed's precompute
    //! kept across a value change). Of another pattern (or never analysed: one that only
    //! carries a PreparationProgress, SparseCholesky::report_to), it is analysed afresh.
    //! \throw PreparationCancelled when its progress is cancelled.
    //! \throw NotPositiveDefiniteError when A is not positive definite in doubles.
    FreeSystemSolver(const SymmetricMatrix& a, int block, bool conjugate_gradients,
                     double budget_bytes, std::vector<std::string>& notes,
                     std::unique_ptr<SparseCholesky> analysed = nullptr);
    FreeSystemSolver(const FreeSystemSolver&) = delete;
    FreeSystemSolver& operator=(const FreeSystemSolver&) = delete;

    //! Replaces r (3 per free vertex: by vertex with blocks, else by coordinate, x then y
    //! then z; or any count of A's columns one after the other) by d = A^-1 r. Conjugate gradients
    //! start from d = 0 and stop at a residual of 1e-13 of r's: the minimizer to rounding. Returns
    //! their iterations (0: the factor).
    int solve(std::span<Scalar> r);
    //! x_f += A^-1 r_f, r and x of 3 #V values read and written at `free` (A's vertices, in
    //! A's order); the same as solve(). Allocates nothing after the first call.
    int add_solution(std::span<const Index> free, std::span<const Scalar> r, std::span<Scalar> x);
    //! The factor, or nullptr when conjugate gradients solve.
    const SparseCholesky* factorization() const { return cholesky_.get(); }
    //! Hands the factor over (for the next system: see the constructor); this solver
    //! cannot solve afterwards. nullptr when conjugate gradients solve.
    std::unique_ptr<SparseCholesky> take_factorization() { return std::move(cholesky_); }
    bool conjugate_gradients() const { return cg_.has_value(); }
    //! \brief Conjugate gradients stop after `limit` iterations a right-hand side (0: at the
    //! tolerance, the default): a truncated solve, d the minimizer of the quadratic over
    //! the Krylov space so far, so that x + d still lowers the energy (the editor's pin
    //! drag on a system too large to factor, a frame at a time). No effect on a factor.
    void limit_iterations(int limit) { iteration_limit_ = limit; }
    //! False when the last solve was truncated before the tolerance (limit_iterations).
    bool solved_to_tolerance() const { return solved_to_tolerance_; }

private:
    void use_conjugate_gradients(const SymmetricMatrix& a);

    int block_;
    std::unique_ptr<SparseCholesky> cholesky_;
    //! Conjugate gradients' matrix (A by rows) and its inverted diagonal blocks
    struct ConjugateGradientSystem
    {
        SymmetricRows a;
        std::vector<Scalar> inverse;
    };
    std::optional<ConjugateGradientSystem> cg_;
    std::vector<Scalar> free_r_; //!< add_solution's r_f, then d_f, in solve()'s order
    int iteration_limit_ = 0;
    bool solved_to_tolerance_ = true;
};

} // namespace meshfair
