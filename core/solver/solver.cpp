// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/solver.h"

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
