// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/patch_guidance.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

Scalar distance3(const Scalar* a, const Scalar* b)
{
    return std::sqrt(squared_distance3(a, b));
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
    // E_P of every patch, as positions in the dual graph's listing (each edge from its
    // lower face): found once, read at every compute().
    const Index nf = mesh.face_count();
    const std::vector<Index>& dual_offsets = topology.face_neighbor_offsets;
    inner_offsets_.assign(static_cast<size_t>(nf) + 1, 0);
    for (Index f = 0; f < nf; ++f)
    {
        const std::span<const Index> ring = ring_of(f);
        const auto in_patch = [&](Index h) {
            return h == f || std::binary_search(ring.begin(), ring.end(), h);
        };
        const auto add = [&](Index i) {
            for (Index k = dual_offsets[i]; k < dual_offsets[i + 1]; ++k)
            {
                const Index j = topology.face_neighbors[k];
                if (j > i && in_patch(j))
                    inner_edges_.push_back(k);
            }
        };
        add(f);
        for (const Index i : ring)
            add(i);
        inner_offsets_[f + 1] = static_cast<Index>(inner_edges_.size());
    }
    area_.assign(mesh.face_count(), 0);
    jump_.assign(topology.face_neighbors.size(), 0);
    consistency_.assign(mesh.face_count(), 0);
    mean_.assign(3 * static_cast<size_t>(mesh.face_count()), 0);
}

void PatchGuidance::compute(std::span<const Scalar> x, std::span<const Scalar> u,
                            std::span<Scalar> g)
{
    constexpr Scalar kEpsilon = 1e-9;
    const Index nf = mesh_->face_count();
    // The areas and the jumps phi across each dual edge (once a face, not once a patch
    // that holds it), each patch's consistency and mean normal, then each face's best
    // patch among those containing it: three sweeps, each face's work its own.
    const std::vector<Index>& dual_offsets = topology_->face_neighbor_offsets;
    parallel_for(nf, [&](Index f) {
        const Vec3 a = face_area_vector(*mesh_, x, f);
        area_[f] = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (Index k = dual_offsets[f]; k < dual_offsets[f + 1]; ++k)
            jump_[k] = distance3(&u[3 * f], &u[3 * topology_->face_neighbors[k]]);
    });
    parallel_for(nf, [&](Index f) {
        const std::span<const Index> ring = ring_of(f);
        Vec3 mean{0, 0, 0};
        Scalar spread2 = 0, jump_max = 0, jump_sum = 0; // D(P)^2: one root a patch
        // D(P) over every pair once. The patch's normals gathered first (most patches hold
        // a dozen faces): each is then read once from the mesh-wide array, not once a pair.
        // (A patch too large to gather, which only a vertex of dozens of faces makes, is read
        // in place.)
        constexpr size_t kGathered = 48;
        std::array<Scalar, 3 * kGathered> gathered;
        const bool gather = ring.size() < kGathered;
        const auto normal = [&](size_t a) { // a = 0: f, else ring[a - 1]
            return gather ? &gathered[3 * a]
                          : &u[3 * static_cast<size_t>(a == 0 ? f : ring[a - 1])];
        };
        if (gather)
        {
            std::copy_n(&u[3 * static_cast<size_t>(f)], 3, gathered.data());
            for (size_t a = 0; a < ring.size(); ++a)
                std::copy_n(&u[3 * static_cast<size_t>(ring[a])], 3, &gathered[3 * (a + 1)]);
        }
        for (size_t a = 0; a <= ring.size(); ++a)
            for (size_t b = a + 1; b <= ring.size(); ++b)
                spread2 = std::max(spread2, squared_distance3(normal(a), normal(b)));
        const auto visit = [&](Index i) {
            for (int k = 0; k < 3; ++k)
                mean[k] += area_[i] * u[3 * static_cast<size_t>(i) + k];
        };
        visit(f);
        for (const Index i : ring)
            visit(i);
        // E_P: each edge shared by two faces of P once.
        for (Index e = inner_offsets_[f]; e < inner_offsets_[f + 1]; ++e)
        {
            const Scalar phi = jump_[inner_edges_[e]];
            jump_max = std::max(jump_max, phi);
            jump_sum += phi;
        }
        consistency_[f] = std::sqrt(spread2) * jump_max / (jump_sum + kEpsilon);
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
