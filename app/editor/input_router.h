// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <deque>
#include <vector>

#include "app/editor/input_event.h"

namespace meshfair::app {

class EditorSession;

//! \brief The one way raw input reaches the editor, from the window's callbacks and from
//! scripts alike. Events are queued and handed out a batch per frame of the interface:
//! the cursor moves, then at most one press, release, wheel turn, key or character, so
//! that no press is lost between two frames and every press is judged where it happened.
//! Each batch goes first to Dear ImGui; what the interface did not capture (ImGui's
//! WantCaptureMouse and WantCaptureKeyboard, or a modal dialog for keys) then goes to the
//! view: the mouse to the session's tools and navigation, keys to the key map's commands.
//! A release goes to the view only when the view took the press.
class InputRouter
{
public:
    void push(const InputEvent& event);
    //! Whether events wait for a frame.
    bool pending() const { return !queue_.empty(); }

    //! \brief Takes the next batch and, with an interface, gives it to ImGui's io. Call
    //! before ImGui::NewFrame.
    void feed_interface(bool with_interface);
    //! \brief Gives the batch's events the interface did not capture to the session.
    //! Call after the interface's frame was built; without an interface nothing is captured.
    void route(EditorSession& session, bool with_interface);

    //! Events other than cursor moves handed to the session so far (route: presses,
    //! releases, wheel turns, characters), and whether a key or a mouse button
    //! is down after them: the widget map reports both, so that a test driving the window
    //! waits for its input to be handled instead of sleeping for a guessed time.
    long routed_count() const { return routed_; }
    //! Cursor moves handed to the session so far: with cursor_x() and cursor_y(), in the
    //! widget map too, so that a test waits until the editor has seen the pointer where it
    //! moved it before pressing there (the window reads a press's place when its frame polls).
    long moved_count() const { return moved_; }
    bool anything_held() const
    {
        return !keys_down_.empty() || buttons_down_[0] || buttons_down_[1] || buttons_down_[2];
    }

    //! Where the cursor was last seen, in framebuffer pixels.
    double cursor_x() const { return x_; }
    double cursor_y() const { return y_; }

private:
    std::deque<InputEvent> queue_;
    std::vector<InputEvent> batch_;
    std::array<bool, 3> view_owns_{}; // the view took the press of this button
    long routed_ = 0;
    long moved_ = 0;
    std::vector<int> keys_down_;
    std::array<bool, 3> buttons_down_{};
    double x_ = 0, y_ = 0;
};

} // namespace meshfair::app
