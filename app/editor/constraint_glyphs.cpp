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
    for (Index e = 0; e < d.topology.edge_count(); ++e)
    {
        const Index a = d.topology.edge_vertices[2 * static_cast<size_t>(e)];
        const Index b = d.topology.edge_vertices[2 * static_cast<size_t>(e) + 1];
        if (on[static_cast<size_t>(a)] && on[static_cast<size_t>(b)])
            border.edges.insert(border.edges.end(), {a, b});
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
                // A few long arrows show a direction better than one per face.
                g.shape = GlyphGroup::Shape::Segments;
                g.size_px = 2.0f;
                const size_t step = std::max<size_t>(1, (s.faces.size() + 23) / 24);
                for (size_t k = 0; k < s.faces.size(); k += step)
                {
                    const Vec3 c = face_centroid(mesh, mesh.positions, s.faces[k]);
                    const Vec3 n = s.normals.empty() ? face_normal(mesh, mesh.positions, s.faces[k])
                                                     : s.normals[k];
                    add_point(g.points, c);
                    add_point(g.points,
                              {c[0] + arrow * n[0], c[1] + arrow * n[1], c[2] + arrow * n[2]});
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
        for (const Index v : border.edges)
            add_point(ring.points, position(d, v));
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
