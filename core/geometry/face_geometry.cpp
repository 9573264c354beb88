// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/geometry/face_geometry.h"

#include <algorithm>
#include <cmath>

namespace meshfair {

namespace {

//! Twice Newell's vector: the normal's unnormalized sum, as face_normal has always summed it.
Vec3 newell_sum(const Mesh& mesh, std::span<const Scalar> x, Index f)
{
    const auto face = mesh.face(f);
    Vec3 n{0, 0, 0};
    for (size_t k = 0; k < face.size(); ++k)
    {
        const Scalar* p = &x[3 * face[k]];
        const Scalar* q = &x[3 * face[(k + 1) % face.size()]];
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    return n;
}

} // namespace

Vec3 face_area_vector(const Mesh& mesh, std::span<const Scalar> x, Index f)
{
    const Vec3 n = newell_sum(mesh, x, f);
    return {n[0] / 2, n[1] / 2, n[2] / 2};
}

Vec3 face_normal(const Mesh& mesh, std::span<const Scalar> x, Index f)
{
    const Vec3 n = newell_sum(mesh, x, f);
    const Scalar len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0))
        return {0, 0, 0};
    return {n[0] / len, n[1] / len, n[2] / len};
}

std::vector<Scalar> face_normals(const Mesh& mesh, std::span<const Scalar> x)
{
    std::vector<Scalar> normals(3 * static_cast<size_t>(mesh.face_count()));
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const Vec3 n = face_normal(mesh, x, f);
        std::copy(n.begin(), n.end(), normals.begin() + 3 * f);
    }
    return normals;
}

Scalar mean_edge_length(const Topology& topology, std::span<const Scalar> x)
{
    const Index edges = topology.edge_count();
    if (edges == 0)
        return 0;
    Scalar sum = 0;
    if (!has_parts(topology.parts, TopologyParts::Edges))
    {
        // The same edges from V(i), each once (i < j), for topologies built without the list.
        for (Index i = 0; i < topology.vertex_count; ++i)
            for (const Index j : topology.neighbors(i))
                if (i < j)
                {
                    const Scalar* p = &x[3 * i];
                    const Scalar* q = &x[3 * j];
                    sum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                     (p[2] - q[2]) * (p[2] - q[2]));
                }
        return sum / edges;
    }
    for (Index e = 0; e < edges; ++e)
    {
        const Scalar* p = &x[3 * topology.edge_vertices[2 * e]];
        const Scalar* q = &x[3 * topology.edge_vertices[2 * e + 1]];
        sum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                         (p[2] - q[2]) * (p[2] - q[2]));
    }
    return sum / edges;
}

BoundingBox bounding_box(std::span<const Scalar> x)
{
    BoundingBox box;
    if (x.size() < 3)
        return box;
    box.empty = false;
    // From the first vertex on, without a test per value: the loop streams.
    for (int a = 0; a < 3; ++a)
        box.min[a] = box.max[a] = x[a];
    for (size_t k = 3; k + 2 < x.size(); k += 3)
        for (int a = 0; a < 3; ++a)
        {
            box.min[a] = std::min(box.min[a], x[k + a]);
            box.max[a] = std::max(box.max[a], x[k + a]);
        }
    return box;
}

} // namespace meshfair
