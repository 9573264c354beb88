// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/tools/selection_tool.h"

namespace meshfair::app {

//! \brief Click to select one element: the face under the cursor (the ID buffer's), or
//! in vertex mode that face's vertex nearest to the cursor on screen. The surface hides
//! what is behind it whatever "through" says: a click names what it sees. A click on the
//! background covers nothing (with no modifier, the selection is then cleared).
class ClickTool final : public SelectionTool
{
public:
    std::vector<Index> press(const ToolView& view, const ToolSettings& settings,
                             ScreenPoint at) override;
    std::vector<Index> drag(ScreenPoint) override { return {}; }
    std::vector<Index> release(ScreenPoint) override { return {}; }
    ToolOverlay overlay(ScreenPoint) const override { return {}; }
};

} // namespace meshfair::app
