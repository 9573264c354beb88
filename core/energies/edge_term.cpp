// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/edge_term.h"

#include "core/parallel/parallel.h"

namespace meshfair {

Scalar EdgeTerm::energy(std::span<const Scalar> x) const
{
    // Each edge once, from its lower end: only V(i) is needed, not the edge list.
    return weight_ * deterministic_sum(topology_->vertex_count, [&](Index i) {
               const Scalar* p = &x[3 * i];
               Scalar sum = 0;
               for (const Index j : topology_->neighbors(i))
                   if (j > i)
                   {
                       const Scalar* q = &x[3 * j];
                       const Scalar d0 = q[0] - p[0], d1 = q[1] - p[1], d2 = q[2] - p[2];
                       sum += d0 * d0 + d1 * d1 + d2 * d2;
                   }
               return sum;
           });
}

void EdgeTerm::add_diagonal(std::span<Scalar> diagonal) const
{
    for (Index i = 0; i < topology_->vertex_count; ++i)
        diagonal[i] += weight_ * topology_->valence(i);
}

void EdgeTerm::add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                       std::span<Scalar> rhs) const
{
    if (weight_ == 0)
        return;
    if (weight_ == 1)
    {
        parallel_for(static_cast<Index>(vertices.size()), [&](Index k) {
            add_vertex_rhs(vertices[k], x.data(), &rhs[3 * vertices[k]]);
        });
        return;
    }
    parallel_for(static_cast<Index>(vertices.size()), [&](Index k) {
        Scalar r[3] = {0, 0, 0};
        add_vertex_rhs(vertices[k], x.data(), r);
        for (int a = 0; a < 3; ++a)
            rhs[3 * vertices[k] + a] += weight_ * r[a];
    });
}

void EdgeTerm::add_vertex_energy(std::span<const Scalar> x, std::span<Scalar> per_vertex) const
{
    for (Index i = 0; i < topology_->vertex_count; ++i)
        for (const Index j : topology_->neighbors(i))
            if (j > i)
            {
                const Scalar* p = &x[3 * i];
                const Scalar* q = &x[3 * j];
                const Scalar d0 = q[0] - p[0], d1 = q[1] - p[1], d2 = q[2] - p[2];
                const Scalar half = 0.5 * weight_ * (d0 * d0 + d1 * d1 + d2 * d2);
                per_vertex[i] += half;
                per_vertex[j] += half;
            }
}

Scalar EdgeTerm::held_energy(std::span<const Scalar> x, std::span<const char> is_free) const
{
    Scalar sum = 0;
    for (Index i = 0; i < topology_->vertex_count; ++i)
        if (!is_free[i])
            for (const Index j : topology_->neighbors(i))
                if (j > i && !is_free[j])
                {
                    const Scalar* p = &x[3 * i];
                    const Scalar* q = &x[3 * j];
                    const Scalar d0 = q[0] - p[0], d1 = q[1] - p[1], d2 = q[2] - p[2];
                    sum += d0 * d0 + d1 * d1 + d2 * d2;
                }
    return weight_ * sum;
}

} // namespace meshfair
