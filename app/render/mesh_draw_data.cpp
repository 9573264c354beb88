// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/mesh_draw_data.h"

#include <cmath>

#include "core/solver/parallel.h"

namespace meshfair::app {

MeshDrawData mesh_draw_data(const Mesh& mesh, const Topology& topology)
{
    MeshDrawData d;
    d.vertex_count = static_cast<std::uint32_t>(mesh.vertex_count());
    d.face_count = static_cast<std::uint32_t>(mesh.face_count());
    const Index nf = mesh.face_count();
    d.triangles.reserve(3 * static_cast<size_t>(mesh.corner_count() - 2 * nf));
    d.triangle_face.reserve(static_cast<size_t>(mesh.corner_count() - 2 * nf));
    for (Index f = 0; f < nf; ++f)
    {
        const std::span<const Index> face = mesh.face(f);
        for (size_t k = 1; k + 1 < face.size(); ++k)
        {
            d.triangles.insert(d.triangles.end(), {static_cast<std::uint32_t>(face[0]),
                                                   static_cast<std::uint32_t>(face[k]),
                                                   static_cast<std::uint32_t>(face[k + 1])});
            d.triangle_face.push_back(static_cast<std::uint32_t>(f));
        }
    }
    for (Index e = 0; e < topology.edge_count(); ++e)
    {
        const Index faces = topology.edge_face_offsets[e + 1] - topology.edge_face_offsets[e];
        const auto i = static_cast<std::uint32_t>(topology.edge_vertices[2 * e]);
        const auto j = static_cast<std::uint32_t>(topology.edge_vertices[2 * e + 1]);
        d.edges.insert(d.edges.end(), {i, j});
        if (faces == 1)
            d.boundary_edges.insert(d.boundary_edges.end(), {i, j});
        else if (faces >= 3)
            d.singular_edges.insert(d.singular_edges.end(), {i, j});
    }
    d.vertex_face_offsets = topology.vertex_corner_offsets;
    d.vertex_faces.resize(topology.vertex_corners.size());
    for (size_t k = 0; k < topology.vertex_corners.size(); ++k)
        d.vertex_faces[k] = topology.face_of_corner(topology.vertex_corners[k]);
    return d;
}

namespace {

// In double precision whatever the coordinates' type.
template <typename Coordinate>
void area_vectors(std::span<const Coordinate> x, const Mesh& mesh, std::span<float> out)
{
    if (mesh.face_vertices.size() == 3 * static_cast<size_t>(mesh.face_count()))
    {
        // Only triangles (scans, mostly): the corners at 3f, 3f + 1, 3f + 2, read directly.
        // The same three products in the same order as the general loop: the same bits.
        const Index* corners = mesh.face_vertices.data();
        parallel_for(mesh.face_count(), [&](Index f) {
            double n[3] = {0, 0, 0};
            const Index* c = corners + 3 * static_cast<size_t>(f);
            for (int k = 0; k < 3; ++k)
            {
                const Coordinate* p = &x[3 * static_cast<size_t>(c[k])];
                const Coordinate* q = &x[3 * static_cast<size_t>(c[k == 2 ? 0 : k + 1])];
                n[0] += (p[1] - q[1]) * (p[2] + q[2]);
                n[1] += (p[2] - q[2]) * (p[0] + q[0]);
                n[2] += (p[0] - q[0]) * (p[1] + q[1]);
            }
            for (int a = 0; a < 3; ++a)
                out[3 * static_cast<size_t>(f) + a] = static_cast<float>(0.5 * n[a]);
        });
        return;
    }
    parallel_for(mesh.face_count(), [&](Index f) {
        const std::span<const Index> face = mesh.face(f);
        double n[3] = {0, 0, 0};
        // Corner k with corner k + 1, the last with the first: no division per corner (this
        // runs for every corner of every frame of live solving).
        const auto add = [&](Index i, Index j) {
            const Coordinate* p = &x[3 * static_cast<size_t>(i)];
            const Coordinate* q = &x[3 * static_cast<size_t>(j)];
            n[0] += (p[1] - q[1]) * (p[2] + q[2]);
            n[1] += (p[2] - q[2]) * (p[0] + q[0]);
            n[2] += (p[0] - q[0]) * (p[1] + q[1]);
        };
        for (size_t k = 0; k + 1 < face.size(); ++k)
            add(face[k], face[k + 1]);
        add(face.back(), face.front());
        for (int a = 0; a < 3; ++a)
            out[3 * static_cast<size_t>(f) + a] = static_cast<float>(0.5 * n[a]);
    });
}

} // namespace

void face_area_vectors(std::span<const Scalar> positions, const Mesh& mesh, std::span<float> out)
{
    area_vectors(positions, mesh, out);
}

void face_area_vectors(std::span<const float> positions, const Mesh& mesh, std::span<float> out)
{
    area_vectors(positions, mesh, out);
}

void vertex_normals(std::span<const Index> offsets, std::span<const Index> faces,
                    std::span<const float> areas, std::span<float> out)
{
    const auto n_vertices = static_cast<Index>(offsets.empty() ? 0 : offsets.size() - 1);
    parallel_for(n_vertices, [&](Index i) {
        float n[3] = {0, 0, 0};
        for (Index k = offsets[i]; k < offsets[i + 1]; ++k)
            for (int a = 0; a < 3; ++a)
                n[a] += areas[3 * static_cast<size_t>(faces[k]) + a];
        const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const float s = len > 0 ? 1 / len : 0;
        for (int a = 0; a < 3; ++a)
            out[3 * static_cast<size_t>(i) + a] = n[a] * s;
    });
}

void positions_to_float(std::span<const Scalar> x, std::span<float> out)
{
    parallel_ranges(static_cast<Index>(x.size()), [&](Index begin, Index end) {
        for (Index k = begin; k < end; ++k)
            out[k] = static_cast<float>(x[k]);
    });
}

} // namespace meshfair::app
