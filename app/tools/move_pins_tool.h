// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <string>

#include "app/tools/interactive_tool.h"

namespace meshfair::app {

//! \brief The M tool: a press on a pin (within kGrabRadiusPx of its glyph) grabs its set;
//! the grabbed point then follows the cursor in the plane through it parallel to the view,
//! and each move gives a MovePins command of the set by the point's displacement. A press
//! on nothing navigates.
class MovePinsTool final : public InteractiveTool
{
public:
    bool press(const ToolContext& context, Modifiers mods, ScreenPoint at,
               std::vector<Command>& out) override;
    void move(ScreenPoint to, std::vector<Command>& out) override;
    void release(ScreenPoint at, std::vector<Command>& out) override;
    ToolOverlay overlay(ScreenPoint cursor, const ToolSettings& settings,
                        bool active) const override;
    const char* gesture_name() const override { return "move pins"; }

private:
    Camera camera_;
    ViewRect view_;
    std::string set_;
    double depth_ = 0;     // the grabbed glyph's window depth
    glm::dvec3 from_{0.0}; // the grabbed point, in the world, as moved so far
    ScreenPoint pressed_at_;
    std::optional<SolverSettings> dome_; //!< taken by the gesture's first move
};

} // namespace meshfair::app
