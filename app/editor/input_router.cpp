// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/input_router.h"

#include <algorithm>

#include <imgui.h>

#include "app/editor/editor_session.h"
#include "app/editor/key_map.h"

namespace meshfair::app {

namespace {

bool is_modifier(int k)
{
    return k >= key::LeftShift && k <= key::RightSuper;
}

int button_index(MouseButton b)
{
    return b == MouseButton::Left ? 0 : b == MouseButton::Right ? 1 : 2; // ImGui's order
}

} // namespace

void InputRouter::push(const InputEvent& event)
{
    queue_.push_back(event);
}

void InputRouter::feed_interface(bool with_interface)
{
    batch_.clear();
    // The cursor's moves, then one event of another kind.
    while (!queue_.empty())
    {
        const InputEvent e = queue_.front();
        queue_.pop_front();
        batch_.push_back(e);
        const bool modifier_key =
            (e.type == InputEvent::Type::KeyPress || e.type == InputEvent::Type::KeyRelease) &&
            is_modifier(e.key);
        if (e.type != InputEvent::Type::MouseMove && !modifier_key)
            break;
    }
    for (const InputEvent& e : batch_)
        if (e.type != InputEvent::Type::KeyPress && e.type != InputEvent::Type::KeyRelease &&
            e.type != InputEvent::Type::Char)
        {
            x_ = e.x;
            y_ = e.y;
        }
    if (!with_interface)
        return;
    ImGuiIO& io = ImGui::GetIO();
    const float sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
    const float sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0f;
    for (const InputEvent& e : batch_)
    {
        switch (e.type)
        {
            case InputEvent::Type::MouseMove:
                io.MousePos = ImVec2(float(e.x) / sx, float(e.y) / sy);
                break;
            case InputEvent::Type::MousePress:
            case InputEvent::Type::MouseRelease:
                io.MousePos = ImVec2(float(e.x) / sx, float(e.y) / sy);
                io.MouseDown[button_index(e.button)] = e.type == InputEvent::Type::MousePress;
                io.KeyShift = e.mods.shift;
                io.KeyCtrl = e.mods.ctrl;
                io.KeyAlt = e.mods.alt;
                break;
            case InputEvent::Type::Scroll:
                io.MousePos = ImVec2(float(e.x) / sx, float(e.y) / sy);
                io.MouseWheel += float(e.amount);
                break;
            case InputEvent::Type::KeyPress:
            case InputEvent::Type::KeyRelease:
            {
                const bool down = e.type == InputEvent::Type::KeyPress;
                if (e.key >= 0 && e.key < int(IM_ARRAYSIZE(io.KeysDown)))
                    io.KeysDown[e.key] = down;
                // A modifier's own event may not carry itself in its modifiers.
                io.KeyShift =
                    e.mods.shift || (down && (e.key == key::LeftShift || e.key == key::RightShift));
                io.KeyCtrl = e.mods.ctrl ||
                             (down && (e.key == key::LeftControl || e.key == key::RightControl));
                io.KeyAlt =
                    e.mods.alt || (down && (e.key == key::LeftAlt || e.key == key::RightAlt));
                if (!down && (e.key == key::LeftShift || e.key == key::RightShift))
                    io.KeyShift = false;
                if (!down && (e.key == key::LeftControl || e.key == key::RightControl))
                    io.KeyCtrl = false;
                if (!down && (e.key == key::LeftAlt || e.key == key::RightAlt))
                    io.KeyAlt = false;
                break;
            }
            case InputEvent::Type::Char:
                if (e.key > 0 && e.key < 0x110000)
                    io.AddInputCharacter(static_cast<unsigned>(e.key));
                break;
        }
    }
}

void InputRouter::route(EditorSession& session, bool with_interface)
{
    bool mouse_captured = false, keys_captured = false, chords_pass = false;
    if (with_interface)
    {
        const ImGuiIO& io = ImGui::GetIO();
        mouse_captured = io.WantCaptureMouse;
        // A dialog or prompt open takes the keys too, as a modal window does.
        const bool popup =
            ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
        keys_captured = io.WantCaptureKeyboard || io.WantTextInput || popup;
        // An open menu takes the letters, but not the Ctrl chords (Ctrl+Q quits with a menu
        // open), unless text is being typed or a dialog or prompt asks.
        const EditorState& st = session.state();
        chords_pass = popup && !io.WantTextInput && !st.dialog && !st.quit_prompt &&
                      !st.recovery_saved_at.has_value();
    }
    const ViewRect& view = session.view_rect();
    for (const InputEvent& e : batch_)
    {
        routed_ += e.type != InputEvent::Type::MouseMove;
        moved_ += e.type == InputEvent::Type::MouseMove;
        if (e.type == InputEvent::Type::KeyPress &&
            std::ranges::find(keys_down_, e.key) == keys_down_.end())
            keys_down_.push_back(e.key);
        if (e.type == InputEvent::Type::KeyRelease)
            std::erase(keys_down_, e.key);
        if (e.type == InputEvent::Type::MousePress || e.type == InputEvent::Type::MouseRelease)
            buttons_down_[button_index(e.button)] = e.type == InputEvent::Type::MousePress;
        const double vx = e.x - view.x, vy = e.y - view.y;
        switch (e.type)
        {
            case InputEvent::Type::MouseMove:
                session.mouse_move(vx, vy, !mouse_captured);
                break;
            case InputEvent::Type::MousePress:
                if (!mouse_captured)
                {
                    view_owns_[button_index(e.button)] = true;
                    session.mouse_press(e.button, e.mods, vx, vy);
                }
                break;
            case InputEvent::Type::MouseRelease:
                if (view_owns_[button_index(e.button)])
                {
                    view_owns_[button_index(e.button)] = false;
                    session.mouse_release(e.button, vx, vy);
                }
                break;
            case InputEvent::Type::Scroll:
                if (!mouse_captured)
                    session.scroll(e.amount, vx, vy);
                break;
            case InputEvent::Type::KeyPress:
                if ((!keys_captured || (e.mods.ctrl && chords_pass)) && !is_modifier(e.key))
                    if (const std::optional<Command> c = command_for_key({e.key, e.mods}))
                        session.dispatch(*c);
                break;
            case InputEvent::Type::KeyRelease:
            case InputEvent::Type::Char:
                break;
        }
    }
    batch_.clear();
}

} // namespace meshfair::app
