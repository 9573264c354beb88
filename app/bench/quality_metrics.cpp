// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/quality_metrics.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>

#include "app/bench/vec3_math.h"
#include "core/energies/volume_constraint.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair::bench {

namespace {

constexpr Scalar kNaN = std::numeric_limits<Scalar>::quiet_NaN();

Vec3 point(std::span<const Scalar> x, Index i)
{
    return {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
}

// Angle between two unit vectors in degrees; atan2 keeps it accurate near 0 (acos would
// turn a rounding error of 1e-16 in the dot product into 1e-6 degrees). 90 when either is
// the zero normal of a degenerate face.
Scalar angle_deg(const Vec3& a, const Vec3& b)
{
    if (dot(a, a) == 0 || dot(b, b) == 0)
        return 90;
    return std::atan2(norm(cross(a, b)), dot(a, b)) * 180 / std::numbers::pi;
}

Scalar segment_distance(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const Scalar length2 = dot(ab, ab);
    const Scalar t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return norm(p - (a + t * ab));
}

} // namespace

Scalar mean_normal_angle_deg(const Mesh& mesh, std::span<const Scalar> x,
                             std::span<const Scalar> clean_x)
{
    const Index nf = mesh.face_count();
    if (nf == 0)
        return 0;
    Scalar sum = 0;
    for (Index f = 0; f < nf; ++f)
        sum += angle_deg(face_normal(mesh, x, f), face_normal(mesh, clean_x, f));
    return sum / nf;
}

Scalar point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    if (norm(cross(ab, ac)) == 0)
        return std::min(
            {segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
    const Scalar d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return norm(ap); // vertex region a
    const Vec3 bp = p - b;
    const Scalar d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return norm(bp); // vertex region b
    const Scalar vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return segment_distance(p, a, b); // edge region ab
    const Vec3 cp = p - c;
    const Scalar d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return norm(cp); // vertex region c
    const Scalar vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return segment_distance(p, a, c); // edge region ac
    const Scalar va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return segment_distance(p, b, c); // edge region bc
    const Scalar denom = 1 / (va + vb + vc);
    const Scalar v = vb * denom, w = vc * denom;
    return norm(p - (a + v * ab + w * ac));
}

SurfaceDistance::SurfaceDistance(const Mesh& mesh, std::span<const Scalar> x)
{
    Scalar size_sum = 0;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const auto face = mesh.face(f);
        for (size_t k = 1; k + 1 < face.size(); ++k)
        {
            triangles_.push_back({point(x, face[0]), point(x, face[k]), point(x, face[k + 1])});
            const auto& t = triangles_.back();
            size_sum += std::max({norm(t[1] - t[0]), norm(t[2] - t[1]), norm(t[0] - t[2])});
        }
    }
    const BoundingBox box = bounding_box(x);
    const Vec3 extent = box.max - box.min;
    diagonal_ = box.diagonal();
    origin_ = box.min;
    // About two triangles wide, and at most 256 cells along an axis.
    const Scalar largest = std::max({extent[0], extent[1], extent[2]});
    cell_ = std::max({2 * size_sum / std::max<size_t>(triangles_.size(), 1), largest / 256,
                      std::numeric_limits<Scalar>::min()});
    for (int a = 0; a < 3; ++a)
        cells_[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / cell_)));

    // Each triangle goes to every cell its bounding box touches (counted, then filled).
    const auto cell_range = [&](const std::array<Vec3, 3>& t, int a) {
        const Scalar lo = std::min({t[0][a], t[1][a], t[2][a]}) - origin_[a];
        const Scalar hi = std::max({t[0][a], t[1][a], t[2][a]}) - origin_[a];
        return std::array<int, 2>{std::clamp(static_cast<int>(lo / cell_), 0, cells_[a] - 1),
                                  std::clamp(static_cast<int>(hi / cell_), 0, cells_[a] - 1)};
    };
    const size_t cell_count = static_cast<size_t>(cells_[0]) * cells_[1] * cells_[2];
    cell_offsets_.assign(cell_count + 1, 0);
    for (int pass = 0; pass < 2; ++pass)
    {
        std::vector<Index> fill;
        if (pass == 1)
        {
            for (size_t c = 0; c < cell_count; ++c)
                cell_offsets_[c + 1] += cell_offsets_[c];
            cell_triangles_.resize(static_cast<size_t>(cell_offsets_.back()));
            fill.assign(cell_offsets_.begin(), cell_offsets_.end() - 1);
        }
        for (size_t t = 0; t < triangles_.size(); ++t)
        {
            const auto rx = cell_range(triangles_[t], 0), ry = cell_range(triangles_[t], 1),
                       rz = cell_range(triangles_[t], 2);
            for (int i = rx[0]; i <= rx[1]; ++i)
                for (int j = ry[0]; j <= ry[1]; ++j)
                    for (int k = rz[0]; k <= rz[1]; ++k)
                    {
                        const size_t c = (static_cast<size_t>(i) * cells_[1] + j) * cells_[2] + k;
                        if (pass == 0)
                            ++cell_offsets_[c + 1];
                        else
                            cell_triangles_[fill[c]++] = static_cast<Index>(t);
                    }
        }
    }
}

Scalar SurfaceDistance::distance(const Vec3& p) const
{
    std::array<int, 3> home;
    for (int a = 0; a < 3; ++a)
        home[a] =
            std::clamp(static_cast<int>(std::floor((p[a] - origin_[a]) / cell_)), 0, cells_[a] - 1);
    const int rings = std::max({cells_[0], cells_[1], cells_[2]});
    Scalar best = std::numeric_limits<Scalar>::infinity();
    for (int r = 0; r <= rings; ++r)
    {
        // The cells at Chebyshev distance r from the home cell.
        for (int i = std::max(0, home[0] - r); i <= std::min(cells_[0] - 1, home[0] + r); ++i)
            for (int j = std::max(0, home[1] - r); j <= std::min(cells_[1] - 1, home[1] + r); ++j)
                for (int k = std::max(0, home[2] - r); k <= std::min(cells_[2] - 1, home[2] + r);
                     ++k)
                {
                    if (std::max({std::abs(i - home[0]), std::abs(j - home[1]),
                                  std::abs(k - home[2])}) != r)
                        continue;
                    const size_t c = (static_cast<size_t>(i) * cells_[1] + j) * cells_[2] + k;
                    for (Index n = cell_offsets_[c]; n < cell_offsets_[c + 1]; ++n)
                    {
                        const auto& t = triangles_[cell_triangles_[n]];
                        best = std::min(best, point_triangle_distance(p, t[0], t[1], t[2]));
                    }
                }
        // Every cell further out is at least r cells away along some axis from the home cell,
        // which holds p (or, p outside the grid, is the grid's cell nearest to it).
        if (best <= r * cell_)
            break;
    }
    return best;
}

Scalar mean_relative_distance(const SurfaceDistance& clean, std::span<const Scalar> x)
{
    const Index nv = static_cast<Index>(x.size() / 3);
    if (nv == 0 || !(clean.diagonal() > 0))
        return 0;
    // Per vertex in parallel, summed in order: the same bits for any thread count.
    std::vector<Scalar> distance(static_cast<size_t>(nv));
    parallel_for(nv, [&](Index i) { distance[i] = clean.distance(point(x, i)); });
    Scalar sum = 0;
    for (const Scalar d : distance)
        sum += d;
    return sum / nv / clean.diagonal();
}

Scalar signed_volume(const Mesh& mesh, std::span<const Scalar> x)
{
    // About the box centre: the terms stay small, so rounding does too.
    const BoundingBox box = bounding_box(x);
    const Vec3 o{(box.min[0] + box.max[0]) / 2, (box.min[1] + box.max[1]) / 2,
                 (box.min[2] + box.max[2]) / 2};
    Scalar six_volume = 0;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const auto face = mesh.face(f);
        const Vec3 a = point(x, face[0]) - o;
        for (size_t k = 1; k + 1 < face.size(); ++k)
            six_volume += dot(a, cross(point(x, face[k]) - o, point(x, face[k + 1]) - o));
    }
    return six_volume / 6;
}

Scalar capped_volume(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x)
{
    const VolumeConstraint volumes(mesh, topology, x,
                                   std::vector<char>(static_cast<size_t>(mesh.vertex_count()), 0));
    Scalar sum = 0;
    for (const Scalar v : volumes.target_volumes())
        sum += v;
    return sum;
}

Index turned_over_faces(const Mesh& mesh, std::span<const Scalar> x, std::span<const Scalar> before)
{
    const Index nf = mesh.face_count();
    std::vector<Vec3> own(static_cast<size_t>(nf));
    for (Index f = 0; f < nf; ++f)
        own[f] = face_area_vector(mesh, before, f);
    std::vector<std::vector<Index>> faces_at(static_cast<size_t>(mesh.vertex_count()));
    for (Index f = 0; f < nf; ++f)
        for (const Index v : mesh.face(f))
            faces_at[v].push_back(f);
    Index count = 0;
    for (Index f = 0; f < nf; ++f)
    {
        Vec3 around{0, 0, 0};
        for (const Index v : mesh.face(f))
            for (const Index g : faces_at[v])
                around = around + own[g];
        const bool lies_in_surface =
            dot(own[f], around) > 0.5 * std::sqrt(dot(own[f], own[f]) * dot(around, around));
        if (lies_in_surface && dot(own[f], face_area_vector(mesh, x, f)) <= 0)
            ++count;
    }
    return count;
}

Scalar volume_change_percent(const Mesh& mesh, std::span<const Scalar> x,
                             std::span<const Scalar> clean_x)
{
    const Scalar clean = signed_volume(mesh, clean_x);
    return 100 * (signed_volume(mesh, x) - clean) / clean;
}

std::vector<Scalar> dihedral_angles_deg(const Mesh& mesh, const Topology& topology,
                                        std::span<const Scalar> x)
{
    const std::vector<Scalar> normals = face_normals(mesh, x);
    std::vector<Scalar> angles(static_cast<size_t>(topology.edge_count()), kNaN);
    for (Index e = 0; e < topology.edge_count(); ++e)
    {
        const auto faces = topology.faces_of_edge(e);
        if (faces.size() == 2)
            angles[e] = angle_deg(point(normals, faces[0]), point(normals, faces[1]));
    }
    return angles;
}

Scalar percentile(std::vector<Scalar> values, Scalar p)
{
    if (values.empty())
        return kNaN;
    std::sort(values.begin(), values.end());
    const auto rank = static_cast<size_t>(std::ceil(p / 100 * static_cast<Scalar>(values.size())));
    return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

SeamFigure seam_figure(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                       std::span<const Index> region_vertices)
{
    const Index nv = mesh.vertex_count();
    std::vector<char> inside(static_cast<size_t>(nv), 0);
    for (const Index v : region_vertices)
        inside[v] = 1;
    // Distance to the border ring by breadth-first search, needed up to 3 (">2").
    constexpr int kFar = 3;
    std::vector<int> distance(static_cast<size_t>(nv), kFar);
    std::deque<Index> queue;
    for (Index v = 0; v < nv; ++v)
        if (inside[v])
            for (const Index w : topology.neighbors(v))
                if (!inside[w])
                {
                    distance[v] = 0;
                    queue.push_back(v);
                    break;
                }
    while (!queue.empty())
    {
        const Index v = queue.front();
        queue.pop_front();
        if (distance[v] + 1 >= kFar)
            continue;
        for (const Index w : topology.neighbors(v))
            if (distance[w] > distance[v] + 1)
            {
                distance[w] = distance[v] + 1;
                queue.push_back(w);
            }
    }
    const std::vector<Scalar> angles = dihedral_angles_deg(mesh, topology, x);
    std::vector<Scalar> border, inner_border, interior;
    for (Index e = 0; e < topology.edge_count(); ++e)
    {
        if (std::isnan(angles[e]))
            continue;
        const Index a = topology.edge_vertices[2 * e], b = topology.edge_vertices[2 * e + 1];
        if (distance[a] <= 2 || distance[b] <= 2)
        {
            border.push_back(angles[e]);
            if (inside[a] && inside[b])
                inner_border.push_back(angles[e]);
        }
        else if (inside[a] && inside[b])
            interior.push_back(angles[e]);
    }
    SeamFigure figure;
    figure.border_p95_deg = percentile(border, 95);
    figure.inner_border_p95_deg = percentile(inner_border, 95);
    figure.interior_p95_deg = percentile(interior, 95);
    figure.border_edges = static_cast<Index>(border.size());
    figure.inner_border_edges = static_cast<Index>(inner_border.size());
    figure.interior_edges = static_cast<Index>(interior.size());
    return figure;
}

} // namespace meshfair::bench
