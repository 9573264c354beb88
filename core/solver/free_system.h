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
    //! \brief A solve of conjugate gradients spread over calls (the editor's frames without a
    //! factor): begin_progressive reads r as add_solution does; each advance_progressive runs
    //! at most `limit` more iterations a right-hand side, the same sequence going on, and
    //! writes x_f = x0_f + d_f with the solution so far (the minimizer over the Krylov space
    //! built: the energy lower at every call). Returns true once every right-hand side is at
    //! the tolerance, or at conjugate gradients' own cap. r, x0 and x at `free` as in
    //! add_solution. \pre conjugate_gradients().
    void begin_progressive(std::span<const Index> free, std::span<const Scalar> r);
    bool advance_progressive(int limit, std::span<const Index> free, std::span<const Scalar> x0,
                             std::span<Scalar> x);
    //! The iterations of the progressive solve so far, over its right-hand sides.
    int progressive_iterations() const;

private:
    void use_conjugate_gradients(const SymmetricMatrix& a);
    //! Where coordinate a of free vertex k (of free_count) sits in solve()'s order.
    size_t order_of(size_t free_count, Index k, int a) const;
    //! r at `free` into out, in solve()'s order.
    void gather(std::span<const Index> free, std::span<const Scalar> r,
                std::vector<Scalar>& out) const;
    //! x = x0 + d at `free` (d in solve()'s order; x0 may be x).
    void scatter(std::span<const Index> free, std::span<const Scalar> d, std::span<const Scalar> x0,
                 std::span<Scalar> x) const;

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
    //! The progressive solve: its right-hand sides, its solution so far (solve()'s order)
    //! and one conjugate-gradient sequence per right-hand side.
    std::vector<Scalar> progressive_b_, progressive_d_;
    std::vector<ConjugateGradient> progressive_;
};

} // namespace meshfair
