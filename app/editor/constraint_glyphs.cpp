// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/constraint_glyphs.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/face_geometry.h"

namespace meshfair::app {

namespace {

void add_point(std::vector<float>& out, const Vec3& p)
{
    out.insert(out.end(), {float(p[0]), float(p[1]), float(p[2])});
}

Vec3 position(const Document& d, Index v)
{
    const size_t k = 3 * static_cast<size_t>(v);
    return {d.mesh.positions[k], d.mesh.positions[k + 1], d.mesh.positions[k + 2]};
}

// Every `stride`-th element, so a huge set draws kMaxGlyphsPerSet glyphs.
size_t stride_for(size_t n)
{
    return std::max<size_t>(1, (n + kMaxGlyphsPerSet - 1) / kMaxGlyphsPerSet);
}

// The vertices of every region set (vertices, and the vertices of faces) as flags.
SelectionMask region_vertices(const Document& d)
{
    SelectionMask in(static_cast<size_t>(d.mesh.vertex_count()), 0);
    SelectionMask faces(static_cast<size_t>(d.mesh.face_count()), 0);
    for (const ConstraintSet& s : d.sets)
        if (s.kind == ConstraintKind::Region)
        {
            for (const Index v : s.vertices)
                in[static_cast<size_t>(v)] = 1;
            for (const Index f : s.faces)
                faces[static_cast<size_t>(f)] = 1;
        }
    const SelectionMask of_faces = vertices_of_faces(d.mesh, faces);
    for (size_t i = 0; i < in.size(); ++i)
        in[i] = in[i] || of_faces[i];
    return in;
}

} // namespace

std::vector<NormalArrow> normal_arrows(const Document& d, const ConstraintSet& s, Scalar length)
{
    std::vector<NormalArrow> arrows;
    if (!kind_info(s.kind).normals || s.faces.empty())
        return arrows;
    const Mesh& mesh = d.mesh;
    if (length < 0)
        length = 6 * mean_edge_length(d.topology, mesh.positions);
    const size_t step = std::max<size_t>(1, (s.faces.size() + 23) / 24);
    for (size_t k = 0; k < s.faces.size(); k += step)
    {
        const Vec3 c = face_centroid(mesh, mesh.positions, s.faces[k]);
        const Vec3 n =
            s.normals.empty() ? face_normal(mesh, mesh.positions, s.faces[k]) : s.normals[k];
        arrows.push_back({c, {c[0] + length * n[0], c[1] + length * n[1], c[2] + length * n[2]}});
    }
    return arrows;
}

Vec3 set_mean_normal(const Mesh& mesh, std::span<const Scalar> positions, const ConstraintSet& s)
{
    Vec3 sum{0, 0, 0};
    for (size_t k = 0; k < s.faces.size(); ++k)
    {
        const Vec3 area = face_area_vector(mesh, positions, s.faces[k]);
        const Scalar a = std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]);
        // Each face by its area: its own normal, or its normal now.
        const Vec3 n = s.normals.empty()
                           ? area
                           : Vec3{a * s.normals[k][0], a * s.normals[k][1], a * s.normals[k][2]};
        for (int c = 0; c < 3; ++c)
            sum[c] += n[c];
    }
    const Scalar len = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    if (!(len > 0) || !std::isfinite(len))
        return {0, 0, 1};
    return {sum[0] / len, sum[1] / len, sum[2] / len};
}

RegionBorder region_border(const Document& d)
{
    RegionBorder border;
    if (std::none_of(d.sets.begin(), d.sets.end(),
                     [](const ConstraintSet& s) { return s.kind == ConstraintKind::Region; }))
        return border;
    const SelectionMask in = region_vertices(d);
    SelectionMask on = grow_vertices(d.topology, in);
    for (size_t i = 0; i < in.size(); ++i)
    {
        on[i] = on[i] && !in[i];
        if (on[i])
            border.vertices.push_back(static_cast<Index>(i));
    }
    // The line between the moving part and the ring: in each face with corners on both
    // sides, its crossing edges (in order around it) joined in pairs at their midpoints.
    std::vector<Index> crossing;
    for (Index f = 0; f < d.mesh.face_count(); ++f)
    {
        const std::span<const Index> face = d.mesh.face(f);
        crossing.clear();
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Index a = face[k], b = face[(k + 1) % face.size()];
            if (in[static_cast<size_t>(a)] != in[static_cast<size_t>(b)])
                crossing.insert(crossing.end(), {a, b});
        }
        // (Two crossings in a triangle; a polygon's 4 or more are paired as they come.)
        for (size_t k = 0; k + 4 <= crossing.size(); k += 4)
            border.crossings.insert(border.crossings.end(), crossing.begin() + k,
                                    crossing.begin() + k + 4);
    }
    return border;
}

std::vector<GlyphGroup> constraint_glyphs(const Document& d, const RegionBorder& border,
                                          std::string_view hidden)
{
    std::vector<GlyphGroup> groups;
    const Mesh& mesh = d.mesh;
    const Scalar arrow = 6 * mean_edge_length(d.topology, mesh.positions);
    const ConstraintSet* region_shown = nullptr; // the first region shown gives the ring its colour
    for (const ConstraintSet& s : d.sets)
    {
        if (!s.visible || (!hidden.empty() && s.name == hidden && s.kind != ConstraintKind::Region))
            continue;
        GlyphGroup g;
        g.color = s.color;
        switch (s.kind)
        {
            case ConstraintKind::Region:
                if (region_shown == nullptr)
                    region_shown = &s;
                continue; // drawn once for all regions: the border ring below
            case ConstraintKind::Pin:
            case ConstraintKind::Anchor:
            {
                g.size_px = s.kind == ConstraintKind::Pin ? 10 : 6;
                const size_t step = stride_for(s.vertices.size());
                for (size_t k = 0; k < s.vertices.size(); k += step)
                    add_point(g.points, s.kind == ConstraintKind::Pin && !s.targets.empty()
                                            ? s.targets[k]
                                            : position(d, s.vertices[k]));
                break;
            }
            case ConstraintKind::Centroid:
            {
                const size_t step = stride_for(s.faces.size());
                for (size_t k = 0; k < s.faces.size(); k += step)
                    add_point(g.points, face_centroid(mesh, mesh.positions, s.faces[k]));
                break;
            }
            case ConstraintKind::Normal:
            case ConstraintKind::HardNormal:
            case ConstraintKind::SoftNormal:
            {
                g.shape = GlyphGroup::Shape::Segments;
                g.size_px = 2.0f;
                for (const NormalArrow& a : normal_arrows(d, s, arrow))
                {
                    add_point(g.points, a.base);
                    add_point(g.points, a.tip);
                }
                break;
            }
        }
        groups.push_back(std::move(g));
    }
    if (region_shown != nullptr)
    {
        // The ring that stays put: its vertices and the edges between two of them.
        GlyphGroup ring;
        ring.shape = GlyphGroup::Shape::Segments;
        ring.color = region_shown->color; // as the region's swatch in the list
        ring.size_px = 2.0f;
        const auto midpoint = [&](Index a, Index b) {
            const Vec3 p = position(d, a), q = position(d, b);
            return Vec3{0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])};
        };
        for (size_t k = 0; k + 4 <= border.crossings.size(); k += 4)
        {
            add_point(ring.points, midpoint(border.crossings[k], border.crossings[k + 1]));
            add_point(ring.points, midpoint(border.crossings[k + 2], border.crossings[k + 3]));
        }
        GlyphGroup dots;
        dots.color = ring.color;
        dots.size_px = 4;
        for (const Index v : border.vertices)
            add_point(dots.points, position(d, v));
        groups.push_back(std::move(ring));
        groups.push_back(std::move(dots));
    }
    return groups;
}

} // namespace meshfair::app
