// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "app/editor/editor_ui.h"
#include "app/editor/input_router.h"

namespace meshfair::app {

class EditorSession;
class InterfaceContext;

//! The size of a frame: the framebuffer's pixels and the window's units (they differ on
//! scaled displays; the interface lays out in window units).
struct FrameSize
{
    int framebuffer_width = 0, framebuffer_height = 0;
    int window_width = 0, window_height = 0;
};

//! \brief One frame of the editor's interface and input, the same for the window, the
//! offscreen screenshots and scripts: a batch of input to ImGui, the panels laid out and
//! their commands dispatched, the input the panels did not capture routed to the view and
//! the key map, then the session updated (the solver's newest positions taken).
class EditorFrame
{
public:
    //! `layer` null: no interface (the view takes the whole framebuffer and all input).
    EditorFrame(EditorSession& session, InterfaceContext* layer);
    void run(const FrameSize& size, double seconds);
    //! Draws the view, then the interface over it, into the current framebuffer.
    void draw();
    InputRouter& input() { return input_; }
    const EditorUi& ui() const { return ui_; }
    bool has_interface() const { return layer_ != nullptr; }

private:
    EditorSession& session_;
    InterfaceContext* layer_;
    EditorUi ui_;
    InputRouter input_;
};

} // namespace meshfair::app
