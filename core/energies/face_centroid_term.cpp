// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/face_centroid_term.h"

#include <algorithm>
#include <utility>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair {

FaceCentroidTerm::FaceCentroidTerm(const Mesh& mesh, const Topology& topology,
                                   std::vector<Index> faces, Scalar mu,
                                   CentroidDenominator denominator, std::span<const Scalar> weights)
    : mesh_(&mesh),
      topology_(&topology),
      mu_(mu),
      denominator_(denominator),
      faces_(IndexList(std::move(faces))),
      constrained_(mesh.face_count(), 0),
      target_(3 * static_cast<size_t>(mesh.face_count()), 0),
      walk_(mesh, topology),
      all_faces_(false)
{
    for (const Index f : faces_)
        constrained_[f] = 1;
    all_faces_ = std::ranges::all_of(constrained_, [](char c) { return c != 0; });
    if (!weights.empty())
    {
        face_weight_.assign(mesh.face_count(), 0);
        for (size_t k = 0; k < faces_.size(); ++k)
            face_weight_[faces_[k]] = mu_ * weights[k];
    }
}

FaceCentroidTerm::FaceCentroidTerm(const Mesh& mesh, const Topology& topology,
                                   std::vector<Index> faces, Scalar mu,
                                   std::span<const Scalar> targets, CentroidDenominator denominator,
                                   std::span<const Scalar> weights)
    : FaceCentroidTerm(mesh, topology, std::move(faces), mu, denominator, weights)
{
    set_targets(targets);
}

void FaceCentroidTerm::use_centroids_of(std::span<const Scalar> x)
{
    std::vector<Scalar>().swap(target_); // freed, not only emptied
    centroid_source_ = x;
}

void FaceCentroidTerm::store_targets()
{
    if (!target_.empty())
        return;
    target_.assign(3 * static_cast<size_t>(mesh_->face_count()), 0);
    centroid_source_ = {};
}

void FaceCentroidTerm::set_targets_to_centroids(std::span<const Scalar> x)
{
    store_targets();
    for (const Index f : faces_)
    {
        const Vec3 c = face_centroid(*mesh_, x, f);
        std::copy(c.begin(), c.end(), &target_[3 * static_cast<size_t>(f)]);
    }
}

void FaceCentroidTerm::set_targets(std::span<const Scalar> targets)
{
    store_targets();
    for (size_t k = 0; k < faces_.size(); ++k)
        for (int a = 0; a < 3; ++a)
            target_[3 * faces_[k] + a] = targets[3 * k + a];
}

Scalar FaceCentroidTerm::energy(std::span<const Scalar> x) const
{
    const Scalar sum = deterministic_sum(static_cast<Index>(faces_.size()), [&](Index k) {
        const Index f = faces_[k];
        const Scalar s = squared_residual(x, f);
        return face_weight_.empty() ? s : face_weight_[f] * s;
    });
    // One weight: mu times the sum, the arithmetic of the paper's single mu.
    return face_weight_.empty() ? mu_ * sum : sum;
}

Scalar FaceCentroidTerm::quadratic(std::span<const Scalar> dx) const
{
    const Scalar sum = deterministic_sum(static_cast<Index>(faces_.size()), [&](Index k) {
        const Index f = faces_[k];
        const Vec3 c = face_centroid(*mesh_, dx, f);
        const Scalar s = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        return face_weight_.empty() ? s : face_weight_[f] * s;
    });
    return face_weight_.empty() ? mu_ * sum : sum;
}

void FaceCentroidTerm::add_diagonal(std::span<Scalar> diagonal) const
{
    for (Index i = 0; i < topology_->vertex_count; ++i)
        for (const Index c : topology_->corners_of_vertex(i))
        {
            const Index f = topology_->face_of_corner(c);
            if (!constrained_[f])
                continue;
            const Scalar n = mesh_->face_size(f);
            const Scalar w = face_weight(f);
            diagonal[i] += denominator_ == CentroidDenominator::Paper ? w / n : w / (n * n);
        }
}

Scalar FaceCentroidTerm::face_residuals(const Scalar* x, const Index* faces, Index begin, Index end,
                                        Scalar* residual) const
{
    return face_residuals(x, faces, begin, end, residual, [](Index) {});
}

void FaceCentroidTerm::add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                               std::span<Scalar> rhs) const
{
    parallel_for(static_cast<Index>(vertices.size()),
                 [&](Index k) { add_vertex_rhs(vertices[k], x.data(), &rhs[3 * vertices[k]]); });
}

Scalar FaceCentroidTerm::squared_residual(std::span<const Scalar> x, Index f) const
{
    const Vec3 c = face_centroid(*mesh_, x, f);
    const Vec3 t = target(f);
    Scalar s = 0;
    for (int a = 0; a < 3; ++a)
    {
        const Scalar d = c[a] - t[a];
        s += d * d;
    }
    return s;
}

void FaceCentroidTerm::add_vertex_energy(std::span<const Scalar> x,
                                         std::span<Scalar> per_vertex) const
{
    for (const Index f : faces_)
    {
        const Scalar share = face_weight(f) * squared_residual(x, f) / Scalar(mesh_->face_size(f));
        for (const Index v : mesh_->face(f))
            per_vertex[v] += share;
    }
}

Scalar FaceCentroidTerm::held_energy(std::span<const Scalar> x, std::span<const char> is_free) const
{
    Scalar sum = 0;
    for (const Index f : faces_)
    {
        const auto face = mesh_->face(f);
        if (std::any_of(face.begin(), face.end(), [&](Index v) { return is_free[v] != 0; }))
            continue;
        sum += face_weight(f) * squared_residual(x, f);
    }
    return sum;
}

} // namespace meshfair
