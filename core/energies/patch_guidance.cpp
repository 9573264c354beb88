// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/patch_guidance.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

Scalar distance3(const Scalar* a, const Scalar* b)
{
    Scalar sum = 0;
    for (int k = 0; k < 3; ++k)
        sum += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(sum);
}

} // namespace

void vertex_face_rings(const Mesh& mesh, const Topology& topology, std::vector<Index>& offsets,
                       std::vector<Index>& rings)
{
    const Index nf = mesh.face_count();
    offsets.assign(static_cast<size_t>(nf) + 1, 0);
    rings.clear();
    // `seen[g] == f + 1` marks g as already listed for f: no clearing between faces.
    std::vector<Index> seen(nf, 0);
    for (Index f = 0; f < nf; ++f)
    {
        const size_t start = rings.size();
        for (const Index v : mesh.face(f))
            for (const Index corner : topology.corners_of_vertex(v))
            {
                const Index g = topology.face_of_corner(corner);
                if (g != f && seen[g] != f + 1)
                {
                    seen[g] = f + 1;
                    rings.push_back(g);
                }
            }
        std::sort(rings.begin() + static_cast<std::ptrdiff_t>(start), rings.end());
        offsets[f + 1] = static_cast<Index>(rings.size());
    }
}

PatchGuidance::PatchGuidance(const Mesh& mesh, const Topology& topology)
    : mesh_(&mesh), topology_(&topology)
{
    vertex_face_rings(mesh, topology, offsets_, ring_);
    area_.assign(mesh.face_count(), 0);
    consistency_.assign(mesh.face_count(), 0);
    mean_.assign(3 * static_cast<size_t>(mesh.face_count()), 0);
}

void PatchGuidance::compute(std::span<const Scalar> x, std::span<const Scalar> u,
                            std::span<Scalar> g)
{
    constexpr Scalar kEpsilon = 1e-9;
    const Index nf = mesh_->face_count();
    // The areas, each patch's consistency and mean normal, then each face's best patch
    // among those containing it: three sweeps, each face's work its own.
    parallel_for(nf, [&](Index f) {
        const Vec3 a = face_area_vector(*mesh_, x, f);
        area_[f] = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    });
    parallel_for(nf, [&](Index f) {
        const std::span<const Index> ring = ring_of(f);
        const auto in_patch = [&](Index h) {
            return h == f || std::binary_search(ring.begin(), ring.end(), h);
        };
        Vec3 mean{0, 0, 0};
        Scalar spread = 0, jump_max = 0, jump_sum = 0;
        const auto visit = [&](Index i) {
            for (int k = 0; k < 3; ++k)
                mean[k] += area_[i] * u[3 * static_cast<size_t>(i) + k];
            // D(P): every pair once (i with the faces after it in the patch's order f, ring).
            if (i == f)
                for (const Index j : ring)
                    spread = std::max(spread, distance3(&u[3 * i], &u[3 * j]));
            else
                for (auto it = std::upper_bound(ring.begin(), ring.end(), i); it != ring.end();
                     ++it)
                    spread = std::max(spread, distance3(&u[3 * i], &u[3 * *it]));
            // E_P: each edge shared by two faces of P once (from its lower face).
            for (const Index j : topology_->face_neighbors_of(i))
                if (j > i && in_patch(j))
                {
                    const Scalar phi = distance3(&u[3 * i], &u[3 * j]);
                    jump_max = std::max(jump_max, phi);
                    jump_sum += phi;
                }
        };
        visit(f);
        for (const Index i : ring)
            visit(i);
        consistency_[f] = spread * jump_max / (jump_sum + kEpsilon);
        const Scalar length = std::sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
        for (int k = 0; k < 3; ++k)
            mean_[3 * static_cast<size_t>(f) + k] =
                length > 0 ? mean[k] / length : u[3 * static_cast<size_t>(f) + k];
    });
    parallel_for(nf, [&](Index f) {
        Index best = f;
        for (const Index h : ring_of(f))
            if (consistency_[h] < consistency_[best] ||
                (consistency_[h] == consistency_[best] && h < best))
                best = h;
        std::copy_n(&mean_[3 * static_cast<size_t>(best)], 3, &g[3 * static_cast<size_t>(f)]);
    });
}

} // namespace meshfair
