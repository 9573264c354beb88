// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/aim_normals_tool.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace meshfair::app {

bool AimNormalsTool::press(const ToolContext& context, Modifiers, ScreenPoint at,
                           std::vector<Command>&)
{
    camera_ = *context.view.camera;
    const ViewRect& view = context.view.view;
    set_.clear();
    if (!context.normal_handles)
        return false;
    const std::vector<GrabHandle> handles = context.normal_handles();
    const Grabbed grabbed = nearest_handle(handles, camera_, view, at);
    if (grabbed.handle != nullptr)
    {
        set_ = grabbed.handle->set;
        const Vec3& d = grabbed.handle->direction;
        direction_ = {d[0], d[1], d[2]};
    }
    last_ = pressed_at_ = at;
    return !set_.empty();
}

void AimNormalsTool::move(ScreenPoint to, std::vector<Command>& out)
{
    const double dx = to.x - last_.x, dy = to.y - last_.y;
    const double angle = std::sqrt(dx * dx + dy * dy) / 100.0;
    if (angle == 0)
        return;
    const glm::dvec3 right = camera_.rotation * glm::dvec3(1, 0, 0);
    const glm::dvec3 up = camera_.rotation * glm::dvec3(0, 1, 0);
    const glm::dvec3 axis = glm::normalize(dy * right + dx * up); // screen y points down
    direction_ = glm::normalize(glm::angleAxis(angle, axis) * direction_);
    out.push_back(cmd::SetNormalDirection{set_, {direction_.x, direction_.y, direction_.z}});
    last_ = to;
}

void AimNormalsTool::release(ScreenPoint at, std::vector<Command>& out)
{
    move(at, out);
}

ToolOverlay AimNormalsTool::overlay(ScreenPoint cursor, const ToolSettings&, bool active) const
{
    if (active)
        return {ToolOverlay::Shape::Polyline, {pressed_at_, cursor}, 0};
    return {ToolOverlay::Shape::Circle, {cursor}, kGrabRadiusPx};
}

} // namespace meshfair::app
