// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/selection_gesture.h"

#include <utility>

namespace meshfair::app {

SelectionGesture::SelectionGesture(ToolKind kind, std::unique_ptr<SelectionTool> tool)
    : kind_(kind), tool_(std::move(tool))
{
}

void SelectionGesture::emit(std::vector<Index> indices, SelectOp op,
                            std::vector<Command>& out) const
{
    if (indices.empty() && op != SelectOp::Replace)
        return;
    out.push_back(cmd::ApplySelection{elements_, op, std::move(indices), kind_});
}

bool SelectionGesture::press(const ToolContext& context, Modifiers mods, ScreenPoint at,
                             std::vector<Command>& out)
{
    // Shift adds to the selection, Ctrl takes away from it; neither replaces it.
    op_ = mods.ctrl ? SelectOp::Subtract : mods.shift ? SelectOp::Add : SelectOp::Replace;
    elements_ = context.settings.elements;
    emit(tool_->press(context.view, context.settings, at), op_, out);
    return true;
}

void SelectionGesture::move(ScreenPoint to, std::vector<Command>& out)
{
    emit(tool_->drag(to), op_ == SelectOp::Subtract ? SelectOp::Subtract : SelectOp::Add, out);
}

void SelectionGesture::release(ScreenPoint at, std::vector<Command>& out)
{
    emit(tool_->release(at), op_ == SelectOp::Subtract ? SelectOp::Subtract : SelectOp::Add, out);
}

ToolOverlay SelectionGesture::overlay(ScreenPoint cursor, const ToolSettings& settings,
                                      bool active) const
{
    // The brush shows its ring where the cursor is before a stroke too.
    if (kind_ == ToolKind::Brush && !active)
        return {ToolOverlay::Shape::Circle, {cursor}, settings.brush_radius_px};
    if (!active)
        return {};
    return tool_->overlay(cursor);
}

const char* SelectionGesture::gesture_name() const
{
    switch (kind_)
    {
        case ToolKind::Click:
            return "click select";
        case ToolKind::Brush:
            return "brush stroke";
        case ToolKind::Rectangle:
            return "rectangle select";
        case ToolKind::Lasso:
            return "lasso select";
        default:
            return "select";
    }
}

} // namespace meshfair::app
