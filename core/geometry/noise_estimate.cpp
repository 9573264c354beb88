// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/geometry/noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/geometry/face_geometry.h"

namespace meshfair {

NoiseEstimate estimate_noise(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                             std::span<const char> counted)
{
    const Index nv = topology.vertex_count;
    std::vector<Scalar> residual;
    Scalar squared_edges = 0;
    Index edges = 0;
    for (Index i = 0; i < nv; ++i)
    {
        if (!counted.empty() && !counted[i])
            continue;
        const std::span<const Index> ring = topology.neighbors(i);
        const Scalar* p = &x[3 * static_cast<size_t>(i)];
        Vec3 mean{0, 0, 0};
        for (const Index j : ring)
        {
            const Scalar* q = &x[3 * static_cast<size_t>(j)];
            for (int a = 0; a < 3; ++a)
                mean[a] += q[a];
            if (i < j || (!counted.empty() && !counted[j]))
            {
                squared_edges += (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                 (p[2] - q[2]) * (p[2] - q[2]);
                ++edges;
            }
        }
        const std::span<const Index> corners = topology.corners_of_vertex(i);
        if (ring.size() < 3 || corners.size() != ring.size())
            continue; // a border, a non-manifold fan or a dangling vertex
        Vec3 normal{0, 0, 0};
        for (const Index c : corners)
        {
            const Vec3 a = face_area_vector(mesh, x, topology.face_of_corner(c));
            for (int k = 0; k < 3; ++k)
                normal[k] += a[k];
        }
        const Scalar length =
            std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        if (!(length > 0))
            continue;
        const Scalar n = static_cast<Scalar>(ring.size());
        Scalar r = 0;
        for (int a = 0; a < 3; ++a)
            r += normal[a] / length * (p[a] - mean[a] / n);
        residual.push_back(std::abs(r) / std::sqrt(1 + 1 / n));
    }
    NoiseEstimate out;
    out.vertices = static_cast<Index>(residual.size());
    if (residual.empty() || edges == 0)
        return out;
    Scalar sum = 0;
    for (const Scalar r : residual)
        sum += r;
    // sqrt(2 / pi): the mean of |z| for a standard normal z.
    out.height = sum / static_cast<Scalar>(residual.size()) / std::sqrt(2 / std::numbers::pi);
    const Scalar mean_squared = squared_edges / static_cast<Scalar>(edges);
    out.edge_length = std::sqrt(
        std::max(mean_squared - 2 * out.height * out.height, Scalar(0.25) * mean_squared));
    out.sigma = out.edge_length > 0 ? out.height / out.edge_length : 0;
    return out;
}

} // namespace meshfair
