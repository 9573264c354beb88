// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/free_system.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

// Conjugate gradients stop at this residual relative to the step's right-hand side: the
// minimizer to rounding, as the factor gives it (the run's rule then stops the steps).
constexpr Scalar kConjugateGradientTolerance = 1e-13;

const char* const kNotPositiveDefinite =
    "the system of the free vertices is not positive definite in double precision (weights "
    "many orders of magnitude apart: closer ones make it so)";

// The factor budget in bytes: the one given, or half the physical memory.
double budget_or_half_memory(double budget)
{
    if (budget > 0)
        return budget;
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? 0.5 * static_cast<double>(pages) * static_cast<double>(page)
                                 : 1e300;
}

} // namespace

FreeSystemSolver::FreeSystemSolver(const SymmetricMatrix& a, int block, bool conjugate_gradients,
                                   double budget_bytes, std::vector<std::string>& notes,
                                   std::unique_ptr<SparseCholesky> analysed)
    : block_(block)
{
    if (conjugate_gradients)
    {
        use_conjugate_gradients(a);
        return;
    }
    // Conjugate gradients in place of a factor that fails or would not fit.
    const auto instead = [&](const std::string& why) {
        notes.push_back(why + ": solved by conjugate gradients instead");
        use_conjugate_gradients(a);
    };
    const bool reuse = analysed != nullptr && analysed->analysed_for(a);
    // One of another pattern is analysed afresh (its factor freed first), keeping the
    // progress it reports to.
    cholesky_ = analysed != nullptr ? std::move(analysed) : std::make_unique<SparseCholesky>();
    try
    {
        if (!reuse)
            cholesky_->analyse(a);
    }
    catch (const SolverError& e)
    {
        instead(e.what());
        return;
    }
    const double budget = budget_or_half_memory(budget_bytes);
    if (cholesky_->stats().factor_bytes() > budget)
    {
        instead("the factor would take " +
                std::to_string(std::lround(cholesky_->stats().factor_bytes() / 1e6)) +
                " MB, over the factor budget of " + std::to_string(std::lround(budget / 1e6)) +
                " MB");
        return;
    }
    bool positive = false;
    try
    {
        positive = cholesky_->factor(a);
    }
    catch (const SolverError& e)
    {
        instead(e.what());
        return;
    }
    if (!positive)
        throw NotPositiveDefiniteError(kNotPositiveDefinite, true);
}

void FreeSystemSolver::use_conjugate_gradients(const SymmetricMatrix& a)
{
    cholesky_.reset();
    ConjugateGradientSystem cg;
    cg.a = SymmetricRows::from_upper(a);
    try
    {
        cg.inverse = block_jacobi_inverse(cg.a, block_);
    }
    catch (const SolverError&)
    {
        throw NotPositiveDefiniteError(kNotPositiveDefinite, false);
    }
    cg_ = std::move(cg);
}

int FreeSystemSolver::add_solution(std::span<const Index> free, std::span<const Scalar> r,
                                   std::span<Scalar> x)
{
    // r_f in the solver's order: by vertex with blocks, else by coordinate (3 columns).
    const Index n = static_cast<Index>(free.size());
    const auto at = [&](Index k, int a) {
        return block_ == 3 ? 3 * static_cast<size_t>(k) + a
                           : static_cast<size_t>(a) * static_cast<size_t>(n) + k;
    };
    free_r_.resize(3 * free.size());
    parallel_for(n, [&](Index k) {
        for (int a = 0; a < 3; ++a)
            free_r_[at(k, a)] = r[3 * static_cast<size_t>(free[k]) + a];
    });
    const int iterations = solve(free_r_);
    parallel_for(n, [&](Index k) {
        for (int a = 0; a < 3; ++a)
            x[3 * static_cast<size_t>(free[k]) + a] += free_r_[at(k, a)];
    });
    return iterations;
}

int FreeSystemSolver::solve(std::span<Scalar> r)
{
    if (cholesky_)
    {
        cholesky_->solve(r, static_cast<int>(static_cast<std::int64_t>(r.size()) /
                                             std::max<std::int64_t>(cholesky_->size(), 1)));
        return 0;
    }
    if (!cg_)
        throw SolverError("FreeSystemSolver::solve: its factorization was handed over");
    // A d = r from d = 0 (a step starts at the current positions, the last solution): one
    // solve of 3 #free unknowns with blocks, else one per coordinate.
    const size_t m = static_cast<size_t>(cg_->a.size);
    std::vector<Scalar> b(m);
    int iterations = 0;
    const int cap = static_cast<int>(std::min<size_t>(4 * m + 100, 1000000));
    solved_to_tolerance_ = true;
    for (size_t c = 0; c * m < r.size(); ++c)
    {
        const std::span<Scalar> d(r.data() + c * m, m);
        std::copy(d.begin(), d.end(), b.begin());
        std::fill(d.begin(), d.end(), Scalar(0));
        const ConjugateGradientResult result =
            conjugate_gradient(cg_->a, cg_->inverse, block_, b, d, kConjugateGradientTolerance,
                               iteration_limit_ > 0 ? std::min(iteration_limit_, cap) : cap);
        iterations += result.iterations;
        solved_to_tolerance_ &= result.relative_residual <= kConjugateGradientTolerance;
    }
    return iterations;
}

} // namespace meshfair
