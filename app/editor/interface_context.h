// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

namespace meshfair::app {

//! \brief A Dear ImGui context, with its OpenGL 3 renderer backend when it draws, for as
//! long as it lives. Keys are MeshFair's codes (app/editor/input_event.h), fed by the
//! InputRouter. No imgui.ini is read or written (the layout is fixed, and screenshots must
//! not depend on a file in the working directory).
class InterfaceContext
{
public:
    //! \pre with `draws`, an OpenGL 3.3 context is current and the GL table loaded; without,
    //! frames are laid out and take input but are never drawn (tests without GL).
    explicit InterfaceContext(bool draws = true);
    ~InterfaceContext();
    InterfaceContext(const InterfaceContext&) = delete;
    InterfaceContext& operator=(const InterfaceContext&) = delete;
    //! Starts a frame (io's display size, time step and input set before).
    void new_frame();
    //! Ends the frame: its draw data is ready for draw().
    void end_frame();
    //! Draws the last ended frame into the current framebuffer, over what is there.
    void draw();

private:
    bool draws_;
};

} // namespace meshfair::app
