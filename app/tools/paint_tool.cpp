// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/paint_tool.h"

#include <algorithm>
#include <cmath>

namespace meshfair::app {

bool PaintTool::press(const ToolContext& context, Modifiers, ScreenPoint at,
                      std::vector<Command>& out)
{
    view_ = context.view;
    paint_ = context.settings.paint;
    if (paint_.set.empty())
        paint_.set = std::string(kPaintSet);
    radius_px_ = context.settings.brush_radius_px;
    if (view_.renderer == nullptr || view_.camera == nullptr)
        return false;
    const PickResult hit =
        view_.renderer->pick(*view_.camera, view_.view, static_cast<int>(std::floor(at.x)),
                             static_cast<int>(std::floor(at.y)));
    if (!hit.hit)
        return false;
    // The screen radius at the depth of the surface under the cursor, in the world.
    const Camera& camera = *view_.camera;
    const int w = view_.view.width, h = view_.view.height;
    const glm::dvec3 window = camera.project(hit.point, w, h);
    const glm::dvec3 edge = camera.unproject({window.x + radius_px_, window.y, window.z}, w, h);
    radius_ = glm::length(edge - hit.point);
    if (!(radius_ > 0) || !std::isfinite(radius_))
        return false;
    out.push_back(cmd::PaintDab{paint_.set,
                                paint_.mode,
                                {hit.point.x, hit.point.y, hit.point.z},
                                radius_,
                                paint_.strength,
                                paint_.curve,
                                paint_.steps});
    last_ = at;
    return true;
}

void PaintTool::dab(ScreenPoint at, std::vector<Command>& out)
{
    const PickResult hit =
        view_.renderer->pick(*view_.camera, view_.view, static_cast<int>(std::floor(at.x)),
                             static_cast<int>(std::floor(at.y)));
    if (!hit.hit)
        return;
    out.push_back(cmd::PaintDab{paint_.set,
                                paint_.mode,
                                {hit.point.x, hit.point.y, hit.point.z},
                                radius_,
                                paint_.strength,
                                paint_.curve,
                                paint_.steps});
}

void PaintTool::move(ScreenPoint to, std::vector<Command>& out)
{
    const double spacing = std::max(1.0, radius_px_ / 4);
    double dx = to.x - last_.x, dy = to.y - last_.y;
    double length = std::sqrt(dx * dx + dy * dy);
    while (length >= spacing)
    {
        last_ = {last_.x + dx / length * spacing, last_.y + dy / length * spacing, 0};
        dab(last_, out);
        dx = to.x - last_.x;
        dy = to.y - last_.y;
        length = std::sqrt(dx * dx + dy * dy);
    }
}

void PaintTool::release(ScreenPoint at, std::vector<Command>& out)
{
    move(at, out);
}

ToolOverlay PaintTool::overlay(ScreenPoint cursor, const ToolSettings& settings, bool) const
{
    return {ToolOverlay::Shape::Circle, {cursor}, settings.brush_radius_px};
}

} // namespace meshfair::app
