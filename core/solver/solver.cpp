// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/solver.h"

#include "core/solver/parallel.h"

namespace meshfair {

void jacobi_displacements(const JacobiSystem& system, std::span<const Index> free_vertices,
                          bool use_blocks, std::span<Scalar> dx)
{
    if (use_blocks)
    {
        parallel_for(static_cast<Index>(free_vertices.size()), [&](Index k) {
            const Index i = free_vertices[k];
            cholesky3_solve(&system.factor[6 * i], &system.rhs[3 * i], &dx[3 * i]);
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

void fused_isotropic_step(const Topology& topology, std::span<const Scalar> diagonal,
                          std::span<const Scalar> soft_weights,
                          std::span<const Scalar> soft_targets,
                          std::span<const Index> free_vertices, Scalar lambda,
                          std::span<const Scalar> x, std::span<Scalar> y)
{
    const Index* offsets = topology.vertex_offsets.data();
    const Index* neighbors = topology.vertex_neighbors.data();
    const Scalar* xp = x.data();
    Scalar* yp = y.data();
    const bool soft = !soft_weights.empty();
    parallel_for(static_cast<Index>(free_vertices.size()), [&](Index k) {
        const Index i = free_vertices[k];
        const Scalar x0 = xp[3 * i], x1 = xp[3 * i + 1], x2 = xp[3 * i + 2];
        // As EdgeTerm::add_rhs: differences first, then the sum, added to a zeroed
        // right-hand side (0 + s, not s: the same bits, signed zeros included).
        Scalar s0 = 0, s1 = 0, s2 = 0;
        for (Index n = offsets[i]; n < offsets[i + 1]; ++n)
        {
            const Scalar* q = xp + 3 * neighbors[n];
            s0 += q[0] - x0;
            s1 += q[1] - x1;
            s2 += q[2] - x2;
        }
        Scalar r0 = Scalar(0) + s0, r1 = Scalar(0) + s1, r2 = Scalar(0) + s2;
        if (soft)
        {
            const Scalar w = soft_weights[i];
            r0 += w * (soft_targets[3 * i] - x0);
            r1 += w * (soft_targets[3 * i + 1] - x1);
            r2 += w * (soft_targets[3 * i + 2] - x2);
        }
        const Scalar inv = Scalar(1) / diagonal[i];
        yp[3 * i] = x0 + lambda * (r0 * inv);
        yp[3 * i + 1] = x1 + lambda * (r1 * inv);
        yp[3 * i + 2] = x2 + lambda * (r2 * inv);
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
