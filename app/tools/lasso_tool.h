// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/tools/selection_tool.h"

namespace meshfair::app {

//! \brief Draw a closed curve; on release it covers the elements that project inside it
//! by the even-odd rule (points_in_lasso). The curve keeps a point per pixel moved.
class LassoTool final : public SelectionTool
{
public:
    std::vector<Index> press(const ToolView& view, const ToolSettings& settings,
                             ScreenPoint at) override;
    std::vector<Index> drag(ScreenPoint to) override;
    std::vector<Index> release(ScreenPoint at) override;
    ToolOverlay overlay(ScreenPoint cursor) const override;

private:
    ScreenElements elements_;
    std::vector<ScreenPoint> curve_;
    bool active_ = false;
};

} // namespace meshfair::app
