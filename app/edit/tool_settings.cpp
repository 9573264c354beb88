// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/edit/tool_settings.h"

#include <array>
#include <utility>

namespace meshfair::app {

namespace {

constexpr std::array<std::pair<ToolKind, std::string_view>, 8> kToolNames = {{
    {ToolKind::Navigate, "navigate"},
    {ToolKind::Click, "click"},
    {ToolKind::Brush, "brush"},
    {ToolKind::Rectangle, "rectangle"},
    {ToolKind::Lasso, "lasso"},
    {ToolKind::MovePins, "move_pins"},
    {ToolKind::AimNormals, "aim_normals"},
    {ToolKind::Paint, "paint"},
}};

constexpr std::array<std::pair<PaintMode, std::string_view>, 4> kPaintModes = {{
    {PaintMode::Relax, "relax"},
    {PaintMode::Add, "add"},
    {PaintMode::Subtract, "subtract"},
    {PaintMode::Smooth, "smooth"},
}};

} // namespace

std::optional<ElementKind> element_kind_named(std::string_view name)
{
    if (name == "vertices")
        return ElementKind::Vertices;
    if (name == "faces")
        return ElementKind::Faces;
    return std::nullopt;
}

std::string_view tool_name(ToolKind tool)
{
    for (const auto& [t, name] : kToolNames)
        if (t == tool)
            return name;
    return {};
}

std::optional<ToolKind> tool_named(std::string_view name)
{
    for (const auto& [t, n] : kToolNames)
        if (n == name)
            return t;
    return std::nullopt;
}

std::string_view paint_mode_name(PaintMode mode)
{
    for (const auto& [m, name] : kPaintModes)
        if (m == mode)
            return name;
    return {};
}

std::optional<PaintMode> paint_mode_named(std::string_view name)
{
    for (const auto& [m, n] : kPaintModes)
        if (n == name)
            return m;
    return std::nullopt;
}

} // namespace meshfair::app
