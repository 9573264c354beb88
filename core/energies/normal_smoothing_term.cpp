// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/normal_smoothing_term.h"

#include <algorithm>
#include <cmath>

#include "core/parallel/parallel.h"

namespace meshfair {

bool normalize3(Scalar* v)
{
    const Scalar len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(len > 0))
        return false;
    for (int a = 0; a < 3; ++a)
        v[a] /= len;
    return true;
}

NormalSmoothingTerm::NormalSmoothingTerm(const Topology& topology,
                                         std::span<const Index> hard_faces,
                                         std::span<const Scalar> hard_normals,
                                         std::span<const Index> soft_faces, Scalar soft_mu,
                                         std::span<const Scalar> soft_normals,
                                         std::span<const Scalar> soft_weights)
    : topology_(&topology),
      hard_faces_(hard_faces.begin(), hard_faces.end()),
      soft_faces_(soft_faces.begin(), soft_faces.end()),
      hard_normal_(hard_normals.begin(), hard_normals.end())
{
    if (!hard_faces_.empty())
        hard_.assign(topology.face_count, 0);
    if (!soft_faces_.empty())
    {
        soft_weight_.assign(topology.face_count, 0);
        soft_target_.assign(3 * static_cast<size_t>(topology.face_count), 0);
    }
    for (const Index f : hard_faces_)
        hard_[f] = 1;
    for (size_t k = 0; k < soft_faces_.size(); ++k)
    {
        const Index f = soft_faces_[k];
        soft_weight_[f] = soft_weights.empty() ? soft_mu : soft_mu * soft_weights[k];
        std::copy_n(&soft_normals[3 * k], 3, &soft_target_[3 * f]);
    }
}

Scalar NormalSmoothingTerm::dual_energy(std::span<const Scalar> u) const
{
    if (weights_)
    {
        // Each pair is listed from both of its faces: half of each listing.
        Scalar sum = 0;
        for (Index f = 0; f < topology_->face_count; ++f)
            for_each_neighbor(f, [&](Index g, Scalar w) {
                for (int a = 0; a < 3; ++a)
                {
                    const Scalar diff = u[3 * g + a] - u[3 * f + a];
                    sum += Scalar(0.5) * w * diff * diff;
                }
            });
        return sum;
    }
    const auto& d = topology_->dual_edge_faces;
    Scalar sum = 0;
    for (size_t k = 0; k < d.size(); k += 2)
        for (int a = 0; a < 3; ++a)
        {
            const Scalar diff = u[3 * d[k + 1] + a] - u[3 * d[k] + a];
            sum += diff * diff;
        }
    return sum;
}

Scalar NormalSmoothingTerm::soft_energy(std::span<const Scalar> u) const
{
    Scalar sum = 0;
    for (const Index f : soft_faces_)
        for (int a = 0; a < 3; ++a)
        {
            const Scalar diff = u[3 * f + a] - soft_target_[3 * f + a];
            sum += soft_weight_[f] * diff * diff;
        }
    return sum;
}

void NormalSmoothingTerm::apply_hard(std::span<Scalar> u) const
{
    for (size_t k = 0; k < hard_faces_.size(); ++k)
        std::copy_n(&hard_normal_[3 * k], 3, &u[3 * hard_faces_[k]]);
}

void NormalSmoothingTerm::displacements(std::span<const Scalar> u, std::span<Scalar> du_all) const
{
    // Each face writes its own displacement: any thread count gives the same bits.
    parallel_for(topology_->face_count, [&](Index f) {
        Scalar* du = &du_all[3 * f];
        du[0] = du[1] = du[2] = 0;
        const Scalar weight = soft_weight(f);
        const Scalar* target = soft_target(f);
        const Scalar denominator = neighbor_weight_sum(f) + weight;
        if (is_hard(f) || !(denominator > 0))
            return;
        const Scalar* uf = &u[3 * f];
        if (weights_)
            for_each_neighbor(f, [&](Index g, Scalar w) {
                for (int a = 0; a < 3; ++a)
                    du[a] += w * (u[3 * g + a] - uf[a]);
            });
        else
            for (const Index g : topology_->face_neighbors_of(f))
                for (int a = 0; a < 3; ++a)
                    du[a] += u[3 * g + a] - uf[a];
        for (int a = 0; a < 3; ++a)
            du[a] = (du[a] + weight * (target[a] - uf[a])) / denominator;
    });
}

void NormalSmoothingTerm::step(std::span<Scalar> u, Scalar lambda, std::span<Scalar> scratch) const
{
    // Displacements from the old normals first (Jacobi), then all updates at once.
    displacements(u, scratch);
    parallel_for(topology_->face_count, [&](Index f) {
        if (is_hard(f))
            return;
        Scalar next[3];
        for (int a = 0; a < 3; ++a)
            next[a] = u[3 * f + a] + lambda * scratch[3 * f + a];
        if (normalize3(next))
            std::copy_n(next, 3, &u[3 * f]);
    });
}

} // namespace meshfair
