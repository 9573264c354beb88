// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/solver/preparation_progress.h"
#include "core/types.h"

namespace meshfair {

//! \brief A symmetric sparse matrix by its upper triangle, in compressed columns: column c
//! holds rows row[column_start[c] .. column_start[c + 1]), ascending, each <= c, with
//! their values. The form CHOLMOD reads (stype 1) without a copy of the indices.
struct SymmetricMatrix
{
    std::int64_t size = 0;
    std::vector<std::int64_t> column_start; //!< size + 1
    std::vector<std::int64_t> row;
    std::vector<Scalar> value;
    //! y = A x (both triangles), for checks and residuals.
    void multiply(std::span<const Scalar> x, std::span<Scalar> y) const;
};

//! What a factorization cost, for reports and the memory budget.
struct FactorStats
{
    //! The analysis's time, 0 for a factorization on a kept analysis.
    double analyse_seconds = 0;
    double factor_seconds = 0;
    //! How many factorizations the analysis has served (1 after the first factor(); more
    //! when a new matrix of the same pattern, a weight changed, was factored on it).
    int factorizations = 0;
    //! Nonzeros of the factor L (CHOLMOD's estimate after the analysis, then its count).
    double factor_nonzeros = 0;
    //! Floating-point operations of the factorization (CHOLMOD's count from the analysis).
    double factor_flops = 0;
    //! Bytes the factor takes: its values and its row indices (8 + 8 each).
    double factor_bytes() const { return factor_nonzeros * 16; }
};

//! \brief Sparse Cholesky factorization A = L L^T of a symmetric positive definite
//! matrix, by CHOLMOD (SuiteSparse, supernodal, with its fill-reducing ordering: AMD, or
//! METIS when it is better), shaped like libigl's min_quad_with_fixed: analyse() once per
//! sparsity pattern (the free vertices and the terms), factor() again when only values
//! change (a weight), solve() for every new right-hand side (moved targets).
//!
//! Not copyable; one factorization at a time. The matrix passed to analyse() and factor()
//! is read during the call only.
class SparseCholesky
{
public:
    SparseCholesky();
    ~SparseCholesky();
    SparseCholesky(const SparseCholesky&) = delete;
    SparseCholesky& operator=(const SparseCholesky&) = delete;

    //! Symbolic analysis: the ordering and the factor's structure, for this pattern.
    //! \throw SolverError when CHOLMOD fails (out of memory); PreparationCancelled.
    void analyse(const SymmetricMatrix& a);
    //! Numeric factorization of a matrix with the pattern given to analyse().
    //! \return false when the matrix is not positive definite (its minimizer is not
    //! unique); the factor is then unusable until a factor() that succeeds.
    //! \throw SolverError on any other failure, or without a prior analyse();
    //! PreparationCancelled.
    bool factor(const SymmetricMatrix& a);
    //! True after a factor() that succeeded.
    bool factored() const { return factored_; }
    //! True when `a` has the sparsity pattern given to analyse() (its size, and the rows of
    //! each column, compared by a 64-bit digest): factor(a) may then skip the analysis.
    bool analysed_for(const SymmetricMatrix& a) const;
    //! Solves A X = B in place for `columns` right-hand sides stored one after the other
    //! (column-major: b holds size * columns values).
    //! \throw SolverError without a factorization or on a size mismatch.
    void solve(std::span<Scalar> b, int columns) const;
    std::int64_t size() const { return size_; }
    const FactorStats& stats() const { return stats_; }
    //! \brief Reports the ordering and the factorization as phases of `progress` (with
    //! their expected lengths, from this process's earlier analyses and factorizations),
    //! and stops before either when it is cancelled (PreparationCancelled).
    void report_to(std::shared_ptr<PreparationProgress> progress)
    {
        progress_ = std::move(progress);
    }
    const std::shared_ptr<PreparationProgress>& progress() const { return progress_; }

private:
    struct Cholmod;
    std::unique_ptr<Cholmod> cholmod_;
    std::int64_t size_ = 0;
    bool factored_ = false;
    FactorStats stats_;
    //! OpenBLAS's threads for this factor: one below kOneBlasThreadBelowFlops, else all.
    void use_blas_threads() const;
    std::shared_ptr<PreparationProgress> progress_;
    std::uint64_t pattern_digest_ = 0; //!< of the analysed pattern (analysed_for)
    std::int64_t pattern_nonzeros_ = -1;
};

} // namespace meshfair
