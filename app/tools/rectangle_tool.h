// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/tools/selection_tool.h"

namespace meshfair::app {

//! \brief Drag a rectangle; on release it covers the elements that project inside it
//! (visible ones only unless "through"). Visibility is the view's at the press.
class RectangleTool final : public SelectionTool
{
public:
    std::vector<Index> press(const ToolView& view, const ToolSettings& settings,
                             ScreenPoint at) override;
    std::vector<Index> drag(ScreenPoint to) override;
    std::vector<Index> release(ScreenPoint at) override;
    ToolOverlay overlay(ScreenPoint cursor) const override;

private:
    ScreenElements elements_;
    ScreenPoint from_, to_;
    bool active_ = false;
};

} // namespace meshfair::app
