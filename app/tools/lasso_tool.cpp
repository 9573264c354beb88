// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/lasso_tool.h"

namespace meshfair::app {

std::vector<Index> LassoTool::press(const ToolView& view, const ToolSettings& settings,
                                    ScreenPoint at)
{
    elements_ = screen_elements(view, settings);
    curve_ = {at};
    active_ = true;
    return {};
}

std::vector<Index> LassoTool::drag(ScreenPoint to)
{
    // A point per pixel moved at most: a long stroke stays a short polygon.
    const ScreenPoint& last = curve_.back();
    if ((to.x - last.x) * (to.x - last.x) + (to.y - last.y) * (to.y - last.y) >= 1.0)
        curve_.push_back(to);
    return {};
}

std::vector<Index> LassoTool::release(ScreenPoint at)
{
    drag(at);
    active_ = false;
    std::vector<Index> covered = points_in_lasso(elements_.points, curve_, elements_.visible);
    elements_ = {};
    return covered;
}

ToolOverlay LassoTool::overlay(ScreenPoint) const
{
    if (!active_)
        return {};
    return {ToolOverlay::Shape::Polyline, curve_, 0};
}

} // namespace meshfair::app
