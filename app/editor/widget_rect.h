// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <functional>
#include <map>
#include <string>

namespace meshfair::app {

//! Where a widget of the interface was drawn in the last frame, in framebuffer pixels.
struct WidgetRect
{
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    double center_x() const { return (x0 + x1) / 2; }
    double center_y() const { return (y0 + y1) / 2; }
};

//! The widgets of a frame by name (scripts click them as a person does).
using WidgetMap = std::map<std::string, WidgetRect, std::less<>>;

} // namespace meshfair::app
