// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/mesh_generator.h"

#include <random>
#include <stdexcept>
#include <string>

#include "core/topology/topology.h"

namespace meshfair::bench {

namespace {

std::int64_t subdivided_vertex_count(const Mesh& mesh, std::int64_t edges, int k)
{
    return mesh.vertex_count() + (k - 1) * edges +
           std::int64_t{k - 1} * (k - 2) / 2 * mesh.face_count();
}

} // namespace

Mesh subdivide_triangles(const Mesh& mesh, int k)
{
    if (k < 1)
        throw std::invalid_argument("subdivide_triangles: k must be at least 1");
    for (Index f = 0; f < mesh.face_count(); ++f)
        if (mesh.face_size(f) != 3)
            throw std::invalid_argument("subdivide_triangles: face " + std::to_string(f) +
                                        " is not a triangle");
    const Topology topology = build_topology(mesh);
    const Index nv = mesh.vertex_count();
    const Index ne = topology.edge_count();
    const Index nf = mesh.face_count();
    const std::int64_t total = subdivided_vertex_count(mesh, ne, k);
    if (total > kMaxVertices || std::int64_t{k} * k * nf > kMaxElements)
        throw std::invalid_argument("subdivide_triangles: the result would be too large");

    Mesh out;
    out.positions.reserve(static_cast<size_t>(3 * total));
    out.positions = mesh.positions;
    const Index edge_base = nv;
    const Index face_base = nv + (k - 1) * ne;
    const auto lerp = [&](Index a, Index b, Scalar t) {
        for (int c = 0; c < 3; ++c)
            out.positions.push_back((1 - t) * mesh.positions[3 * a + c] +
                                    t * mesh.positions[3 * b + c]);
    };
    for (Index e = 0; e < ne; ++e)
        for (int s = 1; s < k; ++s)
            lerp(topology.edge_vertices[2 * e], topology.edge_vertices[2 * e + 1], Scalar(s) / k);

    // Local numbering of a face's interior grid points (i, j), i, j >= 1, i + j <= k - 1.
    std::vector<Index> interior(static_cast<size_t>(k + 1) * (k + 1), kInvalidIndex);
    Index interior_count = 0;
    for (int j = 1; j <= k - 2; ++j)
        for (int i = 1; i + j <= k - 1; ++i)
            interior[static_cast<size_t>(j) * (k + 1) + i] = interior_count++;

    out.face_offsets.reserve(static_cast<size_t>(k) * k * nf + 1);
    out.face_vertices.reserve(3 * static_cast<size_t>(k) * k * nf);
    std::vector<Index> grid(static_cast<size_t>(k + 1) * (k + 1), kInvalidIndex);
    for (Index f = 0; f < nf; ++f)
    {
        const Index corner = mesh.face_offsets[f];
        const Index a = mesh.face_vertices[corner], b = mesh.face_vertices[corner + 1],
                    c = mesh.face_vertices[corner + 2];
        // Point P(i, j) = a + i/k (b - a) + j/k (c - a) lies on the edge `from`-`to` at
        // s/k from `from` when it is on the boundary of the face.
        const auto on_edge = [&](Index edge_corner, Index from, int s) {
            const Index e = topology.corner_edge[edge_corner];
            const bool forward = topology.edge_vertices[2 * e] == from;
            return edge_base + e * (k - 1) + (forward ? s : k - s) - 1;
        };
        const auto at = [&](int i, int j) -> Index& {
            return grid[static_cast<size_t>(j) * (k + 1) + i];
        };
        at(0, 0) = a;
        at(k, 0) = b;
        at(0, k) = c;
        for (int s = 1; s < k; ++s)
        {
            at(s, 0) = on_edge(corner, a, s);         // a -> b
            at(k - s, s) = on_edge(corner + 1, b, s); // b -> c
            at(0, k - s) = on_edge(corner + 2, c, s); // c -> a
        }
        for (int j = 1; j <= k - 2; ++j)
            for (int i = 1; i + j <= k - 1; ++i)
            {
                at(i, j) =
                    face_base + f * interior_count + interior[static_cast<size_t>(j) * (k + 1) + i];
                const Scalar u = Scalar(i) / k, v = Scalar(j) / k;
                for (int d = 0; d < 3; ++d)
                    out.positions.push_back(
                        mesh.positions[3 * a + d] +
                        u * (mesh.positions[3 * b + d] - mesh.positions[3 * a + d]) +
                        v * (mesh.positions[3 * c + d] - mesh.positions[3 * a + d]));
            }
        for (int j = 0; j < k; ++j)
            for (int i = 0; i + j < k; ++i)
            {
                const Index up[3] = {at(i, j), at(i + 1, j), at(i, j + 1)};
                out.add_face(up);
                if (i + j < k - 1)
                {
                    const Index down[3] = {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
                    out.add_face(down);
                }
            }
    }
    return out;
}

int subdivision_factor_for(const Mesh& mesh, std::int64_t min_vertices)
{
    const std::int64_t edges = build_topology(mesh).edge_count();
    int k = 1;
    while (subdivided_vertex_count(mesh, edges, k) < min_vertices)
        ++k;
    return k;
}

std::vector<Index> random_order(Index n, std::uint64_t seed)
{
    std::vector<Index> order(static_cast<size_t>(n));
    for (Index k = 0; k < n; ++k)
        order[static_cast<size_t>(k)] = k;
    std::mt19937_64 random(seed);
    // Fisher-Yates with an explicit bounded draw: std::shuffle's and
    // std::uniform_int_distribution's algorithms differ between standard libraries.
    for (Index k = n - 1; k > 0; --k)
    {
        const std::uint64_t range = static_cast<std::uint64_t>(k) + 1;
        const std::uint64_t limit = UINT64_MAX - UINT64_MAX % range;
        std::uint64_t draw = random();
        while (draw >= limit)
            draw = random();
        std::swap(order[static_cast<size_t>(k)], order[static_cast<size_t>(draw % range)]);
    }
    return order;
}

} // namespace meshfair::bench
