// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/tools/interactive_tool.h"

namespace meshfair::app {

//! \brief The O tool, a sculpt-style brush: a stroke over the surface gives PaintDab
//! commands (the smoothing brush, or painting a set's weight map, as PaintSettings say).
//!
//! Each dab is centred on the visible vertex nearest to the cursor (within the radius), with
//! the screen radius turned into the world at the depth of the first, so that the commands
//! are in the world and a script replays them without the view. The centre is where that
//! vertex was when the stroke began, the shape on which cmd::PaintDab measures its reach:
//! the smoothing brush's runs move the surface while the stroke goes on, as they come from
//! the solver's thread, and the same path must give the same dabs whichever have come. What
//! is visible comes from the ID buffer rendered once, at the press (as the selection brush
//! does): a dab then costs a scan of the visible vertices' screen points, not a render of
//! the mesh. Dabs are a quarter of the radius apart along the cursor's path (a fast stroke
//! leaves no gaps); a press where no visible vertex is within the radius navigates.
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
    //! The visible vertex nearest to `at` within the radius (kInvalidIndex: none).
    Index nearest(ScreenPoint at) const;
    //! A dab at `at` when a visible vertex is there.
    void dab(ScreenPoint at, std::vector<Command>& out);

    ToolView view_;
    std::vector<Index> visible_;         // the vertices the view showed at the press
    std::vector<ScreenPoint> projected_; // where each of them projected
    std::vector<Vec3> places_;           // and where each of them was, in the world
    PaintSettings paint_;
    double radius_px_ = 24;
    double radius_ = 0; // in the world, fixed for the stroke at its first dab
    ScreenPoint last_;  // where the last dab was tried
};

} // namespace meshfair::app
