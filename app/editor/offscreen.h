// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <string>

#include "app/editor/editor_frame.h"
#include "app/editor/script.h"
#include "app/render/renderer.h"

namespace meshfair::app {

class InterfaceContext;

//! \brief Frames of a session without a window, through the same EditorFrame as the
//! window: its view, and the panels when asked for (laid out first, as they decide the
//! view's rectangle). The context must be current.
class OffscreenHost final : public ScriptHost
{
public:
    OffscreenHost(EditorSession& session, int width, int height, bool ui);
    ~OffscreenHost() override;
    void run_frame() override;
    EditorFrame& frame_driver() override { return *frame_; }
    void screenshot(const std::string& path) override;
    //! Runs a frame, draws it, and returns its pixels.
    Image frame();

private:
    EditorSession& session_;
    int width_, height_;
    std::unique_ptr<InterfaceContext> layer_;
    std::unique_ptr<EditorFrame> frame_;
};

//! `left` and `right` in one image, top-aligned (rows below the shorter one transparent).
Image side_by_side(const Image& left, const Image& right);

//! What `meshfair --offscreen` renders.
struct ScreenshotRequest
{
    std::string mesh_path;
    std::string view_path; //!< a camera saved as JSON; empty: frame the mesh, front view
    std::string screenshot_path;
    std::string save_view_path; //!< where to write the camera used; empty: nowhere
    std::string script_path;    //!< a scripted session to play first; empty: none
    //! A second mesh drawn with the same camera to the right of the first, in one picture
    //! twice as wide (a before / after comparison); empty: none
    std::string beside_path;
    int width = 1280;
    int height = 800;
    DisplayOptions display;
    bool ui = false;    //!< draw the editor's panels too
    bool trace = false; //!< print the script's commands and their outcomes on stdout
};

//! \brief Renders one frame through OSMesa (no display, no GLFW) and writes it as PNG,
//! after playing the script, if any, through an EditorSession; with beside_path, the second
//! mesh's frame from the same camera to the right of it.
//! \throw InvalidInputError for a bad mesh or view file, WriteError when the PNG cannot be
//! written (an existing file is kept whole), RenderError when there is no usable OpenGL.
void render_screenshot(const ScreenshotRequest& request);

} // namespace meshfair::app
