// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/selection_tool.h"

#include <array>
#include <utility>

#include "app/render/mesh_draw_data.h"
#include "core/parallel/parallel.h"

namespace meshfair::app {

namespace {

// Face centroids (the mean of the corners) as floats, as the renderer projects them.
std::vector<float> face_centroids(const Mesh& mesh)
{
    std::vector<float> c(3 * static_cast<size_t>(mesh.face_count()));
    parallel_for(mesh.face_count(), [&](Index f) {
        const std::span<const Index> face = mesh.face(f);
        double sum[3] = {0, 0, 0};
        for (const Index v : face)
            for (int k = 0; k < 3; ++k)
                sum[k] += mesh.positions[3 * static_cast<size_t>(v) + k];
        for (int k = 0; k < 3; ++k)
            c[3 * static_cast<size_t>(f) + k] = static_cast<float>(sum[k] / double(face.size()));
    });
    return c;
}

} // namespace

std::vector<ScreenPoint> project_face_centroids(const Mesh& mesh, const Camera& camera, int width,
                                                int height)
{
    return project_points(camera, face_centroids(mesh), width, height);
}

ScreenElements screen_elements(const ToolView& v, const ToolSettings& settings)
{
    ScreenElements out;
    const int width = v.view.width, height = v.view.height;
    if (settings.elements == ElementKind::Vertices && !settings.through)
    {
        if (v.visibility)
        {
            const Visibility& seen = v.visibility();
            out.points = seen.projected;
            out.visible = seen.vertices;
            return out;
        }
        Visibility seen = v.renderer->visibility(*v.camera, v.view);
        out.own_points = std::move(seen.projected);
        out.own_visible = std::move(seen.vertices);
    }
    else if (settings.elements == ElementKind::Vertices)
    {
        std::vector<float> positions(v.mesh->positions.size());
        positions_to_float(v.mesh->positions, positions);
        out.own_points = project_points(*v.camera, positions, width, height);
    }
    else
    {
        if (v.face_points)
            out.points = v.face_points();
        else
            out.own_points = project_face_centroids(*v.mesh, *v.camera, width, height);
        if (!settings.through && v.visibility)
            out.visible = v.visibility().faces;
        else if (!settings.through)
            out.own_visible = std::move(v.renderer->visibility(*v.camera, v.view).faces);
    }
    if (!out.own_points.empty())
        out.points = out.own_points;
    if (!out.own_visible.empty())
        out.visible = out.own_visible;
    return out;
}

} // namespace meshfair::app
