// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_frame.h"

#include <algorithm>

#include <imgui.h>

#include "app/editor/editor_session.h"
#include "app/editor/interface_context.h"

namespace meshfair::app {

EditorFrame::EditorFrame(EditorSession& session, InterfaceContext* layer)
    : session_(session), layer_(layer)
{
}

void EditorFrame::run(const FrameSize& size, double seconds)
{
    if (layer_ == nullptr)
    {
        input_.feed_interface(false);
        session_.set_view_rect(ViewRect::whole(size.framebuffer_width, size.framebuffer_height));
        input_.route(session_, false);
        session_.update();
        return;
    }
    ImGuiIO& io = ImGui::GetIO();
    const int ww = std::max(size.window_width, 1), wh = std::max(size.window_height, 1);
    io.DisplaySize = ImVec2(float(ww), float(wh));
    io.DisplayFramebufferScale = ImVec2(float(size.framebuffer_width) / float(ww),
                                        float(size.framebuffer_height) / float(wh));
    io.DeltaTime = seconds > 0 ? float(seconds) : 1.0f / 60.0f;
    input_.feed_interface(true);
    layer_->new_frame();
    session_.prepare_ui();
    const UiOutput out = ui_.build(session_.document(), session_.state(), session_.camera());
    session_.set_view_rect(
        EditorUi::view_rect(size.framebuffer_width, size.framebuffer_height, session_.state()));
    for (const UiCommand& c : out.commands)
        session_.dispatch(c.command, c.from);
    if (out.end_interaction)
        session_.end_interaction();
    input_.route(session_, true);
    layer_->end_frame();
    session_.update();
}

void EditorFrame::draw()
{
    session_.draw();
    if (layer_ != nullptr)
        layer_->draw();
}

} // namespace meshfair::app
