// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/render/camera.h"

namespace meshfair::app {

enum class MouseButton
{
    Left,
    Middle,
    Right
};

struct Modifiers
{
    bool shift = false;
    bool ctrl = false;
    bool alt = false;
};

//! \brief The mouse map of the view (docs/editor.md), independent of the window system:
//! left or middle drag orbits, right drag or Shift + middle drag pans, Ctrl + middle drag
//! and the wheel zoom (the wheel to the cursor). Events come in window pixels.
class Navigator
{
public:
    void press(MouseButton button, Modifiers mods, double x, double y);
    void release(MouseButton button);
    //! Applies the drag in progress, if any, to the camera.
    void move(Camera& camera, OrbitStyle style, double x, double y, int width, int height);
    //! One wheel notch up (positive) zooms in by 15 %, towards the cursor.
    void scroll(Camera& camera, double notches, double x, double y, int width, int height);
    bool dragging() const { return mode_ != Mode::None; }

private:
    enum class Mode
    {
        None,
        Orbit,
        Pan,
        Zoom
    };
    Mode mode_ = Mode::None;
    MouseButton button_ = MouseButton::Left;
    double x_ = 0, y_ = 0;
};

} // namespace meshfair::app
