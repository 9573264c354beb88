// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <stdexcept>
#include <string>

#include "app/render/renderer.h"

namespace meshfair::app {

//! There is no display to open a window on (no DISPLAY, or the X server refuses).
class NoDisplayError : public std::runtime_error
{
public:
    explicit NoDisplayError(const std::string& what) : std::runtime_error(what) {}
};

struct WindowOptions
{
    std::string mesh_path;
    std::string view_path;       //!< a saved camera to start from; empty: frame the mesh
    std::string screenshot_path; //!< where F12 writes; empty: meshfair-screenshot-N.png
    int width = 1280;
    int height = 800;
    DisplayOptions display;
    bool trace = false;     //!< print each command and its outcome on stdout
    std::string widget_map; //!< a file kept listing the widgets' rectangles; empty: none
};

//! \brief The editor's window: GLFW 3.3, an OpenGL 3.3 core context, Dear ImGui, until the
//! user quits. Prints one line on stdout once the first frame is on screen.
//! \throw NoDisplayError when GLFW cannot reach a display, InvalidInputError for a mesh
//! or view that cannot be read at start, RenderError when there is no usable OpenGL.
void run_window(const WindowOptions& options);

} // namespace meshfair::app
