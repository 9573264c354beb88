// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/click_tool.h"

#include <limits>

namespace meshfair::app {

std::vector<Index> ClickTool::press(const ToolView& v, const ToolSettings& settings, ScreenPoint at)
{
    const PickResult hit =
        v.renderer->pick(*v.camera, v.view, static_cast<int>(at.x), static_cast<int>(at.y));
    if (!hit.hit)
        return {};
    if (settings.elements == ElementKind::Faces)
        return {hit.face};
    // The nearest corner of the whole polygon, not of the fan triangle the pixel lies in.
    Index best = hit.vertex;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (const Index i : v.mesh->face(hit.face))
    {
        const size_t k = 3 * static_cast<size_t>(i);
        const glm::dvec3 p = v.camera->project(
            {v.mesh->positions[k], v.mesh->positions[k + 1], v.mesh->positions[k + 2]},
            v.view.width, v.view.height);
        const double d2 = (p.x - at.x) * (p.x - at.x) + (p.y - at.y) * (p.y - at.y);
        if (d2 < best_d2)
        {
            best_d2 = d2;
            best = i;
        }
    }
    return {best};
}

} // namespace meshfair::app
