// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/soft_vertex_term.h"

namespace meshfair {

SoftVertexTerm::SoftVertexTerm(Index vertex_count, std::span<const Index> vertices, Scalar mu,
                               std::span<const Scalar> targets)
    : mu_(mu),
      vertices_(vertices.begin(), vertices.end()),
      weight_(vertex_count, 0),
      target_(3 * static_cast<size_t>(vertex_count), 0)
{
    for (const Index i : vertices_)
        weight_[i] = mu_;
    set_targets(targets);
}

void SoftVertexTerm::set_targets(std::span<const Scalar> targets)
{
    for (size_t k = 0; k < vertices_.size(); ++k)
        for (int a = 0; a < 3; ++a)
            target_[3 * vertices_[k] + a] = targets[3 * k + a];
}

Scalar SoftVertexTerm::energy(std::span<const Scalar> x) const
{
    Scalar sum = 0;
    for (const Index i : vertices_)
        for (int a = 0; a < 3; ++a)
        {
            const Scalar d = x[3 * i + a] - target_[3 * i + a];
            sum += d * d;
        }
    return mu_ * sum;
}

Scalar SoftVertexTerm::quadratic(std::span<const Scalar> dx) const
{
    Scalar sum = 0;
    for (const Index i : vertices_)
        for (int a = 0; a < 3; ++a)
            sum += dx[3 * i + a] * dx[3 * i + a];
    return mu_ * sum;
}

void SoftVertexTerm::add_diagonal(std::span<Scalar> diagonal) const
{
    for (const Index i : vertices_)
        diagonal[i] += mu_;
}

void SoftVertexTerm::add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                             std::span<Scalar> rhs) const
{
    for (const Index i : vertices)
        for (int a = 0; a < 3; ++a)
            rhs[3 * i + a] += weight_[i] * (target_[3 * i + a] - x[3 * i + a]);
}

} // namespace meshfair
