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

// Conjugate gradients' cap on iterations for a system of m unknowns.
int iteration_cap(size_t m)
{
    return static_cast<int>(std::min<size_t>(4 * m + 100, 1000000));
}

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

size_t FreeSystemSolver::order_of(size_t free_count, Index k, int a) const
{
    // By vertex with blocks, else by coordinate (3 columns).
    return block_ == 3 ? 3 * static_cast<size_t>(k) + static_cast<size_t>(a)
                       : static_cast<size_t>(a) * free_count + static_cast<size_t>(k);
}

void FreeSystemSolver::gather(std::span<const Index> free, std::span<const Scalar> r,
                              std::vector<Scalar>& out) const
{
    out.resize(3 * free.size());
    parallel_for(static_cast<Index>(free.size()), [&](Index k) {
        for (int a = 0; a < 3; ++a)
            out[order_of(free.size(), k, a)] = r[3 * static_cast<size_t>(free[k]) + a];
    });
}

void FreeSystemSolver::scatter(std::span<const Index> free, std::span<const Scalar> d,
                               std::span<const Scalar> x0, std::span<Scalar> x) const
{
    parallel_for(static_cast<Index>(free.size()), [&](Index k) {
        for (int a = 0; a < 3; ++a)
        {
            const size_t i = 3 * static_cast<size_t>(free[k]) + a;
            x[i] = x0[i] + d[order_of(free.size(), k, a)];
        }
    });
}

int FreeSystemSolver::add_solution(std::span<const Index> free, std::span<const Scalar> r,
                                   std::span<Scalar> x)
{
    gather(free, r, free_r_);
    const int iterations = solve(free_r_);
    scatter(free, free_r_, x, x);
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
    const int cap = iteration_cap(m);
    for (size_t c = 0; c * m < r.size(); ++c)
    {
        const std::span<Scalar> d(r.data() + c * m, m);
        std::copy(d.begin(), d.end(), b.begin());
        std::fill(d.begin(), d.end(), Scalar(0));
        const ConjugateGradientResult result = conjugate_gradient(
            cg_->a, cg_->inverse, block_, b, d, kConjugateGradientTolerance, cap);
        iterations += result.iterations;
    }
    return iterations;
}

void FreeSystemSolver::begin_progressive(std::span<const Index> free, std::span<const Scalar> r)
{
    if (!cg_)
        throw SolverError("FreeSystemSolver::begin_progressive: a factor solves this system");
    gather(free, r, progressive_b_);
    progressive_d_.assign(progressive_b_.size(), 0);
    progressive_.clear();
    const size_t m = static_cast<size_t>(cg_->a.size);
    for (size_t c = 0; c * m < progressive_b_.size(); ++c)
        progressive_.emplace_back(cg_->a, cg_->inverse, block_,
                                  std::span<const Scalar>(progressive_b_.data() + c * m, m),
                                  std::span<Scalar>(progressive_d_.data() + c * m, m));
}

bool FreeSystemSolver::advance_progressive(int limit, std::span<const Index> free,
                                           std::span<const Scalar> x0, std::span<Scalar> x)
{
    if (!cg_ || progressive_d_.size() != 3 * free.size())
        throw SolverError("FreeSystemSolver::advance_progressive: no progressive solve begun");
    const int cap = iteration_cap(static_cast<size_t>(cg_->a.size));
    bool done = true;
    for (ConjugateGradient& column : progressive_)
    {
        const ConjugateGradientResult result = column.iterate(
            kConjugateGradientTolerance, std::max(0, std::min(limit, cap - column.iterations())));
        done = done && (result.relative_residual <= kConjugateGradientTolerance ||
                        result.iterations >= cap);
    }
    scatter(free, progressive_d_, x0, x);
    return done;
}

int FreeSystemSolver::progressive_iterations() const
{
    int n = 0;
    for (const ConjugateGradient& column : progressive_)
        n += column.iterations();
    return n;
}

} // namespace meshfair
