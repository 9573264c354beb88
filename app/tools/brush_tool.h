// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/tools/selection_tool.h"

namespace meshfair::app {

//! \brief A round brush of a screen radius: it covers the elements within the radius of
//! its path (dabs a quarter radius apart, so a fast stroke leaves no gaps), visible ones
//! only unless "through", each element once per stroke.
//!
//! Why a grid: a stroke is many dabs and a mesh may have millions of elements. At the
//! press the elements that can be covered are bucketed into square cells of the radius's
//! size, once; a dab then reads the few cells under it, so a dab costs what it covers,
//! not the mesh.
class BrushTool final : public SelectionTool
{
public:
    std::vector<Index> press(const ToolView& view, const ToolSettings& settings,
                             ScreenPoint at) override;
    std::vector<Index> drag(ScreenPoint to) override;
    std::vector<Index> release(ScreenPoint at) override;
    ToolOverlay overlay(ScreenPoint cursor) const override;
    //! The radius of the ring drawn when no stroke is under way.
    void set_radius(double radius_px) { radius_ = radius_px; }

private:
    void dab(ScreenPoint c, std::vector<Index>& out);

    double radius_ = 24;
    ScreenElements elements_;
    int columns_ = 0, rows_ = 0;
    double cell_ = 1;
    std::vector<Index> cell_offsets_, cell_points_; // the elements of each cell (CSR)
    std::vector<char> covered_;                     // covered in this stroke
    ScreenPoint last_;
    bool active_ = false;
};

} // namespace meshfair::app
