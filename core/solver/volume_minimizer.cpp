// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/volume_minimizer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

Scalar dot(std::span<const Scalar> a, std::span<const Scalar> b)
{
    return deterministic_sum(static_cast<Index>(a.size()), [&](Index k) {
        return a[static_cast<size_t>(k)] * b[static_cast<size_t>(k)];
    });
}

// Solves the m x m symmetric system m x = rhs (m <= 5) by Gaussian elimination with
// partial pivoting; false when it is singular to rounding.
template <size_t N>
bool solve_small(std::array<std::array<Scalar, N>, N> m, std::array<Scalar, N> rhs, size_t n,
                 std::array<Scalar, N>& out)
{
    for (size_t c = 0; c < n; ++c)
    {
        size_t pivot = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c]))
                pivot = r;
        if (!(std::abs(m[pivot][c]) > 0))
            return false;
        std::swap(m[c], m[pivot]);
        std::swap(rhs[c], rhs[pivot]);
        for (size_t r = c + 1; r < n; ++r)
        {
            const Scalar f = m[r][c] / m[c][c];
            for (size_t k = c; k < n; ++k)
                m[r][k] -= f * m[c][k];
            rhs[r] -= f * rhs[c];
        }
    }
    for (size_t c = n; c-- > 0;)
    {
        Scalar s = rhs[c];
        for (size_t k = c + 1; k < n; ++k)
            s -= m[c][k] * out[k];
        out[c] = s / m[c][c];
    }
    return std::all_of(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n),
                       [](Scalar v) { return std::isfinite(v); });
}

} // namespace

int VolumeMinimizer::minimize(VolumeConstraint& volume, FreeSystemSolver& solver,
                              std::span<const Index> free, std::span<const Scalar> start,
                              std::span<Scalar> x)
{
    const size_t n = x.size();
    base_.assign(x.begin(), x.end());
    at_.assign(start.begin(), start.end());
    for (std::vector<Scalar>* v :
         {&image_, &residual_, &scratch_, &previous_residual_, &previous_image_})
        v->resize(n);
    residual_steps_.resize(kDepth);
    image_steps_.resize(kDepth);
    for (int k = 0; k < kDepth; ++k)
    {
        residual_steps_[static_cast<size_t>(k)].resize(n);
        image_steps_[static_cast<size_t>(k)].resize(n);
    }
    const Scalar tolerance = 1e-14 * bounding_box(base_).diagonal();
    int iterations = 0, kept = 0, next_column = 0;
    for (int k = 0; k < kMostEvaluations; ++k)
    {
        // image = G(at): from x*, along A^-1 g(at), onto the volume.
        std::copy(base_.begin(), base_.end(), image_.begin());
        volume.project_along(image_, at_, [&](std::span<Scalar> g) {
            std::fill(scratch_.begin(), scratch_.end(), Scalar(0));
            iterations += solver.add_solution(free, g, scratch_);
            std::copy(scratch_.begin(), scratch_.end(), g.begin());
        });
        Scalar change = 0;
        for (const Index v : free)
            for (size_t a = 0; a < 3; ++a)
            {
                const size_t i = 3 * static_cast<size_t>(v) + a;
                residual_[i] = image_[i] - at_[i];
                change = std::max(change, std::abs(residual_[i]));
            }
        if (change <= tolerance)
            break;
        // The residual and image differences since the last evaluation, as a new column.
        if (k > 0)
        {
            std::vector<Scalar>& df = residual_steps_[static_cast<size_t>(next_column)];
            std::vector<Scalar>& dg = image_steps_[static_cast<size_t>(next_column)];
            for (size_t i = 0; i < n; ++i)
            {
                df[i] = residual_[i] - previous_residual_[i];
                dg[i] = image_[i] - previous_image_[i];
            }
            next_column = (next_column + 1) % kDepth;
            kept = std::min(kept + 1, kDepth);
        }
        std::copy(residual_.begin(), residual_.end(), previous_residual_.begin());
        std::copy(image_.begin(), image_.end(), previous_image_.begin());
        // at = image - sum_j gamma_j dg_j, gamma minimizing |residual - sum_j gamma_j df_j|.
        std::copy(image_.begin(), image_.end(), at_.begin());
        if (kept == 0)
            continue;
        std::array<std::array<Scalar, kDepth>, kDepth> normal{};
        std::array<Scalar, kDepth> rhs{}, gamma{};
        for (size_t a = 0; a < static_cast<size_t>(kept); ++a)
        {
            rhs[a] = dot(residual_steps_[a], residual_);
            for (size_t b = a; b < static_cast<size_t>(kept); ++b)
                normal[a][b] = normal[b][a] = dot(residual_steps_[a], residual_steps_[b]);
        }
        for (size_t a = 0; a < static_cast<size_t>(kept); ++a)
            normal[a][a] *= 1 + 1e-12; // (columns nearly parallel: the mixing stays finite)
        if (!solve_small(normal, rhs, static_cast<size_t>(kept), gamma))
        {
            kept = 0; // the history says nothing more: plain steps again
            continue;
        }
        for (size_t j = 0; j < static_cast<size_t>(kept); ++j)
        {
            const std::vector<Scalar>& dg = image_steps_[j];
            for (const Index v : free)
                for (size_t a = 0; a < 3; ++a)
                {
                    const size_t i = 3 * static_cast<size_t>(v) + a;
                    at_[i] -= gamma[j] * dg[i];
                }
        }
    }
    std::copy(image_.begin(), image_.end(), x.begin());
    return iterations;
}

} // namespace meshfair
