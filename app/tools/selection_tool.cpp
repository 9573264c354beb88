// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/selection_tool.h"

#include <array>
#include <utility>

#include "app/render/mesh_draw_data.h"
#include "core/solver/parallel.h"

namespace meshfair::app {

namespace {

constexpr std::array<std::pair<ToolKind, std::string_view>, 5> kToolNames = {{
    {ToolKind::Navigate, "navigate"},
    {ToolKind::Click, "click"},
    {ToolKind::Brush, "brush"},
    {ToolKind::Rectangle, "rectangle"},
    {ToolKind::Lasso, "lasso"},
}};

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

std::string_view tool_name(ToolKind tool)
{
    for (const auto& [t, name] : kToolNames)
        if (t == tool)
            return name;
    return {};
}

std::optional<ToolKind> tool_named(std::string_view name)
{
    for (const auto& [t, n] : kToolNames)
        if (n == name)
            return t;
    return std::nullopt;
}

ScreenElements screen_elements(const ToolView& v, const ToolSettings& settings)
{
    ScreenElements out;
    const int width = v.view.width, height = v.view.height;
    if (settings.elements == ElementKind::Vertices)
    {
        if (!settings.through)
        {
            Visibility seen = v.renderer->visibility(*v.camera, v.view);
            out.points = std::move(seen.projected);
            out.visible = std::move(seen.vertices);
            return out;
        }
        std::vector<float> positions(v.mesh->positions.size());
        positions_to_float(v.mesh->positions, positions);
        out.points = project_points(*v.camera, positions, width, height);
        return out;
    }
    out.points = project_points(*v.camera, face_centroids(*v.mesh), width, height);
    if (!settings.through)
        out.visible = std::move(v.renderer->visibility(*v.camera, v.view).faces);
    return out;
}

} // namespace meshfair::app
