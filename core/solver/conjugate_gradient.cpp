// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/conjugate_gradient.h"

#include <cmath>
#include <string>

#include "core/errors.h"
#include "core/parallel/parallel.h"

namespace meshfair {

SymmetricRows SymmetricRows::from_upper(const SymmetricMatrix& upper)
{
    SymmetricRows a;
    a.size = upper.size;
    const auto n = static_cast<size_t>(upper.size);
    std::vector<std::int64_t> count(n + 1, 0);
    for (std::int64_t c = 0; c < upper.size; ++c)
        for (std::int64_t k = upper.column_start[c]; k < upper.column_start[c + 1]; ++k)
        {
            ++count[static_cast<size_t>(upper.row[k])];
            if (upper.row[k] != c)
                ++count[static_cast<size_t>(c)];
        }
    a.row_start.assign(n + 1, 0);
    for (size_t r = 0; r < n; ++r)
        a.row_start[r + 1] = a.row_start[r] + count[r];
    a.column.resize(static_cast<size_t>(a.row_start[n]));
    a.value.resize(a.column.size());
    // Column by column, ascending: row c receives its lower entries (rows r < c of column
    // c, ascending) and its diagonal while column c is read, then its upper ones (column c'
    // > c) in the later columns' order: every row ends up in ascending columns.
    std::vector<std::int64_t> next(a.row_start.begin(), a.row_start.end() - 1);
    for (std::int64_t c = 0; c < upper.size; ++c)
        for (std::int64_t k = upper.column_start[c]; k < upper.column_start[c + 1]; ++k)
        {
            const std::int64_t r = upper.row[k];
            const auto put = [&](std::int64_t row, std::int64_t col) {
                const auto at = static_cast<size_t>(next[static_cast<size_t>(row)]++);
                a.column[at] = col;
                a.value[at] = upper.value[k];
            };
            if (r != c)
                put(c, r);
            put(r, c);
        }
    return a;
}

void SymmetricRows::multiply(std::span<const Scalar> x, std::span<Scalar> y) const
{
    parallel_for(static_cast<Index>(size), [&](Index r) {
        Scalar sum = 0;
        for (std::int64_t k = row_start[r]; k < row_start[r + 1]; ++k)
            sum += value[static_cast<size_t>(k)] * x[static_cast<size_t>(column[k])];
        y[static_cast<size_t>(r)] = sum;
    });
}

std::vector<Scalar> block_jacobi_inverse(const SymmetricRows& a, int block)
{
    const std::int64_t blocks = a.size / block;
    const auto bb = static_cast<size_t>(block) * static_cast<size_t>(block);
    std::vector<Scalar> inverse(static_cast<size_t>(blocks) * bb, 0);
    bool singular = false;
    for (std::int64_t v = 0; v < blocks; ++v)
    {
        Scalar m[3][3] = {};
        for (int i = 0; i < block; ++i)
        {
            const std::int64_t r = v * block + i;
            for (std::int64_t k = a.row_start[r]; k < a.row_start[r + 1]; ++k)
            {
                const std::int64_t c = a.column[k] - v * block;
                if (c >= 0 && c < block)
                    m[i][c] = a.value[static_cast<size_t>(k)];
            }
        }
        Scalar* out = &inverse[static_cast<size_t>(v) * bb];
        if (block == 1)
        {
            singular = singular || !(m[0][0] > 0);
            out[0] = 1 / m[0][0];
            continue;
        }
        const Scalar c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1],
                     c01 = m[0][2] * m[2][1] - m[0][1] * m[2][2],
                     c02 = m[0][1] * m[1][2] - m[0][2] * m[1][1];
        const Scalar det = m[0][0] * c00 + m[1][0] * c01 + m[2][0] * c02;
        singular = singular || !(det > 0) || !(m[0][0] > 0);
        const Scalar s = 1 / det;
        out[0] = c00 * s;
        out[1] = c01 * s;
        out[2] = c02 * s;
        out[3] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * s;
        out[4] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s;
        out[5] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * s;
        out[6] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * s;
        out[7] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * s;
        out[8] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s;
    }
    if (singular)
        throw SolverError("conjugate gradients: a diagonal block is not positive definite");
    return inverse;
}

ConjugateGradient::ConjugateGradient(const SymmetricRows& a, std::span<const Scalar> inverse_blocks,
                                     int block, std::span<const Scalar> b, std::span<Scalar> x)
    : a_(&a), inverse_(inverse_blocks), block_(block), x_(x)
{
    const auto n = static_cast<size_t>(a.size);
    b_norm_ = std::sqrt(dot(b, b));
    if (n == 0 || b_norm_ == 0)
    {
        std::fill(x.begin(), x.end(), Scalar(0));
        return;
    }
    r_.resize(n);
    z_.resize(n);
    ap_.resize(n);
    a.multiply(x, ap_);
    parallel_for(static_cast<Index>(n), [&](Index i) {
        r_[static_cast<size_t>(i)] = b[static_cast<size_t>(i)] - ap_[static_cast<size_t>(i)];
    });
    r_norm_ = std::sqrt(dot(r_, r_));
    precondition(r_, z_);
    p_ = z_;
    rz_ = dot(r_, z_);
}

Scalar ConjugateGradient::dot(std::span<const Scalar> u, std::span<const Scalar> v) const
{
    return deterministic_sum(static_cast<Index>(a_->size), [&](Index i) {
        return u[static_cast<size_t>(i)] * v[static_cast<size_t>(i)];
    });
}

void ConjugateGradient::precondition(std::span<const Scalar> r, std::span<Scalar> z) const
{
    const int block = block_;
    const auto bb = static_cast<size_t>(block) * static_cast<size_t>(block);
    parallel_for(static_cast<Index>(a_->size) / block, [&](Index v) {
        const Scalar* m = &inverse_[static_cast<size_t>(v) * bb];
        const size_t at = static_cast<size_t>(v) * static_cast<size_t>(block);
        for (int i = 0; i < block; ++i)
        {
            Scalar s = 0;
            for (int j = 0; j < block; ++j)
                s += m[i * block + j] * r[at + static_cast<size_t>(j)];
            z[at + static_cast<size_t>(i)] = s;
        }
    });
}

ConjugateGradientResult ConjugateGradient::iterate(Scalar tolerance, int max_iterations)
{
    const Index ni = static_cast<Index>(a_->size);
    int done = 0;
    while (b_norm_ > 0 && r_norm_ > tolerance * b_norm_ && done < max_iterations)
    {
        a_->multiply(p_, ap_);
        const Scalar alpha = rz_ / dot(p_, ap_);
        parallel_for(ni, [&](Index i) {
            const auto k = static_cast<size_t>(i);
            x_[k] += alpha * p_[k];
            r_[k] -= alpha * ap_[k];
        });
        ++done;
        ++iterations_;
        r_norm_ = std::sqrt(dot(r_, r_));
        precondition(r_, z_);
        const Scalar rz_next = dot(r_, z_);
        const Scalar beta = rz_next / rz_;
        rz_ = rz_next;
        parallel_for(ni, [&](Index i) {
            const auto k = static_cast<size_t>(i);
            p_[k] = z_[k] + beta * p_[k];
        });
    }
    ConjugateGradientResult result;
    result.iterations = iterations_;
    result.relative_residual = b_norm_ > 0 ? r_norm_ / b_norm_ : 0;
    return result;
}

ConjugateGradientResult conjugate_gradient(const SymmetricRows& a,
                                           std::span<const Scalar> inverse_blocks, int block,
                                           std::span<const Scalar> b, std::span<Scalar> x,
                                           Scalar tolerance, int max_iterations)
{
    return ConjugateGradient(a, inverse_blocks, block, b, x).iterate(tolerance, max_iterations);
}

} // namespace meshfair
