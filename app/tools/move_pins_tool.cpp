// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/move_pins_tool.h"

#include <utility>

namespace meshfair::app {

bool MovePinsTool::press(const ToolContext& context, Modifiers, ScreenPoint at,
                         std::vector<Command>&)
{
    camera_ = *context.view.camera;
    view_ = context.view.view;
    set_.clear();
    if (!context.pin_handles)
        return false;
    const std::vector<GrabHandle> handles = context.pin_handles();
    const Grabbed grabbed = nearest_handle(handles, camera_, view_, at);
    if (grabbed.handle == nullptr)
        return false;
    set_ = grabbed.handle->set;
    depth_ = grabbed.depth;
    from_ = camera_.unproject({at.x, at.y, depth_}, view_.width, view_.height);
    pressed_at_ = at;
    // The drag shows the minimizer with the thin plate (a dome, not the membrane's horn):
    // the first move takes the settings, in its undo step.
    dome_ = context.dome;
    return true;
}

void MovePinsTool::move(ScreenPoint to, std::vector<Command>& out)
{
    const glm::dvec3 p = camera_.unproject({to.x, to.y, depth_}, view_.width, view_.height);
    const glm::dvec3 d = p - from_;
    if (d == glm::dvec3(0.0))
        return;
    out.push_back(cmd::MovePins{set_, {d.x, d.y, d.z}, std::exchange(dome_, std::nullopt)});
    from_ = p;
}

void MovePinsTool::release(ScreenPoint at, std::vector<Command>& out)
{
    move(at, out);
}

ToolOverlay MovePinsTool::overlay(ScreenPoint cursor, const ToolSettings&, bool active) const
{
    // The reach of a press, and while dragging the way from where the pins were grabbed.
    if (active)
        return {ToolOverlay::Shape::Polyline, {pressed_at_, cursor}, 0};
    return {ToolOverlay::Shape::Circle, {cursor}, kGrabRadiusPx};
}

} // namespace meshfair::app
