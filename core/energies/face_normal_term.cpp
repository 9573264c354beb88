// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/face_normal_term.h"

#include <algorithm>
#include <utility>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair {

FaceNormalTerm::FaceNormalTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces,
                               Scalar mu, std::span<const Scalar> weights)
    : FaceNormalTerm(mesh, topology, std::move(faces), mu, weights,
                     bounding_box(mesh.positions).centre())
{
}

FaceNormalTerm::FaceNormalTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces,
                               Scalar mu, std::span<const Scalar> weights, const Vec3& centre)
    : mesh_(&mesh),
      topology_(&topology),
      mu_(mu),
      faces_(IndexList(std::move(faces))),
      constrained_(mesh.face_count(), 0),
      walk_(mesh, topology),
      centre_(centre),
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

Scalar FaceNormalTerm::energy(std::span<const Scalar> x, std::span<const Scalar> normals) const
{
    const Scalar sum = deterministic_block_sums<Scalar>(
        static_cast<Index>(faces_.size()), [&](Index begin, Index end) {
            return pair_sums(x.data(), normals.data(), faces_.data(), begin, end);
        });
    // One weight: mu times the sum, the arithmetic of the paper's single mu.
    return energy_of_sum(sum);
}

void FaceNormalTerm::add_block(std::span<const Scalar> normals, std::span<const Index> vertices,
                               std::span<Scalar> block) const
{
    for (const Index i : vertices)
    {
        Scalar* B = &block[6 * i];
        for (const Index c : topology_->corners_of_vertex(i))
        {
            const Index f = topology_->face_of_corner(c);
            if (!constrained_[f])
                continue;
            const Scalar w = 2 * face_weight(f);
            const Scalar* u = &normals[3 * f];
            B[0] += w * u[0] * u[0];
            B[1] += w * u[0] * u[1];
            B[2] += w * u[0] * u[2];
            B[3] += w * u[1] * u[1];
            B[4] += w * u[1] * u[2];
            B[5] += w * u[2] * u[2];
        }
    }
}

void FaceNormalTerm::add_rhs(std::span<const Scalar> x, std::span<const Scalar> normals,
                             std::span<const Index> vertices, std::span<Scalar> rhs) const
{
    parallel_for(static_cast<Index>(vertices.size()), [&](Index k) {
        add_vertex_rhs(vertices[k], x.data(), normals.data(), &rhs[3 * vertices[k]]);
    });
}

template <bool Energy>
Scalar FaceNormalTerm::face_shares(const Scalar* x, const Scalar* normals, const Index* faces,
                                   Index begin, Index end, Scalar* share, bool add_all,
                                   const char* add) const
{
    Scalar sum = 0;
    for (Index k = begin; k < end; ++k)
    {
        const Index f = faces != nullptr ? faces[k] : k;
        sum += face_share<Energy>(x, normals, f, share, add_all || (add != nullptr && add[f] != 0));
    }
    return energy_of_sum(sum);
}

template Scalar FaceNormalTerm::face_shares<false>(const Scalar*, const Scalar*, const Index*,
                                                   Index, Index, Scalar*, bool, const char*) const;
template Scalar FaceNormalTerm::face_shares<true>(const Scalar*, const Scalar*, const Index*, Index,
                                                  Index, Scalar*, bool, const char*) const;

Scalar FaceNormalTerm::pair_sums(const Scalar* x, const Scalar* normals, const Index* faces,
                                 Index begin, Index end) const
{
    Scalar sum = 0;
    for (Index k = begin; k < end; ++k)
    {
        const Index f = faces != nullptr ? faces[k] : k;
        const Scalar s = pair_sum(&normals[3 * static_cast<std::ptrdiff_t>(f)], x, mesh_->face(f));
        sum += face_weight_.empty() ? s : face_weight_[f] * s;
    }
    return sum;
}

Scalar FaceNormalTerm::face_energies(const Scalar* x, const Scalar* normals, const Index* faces,
                                     Index begin, Index end) const
{
    return energy_of_sum(pair_sums(x, normals, faces, begin, end));
}

void FaceNormalTerm::edge_scatter(std::span<const Scalar> x, Index f, Scalar* M) const
{
    for (int k = 0; k < 6; ++k)
        M[k] = 0;
    const auto face = mesh_->face(f);
    for (size_t k = 0; k < face.size(); ++k)
    {
        const Scalar* p = &x[3 * face[k]];
        const Scalar* q = &x[3 * face[(k + 1) % face.size()]];
        const Scalar e0 = q[0] - p[0], e1 = q[1] - p[1], e2 = q[2] - p[2];
        M[0] += e0 * e0;
        M[1] += e0 * e1;
        M[2] += e0 * e2;
        M[3] += e1 * e1;
        M[4] += e1 * e2;
        M[5] += e2 * e2;
    }
}

void FaceNormalTerm::add_vertex_energy(std::span<const Scalar> x, std::span<const Scalar> normals,
                                       std::span<Scalar> per_vertex) const
{
    for (const Index f : faces_)
    {
        const Scalar* u = &normals[3 * f];
        const Scalar w = face_weight(f);
        const auto face = mesh_->face(f);
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Index i = face[k], j = face[(k + 1) % face.size()];
            const Scalar* p = &x[3 * i];
            const Scalar* q = &x[3 * j];
            const Scalar d = u[0] * (q[0] - p[0]) + u[1] * (q[1] - p[1]) + u[2] * (q[2] - p[2]);
            per_vertex[i] += 0.5 * w * d * d;
            per_vertex[j] += 0.5 * w * d * d;
        }
    }
}

Scalar FaceNormalTerm::held_energy(std::span<const Scalar> x, std::span<const char> is_free) const
{
    Scalar sum = 0;
    for (const Index f : faces_)
    {
        const auto face = mesh_->face(f);
        if (std::any_of(face.begin(), face.end(), [&](Index v) { return is_free[v] != 0; }))
            continue;
        const Scalar* u = &normals_[3 * f];
        const Scalar w = face_weight(f);
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Scalar* p = &x[3 * face[k]];
            const Scalar* q = &x[3 * face[(k + 1) % face.size()]];
            const Scalar d = u[0] * (q[0] - p[0]) + u[1] * (q[1] - p[1]) + u[2] * (q[2] - p[2]);
            sum += w * d * d;
        }
    }
    return sum;
}

} // namespace meshfair
