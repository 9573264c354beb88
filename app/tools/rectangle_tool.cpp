// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/rectangle_tool.h"

namespace meshfair::app {

std::vector<Index> RectangleTool::press(const ToolView& view, const ToolSettings& settings,
                                        ScreenPoint at)
{
    elements_ = screen_elements(view, settings);
    from_ = to_ = at;
    active_ = true;
    return {};
}

std::vector<Index> RectangleTool::drag(ScreenPoint to)
{
    to_ = to;
    return {};
}

std::vector<Index> RectangleTool::release(ScreenPoint at)
{
    to_ = at;
    active_ = false;
    std::vector<Index> covered =
        points_in_rectangle(elements_.points, {from_.x, from_.y, to_.x, to_.y}, elements_.visible);
    elements_ = {};
    return covered;
}

ToolOverlay RectangleTool::overlay(ScreenPoint) const
{
    if (!active_)
        return {};
    return {ToolOverlay::Shape::Rectangle, {from_, to_}, 0};
}

} // namespace meshfair::app
