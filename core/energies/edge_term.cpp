// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/edge_term.h"

#include "core/solver/parallel.h"

namespace meshfair {

Scalar EdgeTerm::energy(std::span<const Scalar> x) const
{
    const Index* ev = topology_->edge_vertices.data();
    return deterministic_sum(topology_->edge_count(), [&](Index e) {
        const Scalar* p = &x[3 * ev[2 * e]];
        const Scalar* q = &x[3 * ev[2 * e + 1]];
        const Scalar d0 = q[0] - p[0], d1 = q[1] - p[1], d2 = q[2] - p[2];
        return d0 * d0 + d1 * d1 + d2 * d2;
    });
}

void EdgeTerm::add_diagonal(std::span<Scalar> diagonal) const
{
    for (Index i = 0; i < topology_->vertex_count; ++i)
        diagonal[i] += topology_->valence(i);
}

void EdgeTerm::add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                       std::span<Scalar> rhs) const
{
    // Differences first, then the sum: meshes far from the origin (scans in
    // millimetres at 10^3) would lose digits to sum_j x_j - n_i x_i.
    parallel_for(static_cast<Index>(vertices.size()), [&](Index k) {
        const Index i = vertices[k];
        const Scalar x0 = x[3 * i], x1 = x[3 * i + 1], x2 = x[3 * i + 2];
        Scalar s0 = 0, s1 = 0, s2 = 0;
        for (const Index j : topology_->neighbors(i))
        {
            s0 += x[3 * j] - x0;
            s1 += x[3 * j + 1] - x1;
            s2 += x[3 * j + 2] - x2;
        }
        rhs[3 * i] += s0;
        rhs[3 * i + 1] += s1;
        rhs[3 * i + 2] += s2;
    });
}

} // namespace meshfair
