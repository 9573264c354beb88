// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

namespace meshfair::app {

//! \brief A Dear ImGui context with its OpenGL 3 renderer backend, for as long as it lives.
//! No imgui.ini is read or written (the layout is fixed, and screenshots must not depend on
//! a file in the working directory).
//! \pre an OpenGL 3.3 context is current and the GL table loaded.
class InterfaceContext
{
public:
    InterfaceContext();
    ~InterfaceContext();
    InterfaceContext(const InterfaceContext&) = delete;
    InterfaceContext& operator=(const InterfaceContext&) = delete;

    //! Starts a frame (after the platform backend's NewFrame, or io set by hand).
    void new_frame();
    //! Ends the frame: its draw data is ready for draw().
    void end_frame();
    //! Draws the last ended frame into the current framebuffer, over what is there.
    void draw();
};

} // namespace meshfair::app
