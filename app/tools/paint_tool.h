// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/tools/interactive_tool.h"

namespace meshfair::app {

//! \brief The O tool, a sculpt-style brush: a stroke over the surface gives PaintDab
//! commands (the smoothing brush, or painting a set's weight map, as PaintSettings say).
//!
//! Each dab is where the ID buffer shows the surface under the cursor, with the screen
//! radius turned into the world at that depth, so that the commands are in the world and a
//! script replays them without the view. Dabs are a quarter of the radius apart along the
//! cursor's path (a fast stroke leaves no gaps); a press off the surface navigates.
class PaintTool final : public InteractiveTool
{
public:
    bool press(const ToolContext& context, Modifiers mods, ScreenPoint at,
               std::vector<Command>& out) override;
    void move(ScreenPoint to, std::vector<Command>& out) override;
    void release(ScreenPoint at, std::vector<Command>& out) override;
    ToolOverlay overlay(ScreenPoint cursor, const ToolSettings& settings,
                        bool active) const override;
    const char* gesture_name() const override { return "paint"; }

private:
    //! A dab at `at` when the surface is there.
    void dab(ScreenPoint at, std::vector<Command>& out);

    ToolView view_;
    PaintSettings paint_;
    double radius_px_ = 24;
    double radius_ = 0; // in the world, fixed for the stroke at its first dab
    ScreenPoint last_;  // where the last dab was tried
};

} // namespace meshfair::app
