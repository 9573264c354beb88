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
    parallel_for(static_cast<Index>(vertices.size()),
                 [&](Index k) { add_vertex_rhs(vertices[k], x.data(), &rhs[3 * vertices[k]]); });
}

} // namespace meshfair
