// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/solver.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/parallel/parallel.h"

namespace meshfair {

void jacobi_displacements(const JacobiSystem& system, std::span<const Index> free_vertices,
                          bool use_blocks, std::span<Scalar> dx)
{
    if (use_blocks)
    {
        parallel_for(static_cast<Index>(free_vertices.size()), [&](Index k) {
            const Index i = free_vertices[k];
            symmetric3_apply(&system.inverse[6 * i], &system.rhs[3 * i], &dx[3 * i]);
        });
        return;
    }
    parallel_for(static_cast<Index>(free_vertices.size()), [&](Index k) {
        const Index i = free_vertices[k];
        const Scalar inv = Scalar(1) / system.diagonal[i];
        for (int a = 0; a < 3; ++a)
            dx[3 * i + a] = system.rhs[3 * i + a] * inv;
    });
}

void gradient_displacements(const JacobiSystem& system, std::span<const Index> free_vertices,
                            std::span<Scalar> dx)
{
    parallel_for(static_cast<Index>(free_vertices.size()), [&](Index k) {
        const Index i = free_vertices[k];
        for (int a = 0; a < 3; ++a)
            dx[3 * i + a] = system.rhs[3 * i + a];
    });
}

Scalar optimal_step(Scalar rhs_dot_dx, Scalar quadratic)
{
    return quadratic > 0 ? rhs_dot_dx / quadratic : Scalar(0);
}

Scalar rhs_dot(const JacobiSystem& system, std::span<const Index> free_vertices,
               std::span<const Scalar> dx)
{
    return deterministic_sum(static_cast<Index>(free_vertices.size()), [&](Index k) {
        const Index i = free_vertices[k];
        return system.rhs[3 * i] * dx[3 * i] + system.rhs[3 * i + 1] * dx[3 * i + 1] +
               system.rhs[3 * i + 2] * dx[3 * i + 2];
    });
}

Scalar rhs_norm(const JacobiSystem& system, std::span<const Index> free_vertices)
{
    return std::sqrt(deterministic_sum(static_cast<Index>(free_vertices.size()), [&](Index k) {
        const Scalar* r = &system.rhs[3 * static_cast<size_t>(free_vertices[k])];
        return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    }));
}

Scalar largest_displacement(std::span<const Index> free_vertices, std::span<const Scalar> dx)
{
    Scalar largest = 0;
    for (const Index i : free_vertices)
    {
        const Scalar* d = &dx[3 * static_cast<size_t>(i)];
        largest = std::max(largest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
    return largest;
}

bool invert_blocks(JacobiSystem& system, std::span<const Index> free_vertices, bool keep_blocks)
{
    Scalar* inverse = keep_blocks ? system.inverse.data() : system.block.data();
    for (const Index i : free_vertices)
        if (!spd_inverse3(system.diagonal[i], &system.block[6 * i], &inverse[6 * i]))
            return false;
    if (!keep_blocks)
        system.inverse = std::move(system.block);
    return true;
}

void apply_displacements(std::span<const Index> free_vertices, std::span<const Scalar> dx,
                         Scalar lambda, std::span<Scalar> x)
{
    parallel_for(static_cast<Index>(free_vertices.size()), [&](Index k) {
        const Index i = free_vertices[k];
        for (int a = 0; a < 3; ++a)
            x[3 * i + a] += lambda * dx[3 * i + a];
    });
}

bool converged(Scalar before, Scalar after, Scalar tolerance)
{
    if (!(tolerance > 0))
        return false;
    if (!(before > 0))
        return true;
    return (before - after) / before < tolerance;
}

} // namespace meshfair
