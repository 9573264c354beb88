// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/reference_filters.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair::bench {

namespace {

Scalar distance2(const Scalar* a, const Scalar* b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

std::vector<Scalar> face_centroids(const Mesh& mesh, std::span<const Scalar> x)
{
    std::vector<Scalar> centroids(3 * static_cast<size_t>(mesh.face_count()));
    parallel_for(mesh.face_count(), [&](Index f) {
        const Vec3 c = face_centroid(mesh, x, f);
        for (int a = 0; a < 3; ++a)
            centroids[3 * f + a] = c[a];
    });
    return centroids;
}

// One umbrella step x <- x + factor dx into y.
void umbrella_step(const Topology& topology, std::span<const Scalar> x, std::span<Scalar> y,
                   Scalar factor)
{
    parallel_for(topology.vertex_count, [&](Index i) {
        const auto neighbors = topology.neighbors(i);
        for (int a = 0; a < 3; ++a)
        {
            if (neighbors.empty())
            {
                y[3 * i + a] = x[3 * i + a];
                continue;
            }
            Scalar mean = 0;
            for (const Index j : neighbors)
                mean += x[3 * j + a];
            mean /= static_cast<Scalar>(neighbors.size());
            y[3 * i + a] = x[3 * i + a] + factor * (mean - x[3 * i + a]);
        }
    });
}

} // namespace

void bilateral_normal_filter(const Mesh& mesh, const Topology& topology, std::span<Scalar> x,
                             const BilateralSettings& settings)
{
    const Index nf = mesh.face_count(), nv = mesh.vertex_count();
    std::vector<Scalar> normals = face_normals(mesh, x);
    const std::vector<Scalar> centroids = face_centroids(mesh, x);
    std::vector<Scalar> areas(static_cast<size_t>(nf));
    for (Index f = 0; f < nf; ++f)
    {
        const Vec3 n = face_area_vector(mesh, x, f);
        areas[f] = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    Scalar spacing = 0;
    for (Index e = 0; e < topology.dual_edge_count(); ++e)
        spacing += std::sqrt(distance2(&centroids[3 * topology.dual_edge_faces[2 * e]],
                                       &centroids[3 * topology.dual_edge_faces[2 * e + 1]]));
    const Scalar sigma_s =
        topology.dual_edge_count() > 0 ? spacing / topology.dual_edge_count() : 1;
    const Scalar spatial = 1 / (2 * sigma_s * sigma_s);
    const Scalar range = 1 / (2 * settings.sigma_r * settings.sigma_r);

    std::vector<Scalar> next(normals.size());
    for (int it = 0; it < settings.normal_iterations; ++it)
    {
        parallel_for(nf, [&](Index f) {
            const Scalar* n_f = &normals[3 * f];
            const Scalar* cf = &centroids[3 * f];
            const auto weight = [&](Index g) {
                return areas[g] * std::exp(-spatial * distance2(cf, &centroids[3 * g])) *
                       std::exp(-range * distance2(n_f, &normals[3 * g]));
            };
            Scalar sum[3] = {0, 0, 0};
            const auto add = [&](Index g) {
                const Scalar w = weight(g);
                for (int a = 0; a < 3; ++a)
                    sum[a] += w * normals[3 * g + a];
            };
            add(f);
            for (const Index g : topology.face_neighbors_of(f))
                add(g);
            const Scalar length = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
            for (int a = 0; a < 3; ++a)
                next[3 * f + a] = length > 0 ? sum[a] / length : normals[3 * f + a];
        });
        std::swap(normals, next);
    }

    std::vector<Scalar> y(x.begin(), x.end());
    for (int it = 0; it < settings.vertex_iterations; ++it)
    {
        const std::vector<Scalar> c = face_centroids(mesh, x);
        parallel_for(nv, [&](Index i) {
            const auto corners = topology.corners_of_vertex(i);
            if (corners.empty())
                return;
            Scalar move[3] = {0, 0, 0};
            for (const Index corner : corners)
            {
                const Index f = topology.face_of_corner(corner);
                const Scalar* n = &normals[3 * f];
                const Scalar offset = n[0] * (c[3 * f] - x[3 * i]) +
                                      n[1] * (c[3 * f + 1] - x[3 * i + 1]) +
                                      n[2] * (c[3 * f + 2] - x[3 * i + 2]);
                for (int a = 0; a < 3; ++a)
                    move[a] += offset * n[a];
            }
            for (int a = 0; a < 3; ++a)
                y[3 * i + a] = x[3 * i + a] + move[a] / static_cast<Scalar>(corners.size());
        });
        std::copy(y.begin(), y.end(), x.begin());
    }
}

void taubin_smooth(const Topology& topology, std::span<Scalar> x, const TaubinSettings& settings)
{
    std::vector<Scalar> y(x.size());
    for (int pair = 0; pair < settings.pairs; ++pair)
    {
        umbrella_step(topology, x, y, settings.lambda);
        if (settings.mu == 0)
        {
            std::copy(y.begin(), y.end(), x.begin());
            continue;
        }
        umbrella_step(topology, y, x, settings.mu);
    }
}

} // namespace meshfair::bench
