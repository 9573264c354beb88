// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>

#include "app/tools/interactive_tool.h"

namespace meshfair::app {

//! \brief A selection tool (click, brush, rectangle, lasso) as a gesture of commands: what
//! it covers becomes ApplySelection commands with the modifiers' operation (no modifier
//! replaces the selection at the press, Shift adds, Ctrl takes away).
class SelectionGesture final : public InteractiveTool
{
public:
    SelectionGesture(ToolKind kind, std::unique_ptr<SelectionTool> tool);
    bool press(const ToolContext& context, Modifiers mods, ScreenPoint at,
               std::vector<Command>& out) override;
    void move(ScreenPoint to, std::vector<Command>& out) override;
    void release(ScreenPoint at, std::vector<Command>& out) override;
    ToolOverlay overlay(ScreenPoint cursor, const ToolSettings& settings,
                        bool active) const override;
    const char* gesture_name() const override;

private:
    void emit(std::vector<Index> indices, SelectOp op, std::vector<Command>& out) const;
    ToolKind kind_;
    std::unique_ptr<SelectionTool> tool_;
    SelectOp op_ = SelectOp::Replace;
    ElementKind elements_ = ElementKind::Vertices;
};

} // namespace meshfair::app
