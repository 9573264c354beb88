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

ConjugateGradientResult conjugate_gradient(const SymmetricRows& a,
                                           std::span<const Scalar> inverse_blocks, int block,
                                           std::span<const Scalar> b, std::span<Scalar> x,
                                           Scalar tolerance, int max_iterations)
{
    const auto n = static_cast<size_t>(a.size);
    const Index ni = static_cast<Index>(a.size);
    const auto dot = [&](std::span<const Scalar> u, std::span<const Scalar> v) {
        return deterministic_sum(
            ni, [&](Index i) { return u[static_cast<size_t>(i)] * v[static_cast<size_t>(i)]; });
    };
    const auto precondition = [&](std::span<const Scalar> r, std::span<Scalar> z) {
        const auto bb = static_cast<size_t>(block) * static_cast<size_t>(block);
        parallel_for(ni / block, [&](Index v) {
            const Scalar* m = &inverse_blocks[static_cast<size_t>(v) * bb];
            const size_t at = static_cast<size_t>(v) * static_cast<size_t>(block);
            for (int i = 0; i < block; ++i)
            {
                Scalar s = 0;
                for (int j = 0; j < block; ++j)
                    s += m[i * block + j] * r[at + static_cast<size_t>(j)];
                z[at + static_cast<size_t>(i)] = s;
            }
        });
    };
    ConjugateGradientResult result;
    const Scalar b_norm = std::sqrt(dot(b, b));
    if (n == 0 || b_norm == 0)
    {
        std::fill(x.begin(), x.end(), Scalar(0));
        return result;
    }
    std::vector<Scalar> r(n), z(n), p(n), ap(n);
    a.multiply(x, ap);
    parallel_for(ni, [&](Index i) {
        r[static_cast<size_t>(i)] = b[static_cast<size_t>(i)] - ap[static_cast<size_t>(i)];
    });
    Scalar r_norm = std::sqrt(dot(r, r));
    precondition(r, z);
    p = z;
    Scalar rz = dot(r, z);
    while (r_norm > tolerance * b_norm && result.iterations < max_iterations)
    {
        a.multiply(p, ap);
        const Scalar alpha = rz / dot(p, ap);
        parallel_for(ni, [&](Index i) {
            const auto k = static_cast<size_t>(i);
            x[k] += alpha * p[k];
            r[k] -= alpha * ap[k];
        });
        ++result.iterations;
        r_norm = std::sqrt(dot(r, r));
        precondition(r, z);
        const Scalar rz_next = dot(r, z);
        const Scalar beta = rz_next / rz;
        rz = rz_next;
        parallel_for(ni, [&](Index i) {
            const auto k = static_cast<size_t>(i);
            p[k] = z[k] + beta * p[k];
        });
    }
    result.relative_residual = r_norm / b_norm;
    return result;
}

} // namespace meshfair
