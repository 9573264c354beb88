// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/bilateral_face_weights.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/energies/patch_guidance.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

//! Every k-th neighbour entry goes into the median, so that at most 2^20 do.
size_t sample_stride(size_t entries)
{
    constexpr size_t kMaxSample = size_t(1) << 20;
    return std::max<size_t>(1, (entries + kMaxSample - 1) / kMaxSample);
}

} // namespace

Scalar mean_dual_edge_length(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x)
{
    const auto& d = topology.dual_edge_faces;
    if (d.empty())
        return 0;
    Scalar sum = 0;
    for (size_t k = 0; k < d.size(); k += 2)
    {
        const Vec3 a = face_centroid(mesh, x, d[k]), b = face_centroid(mesh, x, d[k + 1]);
        sum += std::sqrt(squared_distance3(a.data(), b.data()));
    }
    const size_t pairs = d.size() / 2;
    return sum / static_cast<Scalar>(pairs);
}

BilateralFaceWeights::BilateralFaceWeights(const Mesh& mesh, const Topology& topology,
                                           const BilateralWeights& settings,
                                           std::span<const Scalar> x)
    : mesh_(&mesh),
      sigma_s_(settings.sigma_s * mean_dual_edge_length(mesh, topology, x)),
      sigma_r_(settings.sigma_r),
      noise_scale_(settings.noise_scale),
      effective_sigma_r_(settings.sigma_r),
      reweight_every_(settings.reweight_every)
{
    if (settings.neighbors == FaceNeighborhood::Vertex)
        vertex_face_rings(mesh, topology, offsets_, neighbors_);
    else
    {
        offsets_ = topology.face_neighbor_offsets;
        neighbors_ = topology.face_neighbors;
    }
    const Index nf = mesh.face_count();
    spatial_.assign(neighbors_.size(), 1);
    weights_.assign(neighbors_.size(), 1);
    weight_sum_.resize(nf);
    for (Index f = 0; f < nf; ++f)
        weight_sum_[f] = static_cast<Scalar>(offsets_[f + 1] - offsets_[f]);
    centroids_.assign(3 * static_cast<size_t>(nf), 0);
    if (settings.guided)
    {
        guidance_.emplace(mesh, topology);
        guide_.assign(3 * static_cast<size_t>(nf), 0);
    }
    if (noise_scale_ > 0)
        sample_.assign((neighbors_.size() + sample_stride(neighbors_.size()) - 1) /
                           sample_stride(neighbors_.size()),
                       0);
}

void BilateralFaceWeights::reweight(std::span<const Scalar> x, std::span<const Scalar> u)
{
    const Index nf = mesh_->face_count();
    Scalar* centroids = centroids_.data();
    // The spatial factors change only when a centroid does: in the two-stage process the
    // positions stay put through every reweighting, and one exponential in two per
    // listing is then the one of the last reweighting, bit for bit.
    std::atomic<bool> moved{!spatial_current_};
    parallel_for(nf, [&](Index f) {
        const Vec3 c = face_centroid(*mesh_, x, f);
        if (!std::equal(c.begin(), c.end(), &centroids[3 * f]))
        {
            std::copy(c.begin(), c.end(), &centroids[3 * f]);
            moved.store(true, std::memory_order_relaxed);
        }
    });
    const bool spatial_due = moved.load();
    spatial_current_ = true;
    // 1 / 2 sigma^2, or 0 for a spatial factor of 1 (sigma_s = 0: no scale to measure).
    const Scalar spatial_rate = sigma_s_ > 0 ? Scalar(1) / (2 * sigma_s_ * sigma_s_) : 0;
    // The range kernel compares the guidance normals when guided, the normals otherwise.
    if (guidance_)
        guidance_->compute(x, u, guide_);
    const std::span<const Scalar> r = guidance_ ? std::span<const Scalar>(guide_) : u;
    effective_sigma_r_ = sigma_r_;
    if (!sample_.empty())
    {
        // Each pair is listed from both faces: the median of the listings is the pairs'.
        const size_t stride = sample_stride(neighbors_.size());
        Scalar* sample = sample_.data();
        parallel_for(nf, [&](Index f) {
            for (Index k = offsets_[f]; k < offsets_[f + 1]; ++k)
                if (static_cast<size_t>(k) % stride == 0)
                    sample[static_cast<size_t>(k) / stride] =
                        std::sqrt(squared_distance3(&r[3 * f], &r[3 * neighbors_[k]]));
        });
        const auto middle = sample_.begin() + static_cast<std::ptrdiff_t>(sample_.size() / 2);
        std::nth_element(sample_.begin(), middle, sample_.end());
        effective_sigma_r_ = std::max(sigma_r_, noise_scale_ * *middle);
    }
    const Scalar range_rate = Scalar(1) / (2 * effective_sigma_r_ * effective_sigma_r_);
    parallel_for(nf, [&](Index f) {
        Scalar sum = 0;
        for (Index k = offsets_[f]; k < offsets_[f + 1]; ++k)
        {
            const Index g = neighbors_[k];
            if (spatial_due)
                spatial_[k] = std::exp(-spatial_rate *
                                       squared_distance3(&centroids[3 * f], &centroids[3 * g]));
            weights_[k] =
                spatial_[k] * std::exp(-range_rate * squared_distance3(&r[3 * f], &r[3 * g]));
            sum += weights_[k];
        }
        weight_sum_[f] = sum;
    });
}

Scalar BilateralFaceWeights::robust_energy(std::span<const Scalar> u) const
{
    const Scalar range_rate = Scalar(1) / (2 * effective_sigma_r_ * effective_sigma_r_);
    const Scalar scale = effective_sigma_r_ * effective_sigma_r_;
    // Each unordered pair is listed from both faces: half of each listing.
    return Scalar(0.5) * deterministic_sum(mesh_->face_count(), [&](Index f) {
               Scalar sum = 0;
               for (Index k = offsets_[f]; k < offsets_[f + 1]; ++k)
                   sum += spatial_[k] * scale *
                          (1 - std::exp(-range_rate *
                                        squared_distance3(&u[3 * f], &u[3 * neighbors_[k]])));
               return sum;
           });
}

} // namespace meshfair
