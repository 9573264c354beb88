// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/soft_vertex_term.h"

#include <algorithm>
#include <utility>

#include "core/parallel/parallel.h"

namespace meshfair {

SoftVertexTerm::SoftVertexTerm(Index vertex_count, std::vector<Index> vertices, Scalar mu,
                               std::span<const Scalar> targets, std::span<const Scalar> weights)
    : mu_(mu),
      has_weights_(!weights.empty()),
      vertices_(IndexList(std::move(vertices))),
      own_target_(3 * static_cast<size_t>(vertex_count), 0),
      target_(own_target_)
{
    if (has_weights_)
    {
        weight_.assign(vertex_count, 0);
        for (size_t k = 0; k < vertices_.size(); ++k)
            weight_[vertices_[k]] = mu_ * weights[k];
    }
    else
    {
        listed_.assign(vertex_count, 0);
        for (const Index i : vertices_)
            listed_[i] = 1;
    }
    if (!targets.empty())
        set_targets(targets);
}

void SoftVertexTerm::own_targets()
{
    if (!own_target_.empty())
        return;
    own_target_.assign(target_.begin(), target_.end());
    target_ = own_target_;
}

void SoftVertexTerm::view_targets(std::span<const Scalar> x)
{
    std::vector<Scalar>().swap(own_target_); // freed, not only emptied
    target_ = x;
}

void SoftVertexTerm::set_targets_at(std::span<const Scalar> x)
{
    own_targets();
    for (const Index i : vertices_)
        std::copy_n(&x[3 * static_cast<size_t>(i)], 3, &own_target_[3 * static_cast<size_t>(i)]);
}

void SoftVertexTerm::set_targets(std::span<const Scalar> targets)
{
    own_targets();
    for (size_t k = 0; k < vertices_.size(); ++k)
        for (int a = 0; a < 3; ++a)
            own_target_[3 * vertices_[k] + a] = targets[3 * k + a];
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
        diagonal[i] += weight(i); // mu itself without weights
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
        per_vertex[i] += weight(i) * s;
    }
}

Scalar SoftVertexTerm::held_energy(std::span<const Scalar> x, std::span<const char> is_free) const
{
    Scalar sum = 0;
    for (const Index i : vertices_)
    {
        if (is_free[i])
            continue;
        Scalar s = 0;
        for (int a = 0; a < 3; ++a)
        {
            const Scalar d = x[3 * i + a] - target_[3 * i + a];
            s += d * d;
        }
        sum += weight(i) * s;
    }
    return sum;
}

} // namespace meshfair
