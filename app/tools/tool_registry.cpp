// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/tool_registry.h"

#include <algorithm>

#include "app/tools/aim_normals_tool.h"
#include "app/tools/brush_tool.h"
#include "app/tools/click_tool.h"
#include "app/tools/lasso_tool.h"
#include "app/tools/move_pins_tool.h"
#include "app/tools/paint_tool.h"
#include "app/tools/rectangle_tool.h"
#include "app/tools/selection_gesture.h"

namespace meshfair::app {

static_assert(static_cast<int>(ToolKind::Paint) + 1 == kToolKinds);

ToolRegistry::ToolRegistry()
{
    const auto slot = [&](ToolKind kind) -> std::unique_ptr<InteractiveTool>& {
        return tools_[static_cast<size_t>(kind)];
    };
    slot(ToolKind::Click) =
        std::make_unique<SelectionGesture>(ToolKind::Click, std::make_unique<ClickTool>());
    slot(ToolKind::Brush) =
        std::make_unique<SelectionGesture>(ToolKind::Brush, std::make_unique<BrushTool>());
    slot(ToolKind::Rectangle) =
        std::make_unique<SelectionGesture>(ToolKind::Rectangle, std::make_unique<RectangleTool>());
    slot(ToolKind::Lasso) =
        std::make_unique<SelectionGesture>(ToolKind::Lasso, std::make_unique<LassoTool>());
    slot(ToolKind::MovePins) = std::make_unique<MovePinsTool>();
    slot(ToolKind::AimNormals) = std::make_unique<AimNormalsTool>();
    slot(ToolKind::Paint) = std::make_unique<PaintTool>();
}

Grabbed nearest_handle(std::span<const GrabHandle> handles, const Camera& camera,
                       const ViewRect& view, ScreenPoint at)
{
    Grabbed grabbed;
    double best = kGrabRadiusPx * kGrabRadiusPx;
    for (const GrabHandle& h : handles)
    {
        const glm::dvec3 a = camera.project(h.point, view.width, view.height);
        // The nearest point of the arrow's drawn segment (of the point itself for a pin).
        glm::dvec3 w = a;
        if (h.tip)
        {
            const glm::dvec3 b = camera.project(*h.tip, view.width, view.height);
            const glm::dvec2 ab(b.x - a.x, b.y - a.y), ap(at.x - a.x, at.y - a.y);
            const double len2 = glm::dot(ab, ab);
            const double t = len2 > 0 ? std::clamp(glm::dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
            if (b.z >= 0 && b.z <= 1)
                w = a + t * (b - a);
        }
        const double d2 = (w.x - at.x) * (w.x - at.x) + (w.y - at.y) * (w.y - at.y);
        if (w.z >= 0 && w.z <= 1 && d2 < best)
        {
            best = d2;
            grabbed = {&h, w.z};
        }
    }
    return grabbed;
}

InteractiveTool* ToolRegistry::find(ToolKind kind) const
{
    const auto k = static_cast<size_t>(kind);
    return k < tools_.size() ? tools_[k].get() : nullptr;
}

} // namespace meshfair::app
