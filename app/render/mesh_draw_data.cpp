// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/mesh_draw_data.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "core/parallel/parallel.h"

namespace meshfair::app {

MeshDrawData mesh_draw_data(const Mesh& mesh, const Topology& topology)
{
    MeshDrawData d;
    d.vertex_count = static_cast<std::uint32_t>(mesh.vertex_count());
    d.face_count = static_cast<std::uint32_t>(mesh.face_count());
    const Index nf = mesh.face_count();
    d.triangles.reserve(3 * static_cast<size_t>(mesh.corner_count() - 2 * nf));
    d.triangle_face.reserve(static_cast<size_t>(mesh.corner_count() - 2 * nf));
    d.triangle_edges.reserve(static_cast<size_t>(mesh.corner_count() - 2 * nf));
    for (Index f = 0; f < nf; ++f)
    {
        const std::span<const Index> face = mesh.face(f);
        for (size_t k = 1; k + 1 < face.size(); ++k)
        {
            d.triangles.insert(d.triangles.end(), {static_cast<std::uint32_t>(face[0]),
                                                   static_cast<std::uint32_t>(face[k]),
                                                   static_cast<std::uint32_t>(face[k + 1])});
            d.triangle_face.push_back(static_cast<std::uint32_t>(f));
            // (c0, ck) is the polygon's first edge for k = 1, (ck, ck+1) always one of its
            // edges, (ck+1, c0) its last for the last triangle; the others are diagonals.
            d.triangle_edges.push_back(
                static_cast<std::uint8_t>((k == 1 ? 1 : 0) | 2 | (k + 2 == face.size() ? 4 : 0)));
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

//! f(i) for every index i of the ranges, split over the threads as parallel_ranges splits
//! [0, count): each i is its own element (the rule of parallel_for).
template <class F>
void for_each_in(const IndexRanges& r, F&& f)
{
    parallel_ranges(r.count(), [&](Index first, Index last) {
        if (first >= last)
            return;
        // The range holding the first'th index.
        size_t k = static_cast<size_t>(std::upper_bound(r.before.begin(), r.before.end(), first) -
                                       r.before.begin()) -
                   1;
        Index i = r.begin[k] + (first - r.before[k]);
        // Range by range: each a counted loop of its own.
        for (Index left = last - first; left > 0; i = r.begin[++k])
        {
            const Index stop = std::min(r.end[k], i + left);
            left -= stop - i;
            for (; i < stop; ++i)
                f(i);
            if (left == 0)
                break;
        }
    });
}

//! One range of all n indices.
IndexRanges all_of(Index n)
{
    IndexRanges r;
    if (n > 0)
        r = {{0}, {n}, {0}};
    return r;
}

//! Face f's area vector (Newell), in double precision whatever the coordinates' type: corner
//! k with corner k + 1, the last with the first (no division per corner: this runs for
//! every corner of every frame of live solving).
template <typename Coordinate>
inline void area_vector(const Coordinate* x, const Index* corners, Index size, float* out)
{
    double n[3] = {0, 0, 0};
    for (Index k = 0; k < size; ++k)
    {
        const Coordinate* p = &x[3 * static_cast<size_t>(corners[k])];
        const Coordinate* q = &x[3 * static_cast<size_t>(corners[k + 1 == size ? 0 : k + 1])];
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    for (int a = 0; a < 3; ++a)
        out[a] = static_cast<float>(0.5 * n[a]);
}

template <typename Coordinate>
void area_vectors(std::span<const Coordinate> x, const Mesh& mesh, const IndexRanges& faces,
                  std::span<float> out)
{
    const Index* corners = mesh.face_vertices.data();
    if (mesh.face_vertices.size() == 3 * static_cast<size_t>(mesh.face_count()))
    {
        // Only triangles (scans, mostly): the corners at 3f, 3f + 1, 3f + 2, read directly
        // (the same products in the same order as for any polygon: the same bits).
        for_each_in(faces, [&](Index f) {
            const size_t at = 3 * static_cast<size_t>(f);
            area_vector(x.data(), corners + at, 3, &out[at]);
        });
        return;
    }
    const Index* offsets = mesh.face_offsets.data();
    for_each_in(faces, [&](Index f) {
        area_vector(x.data(), corners + offsets[f], offsets[f + 1] - offsets[f],
                    &out[3 * static_cast<size_t>(f)]);
    });
}

void normals_of(std::span<const Index> offsets, std::span<const Index> faces,
                std::span<const float> areas, const IndexRanges& vertices, std::span<float> out)
{
    for_each_in(vertices, [&](Index i) {
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

void floats_of(std::span<const Scalar> x, const IndexRanges& vertices, std::span<float> out)
{
    for_each_in(vertices, [&](Index i) {
        for (size_t a = 3 * static_cast<size_t>(i); a < 3 * static_cast<size_t>(i) + 3; ++a)
            out[a] = static_cast<float>(x[a]);
    });
}

//! The runs of set flags as ranges: runs less than `gap` apart merged, with the gap
//! growing until there are at most kMaxRanges.
IndexRanges ranges_of(const std::vector<char>& flags)
{
    constexpr size_t kMaxRanges = 256;
    IndexRanges r;
    const auto n = static_cast<Index>(flags.size());
    const char* data = flags.data();
    for (Index i = 0; i < n;)
    {
        if (!data[i])
        {
            // The next set flag, a word at a time over unset ones.
            const void* set = std::memchr(data + i, 1, static_cast<size_t>(n - i));
            i = set == nullptr ? n : static_cast<Index>(static_cast<const char*>(set) - data);
            continue;
        }
        Index j = i;
        while (j < n && data[j])
            ++j;
        r.begin.push_back(i);
        r.end.push_back(j);
        i = j;
    }
    for (Index gap = 32; !r.begin.empty(); gap *= 4)
    {
        size_t kept = 0;
        for (size_t k = 1; k < r.begin.size(); ++k)
            if (r.begin[k] - r.end[kept] < gap)
                r.end[kept] = r.end[k];
            else
            {
                ++kept;
                r.begin[kept] = r.begin[k];
                r.end[kept] = r.end[k];
            }
        r.begin.resize(kept + 1);
        r.end.resize(kept + 1);
        if (r.begin.size() <= kMaxRanges)
            break;
    }
    r.before.resize(r.begin.size());
    Index count = 0;
    for (size_t k = 0; k < r.begin.size(); ++k)
    {
        r.before[k] = count;
        count += r.end[k] - r.begin[k];
    }
    return r;
}

} // namespace

void face_area_vectors(std::span<const Scalar> positions, const Mesh& mesh, std::span<float> out)
{
    area_vectors(positions, mesh, all_of(mesh.face_count()), out);
}

void face_area_vectors(std::span<const float> positions, const Mesh& mesh, std::span<float> out)
{
    area_vectors(positions, mesh, all_of(mesh.face_count()), out);
}

void vertex_normals(std::span<const Index> offsets, std::span<const Index> faces,
                    std::span<const float> areas, std::span<float> out)
{
    normals_of(offsets, faces, areas,
               all_of(static_cast<Index>(offsets.empty() ? 0 : offsets.size() - 1)), out);
}

void positions_to_float(std::span<const Scalar> x, std::span<float> out)
{
    parallel_ranges(static_cast<Index>(x.size()), [&](Index begin, Index end) {
        for (Index k = begin; k < end; ++k)
            out[k] = static_cast<float>(x[k]);
    });
}

ChangingPart changing_part(const Mesh& mesh, std::span<const Index> vertex_face_offsets,
                           std::span<const Index> vertex_faces,
                           std::span<const Index> free_vertices)
{
    // The vertex count from the faces around each vertex: a solver run's mesh has lent
    // its positions to the session.
    const size_t nv = vertex_face_offsets.empty() ? 0 : vertex_face_offsets.size() - 1;
    std::vector<char> faces(static_cast<size_t>(mesh.face_count()), 0);
    std::vector<char> vertices(nv, 0);
    for (const Index v : free_vertices)
        vertices[v] = 1;
    // A small region (a brush's dab restarts the run) lists the faces as it meets them
    // and costs its own size; a large one marks them and passes over every face once.
    const bool small = free_vertices.size() < nv / 8;
    std::vector<Index> met;
    for (const Index v : free_vertices)
        for (Index k = vertex_face_offsets[v]; k < vertex_face_offsets[v + 1]; ++k)
        {
            const Index f = vertex_faces[k];
            if (small && !faces[f])
                met.push_back(f);
            faces[f] = 1;
        }
    const auto mark_corners = [&](Index f) {
        for (const Index v : mesh.face(f))
            vertices[v] = 1;
    };
    if (small)
        std::ranges::for_each(met, mark_corners);
    else
        for (Index f = 0; f < mesh.face_count(); ++f)
            if (faces[f])
                mark_corners(f);
    return {ranges_of(vertices), ranges_of(faces)};
}

std::uint64_t new_display_run()
{
    static std::atomic<std::uint64_t> runs{0};
    return ++runs;
}

void update_display_geometry(std::span<const Scalar> x, const Mesh& mesh,
                             std::span<const Index> vertex_face_offsets,
                             std::span<const Index> vertex_faces, std::uint64_t run,
                             std::shared_ptr<const ChangingPart> changing, DisplayGeometry& g)
{
    const size_t face_values = 3 * static_cast<size_t>(mesh.face_count());
    // A part that is every vertex (plain smoothing of the whole mesh) takes the whole
    // computation's loops.
    const bool part =
        changing != nullptr && static_cast<size_t>(changing->vertices.count()) < x.size() / 3;
    if (run != 0 && g.run == run && part && g.positions.size() == x.size() &&
        g.normals.size() == x.size() && g.face_areas.size() == face_values)
    {
        floats_of(x, changing->vertices, g.positions);
        area_vectors(x, mesh, changing->faces, g.face_areas);
        normals_of(vertex_face_offsets, vertex_faces, g.face_areas, changing->vertices, g.normals);
    }
    else
    {
        g.positions.resize(x.size());
        g.normals.resize(x.size());
        g.face_areas.resize(face_values);
        positions_to_float(x, g.positions);
        face_area_vectors(x, mesh, g.face_areas);
        vertex_normals(vertex_face_offsets, vertex_faces, g.face_areas, g.normals);
    }
    g.run = run;
    g.changing = std::move(changing);
}

} // namespace meshfair::app
