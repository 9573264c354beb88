// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/soft_vertex_term.h"

#include <algorithm>
#include <utility>

#include "core/solver/parallel.h"

namespace meshfair {

SoftVertexTerm::SoftVertexTerm(Index vertex_count, std::vector<Index> vertices, Scalar mu,
                               std::span<const Scalar> targets, std::span<const Scalar> weights)
    : mu_(mu),
      has_weights_(!weights.empty()),
      vertices_(std::move(vertices)),
      weight_(vertex_count, 0),
      target_(3 * static_cast<size_t>(vertex_count), 0)
{
    for (size_t k = 0; k < vertices_.size(); ++k)
        weight_[vertices_[k]] = has_weights_ ? mu_ * weights[k] : mu_;
    if (!targets.empty())
        set_targets(targets);
}

void SoftVertexTerm::set_targets_at(std::span<const Scalar> x)
{
    for (const Index i : vertices_)
        std::copy_n(&x[3 * static_cast<size_t>(i)], 3, &target_[3 * static_cast<size_t>(i)]);
}

void SoftVertexTerm::set_targets(std::span<const Scalar> targets)
{
    for (size_t k = 0; k < vertices_.size(); ++k)
        for (int a = 0; a < 3; ++a)
            target_[3 * vertices_[k] + a] = targets[3 * k + a];
}

Scalar SoftVertexTerm::energy(std::span<const Scalar> x) const
{
    const Scalar sum = deterministic_sum(static_cast<Index>(vertices_.size()), [&](Index k) {
        const Index i = vertices_[k];
        Scalar s = 0;
        for (int a = 0; a < 3; ++a)
        {
            const Scalar d = x[3 * i + a] - target_[3 * i + a];
            s += d * d;
        }
        return has_weights_ ? weight_[i] * s : s;
    });
    // One weight: mu times the sum, the arithmetic of the paper's single mu.
    return has_weights_ ? sum : mu_ * sum;
}

Scalar SoftVertexTerm::quadratic(std::span<const Scalar> dx) const
{
    const Scalar sum = deterministic_sum(static_cast<Index>(vertices_.size()), [&](Index k) {
        const Index i = vertices_[k];
        const Scalar s =
            dx[3 * i] * dx[3 * i] + dx[3 * i + 1] * dx[3 * i + 1] + dx[3 * i + 2] * dx[3 * i + 2];
        return has_weights_ ? weight_[i] * s : s;
    });
    return has_weights_ ? sum : mu_ * sum;
}

void SoftVertexTerm::add_diagonal(std::span<Scalar> diagonal) const
{
    for (const Index i : vertices_)
        diagonal[i] += weight_[i]; // mu itself without weights
}

void SoftVertexTerm::add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                             std::span<Scalar> rhs) const
{
    parallel_for(static_cast<Index>(vertices.size()),
                 [&](Index k) { add_vertex_rhs(vertices[k], x.data(), &rhs[3 * vertices[k]]); });
}

void SoftVertexTerm::add_vertex_energy(std::span<const Scalar> x,
                                       std::span<Scalar> per_vertex) const
{
    for (const Index i : vertices_)
    {
        Scalar s = 0;
        for (int a = 0; a < 3; ++a)
        {
            const Scalar d = x[3 * i + a] - target_[3 * i + a];
            s += d * d;
        }
        per_vertex[i] += weight_[i] * s;
    }
}

} // namespace meshfair
