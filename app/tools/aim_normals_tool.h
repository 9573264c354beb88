// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>

#include "app/tools/interactive_tool.h"

namespace meshfair::app {

//! \brief The D tool: a press near the base of one of a normal set's arrows (within
//! kGrabRadiusPx) grabs the set; dragging turns its direction about the view-plane axis
//! across the drag, one radian per 100 pixels, as a trackball turns what is under the
//! mouse. Each move gives a SetNormalDirection command with the new direction. A press on
//! nothing navigates.
class AimNormalsTool final : public InteractiveTool
{
public:
    bool press(const ToolContext& context, Modifiers mods, ScreenPoint at,
               std::vector<Command>& out) override;
    void move(ScreenPoint to, std::vector<Command>& out) override;
    void release(ScreenPoint at, std::vector<Command>& out) override;
    ToolOverlay overlay(ScreenPoint cursor, const ToolSettings& settings,
                        bool active) const override;
    const char* gesture_name() const override { return "normal direction"; }

private:
    Camera camera_;
    std::string set_;
    glm::dvec3 direction_{0, 0, 1};
    ScreenPoint last_, pressed_at_;
};

} // namespace meshfair::app
