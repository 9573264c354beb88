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
    double best = kGrabRadiusPx * kGrabRadiusPx;
    for (const GrabHandle& h : context.normal_handles())
    {
        const glm::dvec3 w = camera_.project(h.point, view.width, view.height);
        const double d2 = (w.x - at.x) * (w.x - at.x) + (w.y - at.y) * (w.y - at.y);
        if (w.z >= 0 && w.z <= 1 && d2 < best)
        {
            best = d2;
            set_ = h.set;
            direction_ = {h.direction[0], h.direction[1], h.direction[2]};
        }
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
