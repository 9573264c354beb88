// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/navigation.h"

#include <algorithm>
#include <cmath>

namespace meshfair::app {

void Navigator::press(MouseButton button, Modifiers mods, double x, double y)
{
    if (mode_ != Mode::None)
        return; // one drag at a time: the first button decides
    switch (button)
    {
        case MouseButton::Left:
            mode_ = Mode::Orbit;
            break;
        case MouseButton::Middle:
            mode_ = mods.ctrl ? Mode::Zoom : mods.shift ? Mode::Pan : Mode::Orbit;
            break;
        case MouseButton::Right:
            mode_ = Mode::Pan;
            break;
    }
    button_ = button;
    x_ = x;
    y_ = y;
}

void Navigator::release(MouseButton button)
{
    if (button == button_)
        mode_ = Mode::None;
}

void Navigator::move(Camera& camera, OrbitStyle style, double x, double y, int width, int height)
{
    switch (mode_)
    {
        case Mode::None:
            break;
        case Mode::Orbit:
            camera.orbit(style, x_, y_, x, y, width, height);
            break;
        case Mode::Pan:
            camera.pan(x - x_, y - y_, width, height);
            break;
        case Mode::Zoom:
            // Drag up to come closer: a window height is a factor of e^2.
            camera.zoom(std::exp(2 * (y - y_) / std::max(height, 1)), 0.5 * width, 0.5 * height,
                        width, height);
            break;
    }
    x_ = x;
    y_ = y;
}

void Navigator::scroll(Camera& camera, double notches, double x, double y, int width, int height)
{
    camera.zoom(std::pow(0.85, notches), x, y, width, height);
}

} // namespace meshfair::app
