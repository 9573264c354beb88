// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/edit/command.h"
#include "app/editor/document.h"
#include "app/editor/editor_state.h"
#include "app/editor/file_browser.h"
#include "app/editor/widget_rect.h"
#include "app/render/camera.h"

namespace meshfair::app {

class InterfaceContext;

//! A command from the interface, with the interaction it belongs to (a slider held).
struct UiCommand
{
    Command command;
    Interaction from;
};

//! What a frame of the interface asked for.
struct UiOutput
{
    std::vector<UiCommand> commands;
    //! A widget was let go: its interaction (a slider's series of values) ends.
    bool end_interaction = false;
};

//! \brief The editor's Dear ImGui interface: menu bar, side panel (one file per section in
//! app/editor/panels/), status bar, energy plot, help overlay, file dialogs and prompts.
//! Pure ImGui: called between ImGui::NewFrame and ImGui::Render. It never edits the
//! document: every action it offers is a command in its output.
class EditorUi
{
public:
    UiOutput build(const Document& document, EditorState& state, const Camera& camera);

    //! \brief Lays out the interface for a `width` x `height` frame without input (the
    //! offscreen screenshot's --ui): afterwards view_rect is known and the layer draws it.
    void prepare_offscreen(InterfaceContext& layer, const Document& document, EditorState& state,
                           const Camera& camera, int width, int height);

    //! \brief The part of a `width` x `height` framebuffer the 3D view gets: all of it but
    //! the menu bar, the status bar and the side panel when shown.
    //! \pre a frame of the interface was laid out (the bars' heights come from its font).
    static ViewRect view_rect(int width, int height, const EditorState& state);

    //! \brief Where the widget named `label` was drawn in the last frame ("Grow",
    //! "Play", "File", "File/Export recipe...", "sets/pins/delete"), for scripts that click
    //! panels as a person does; nullopt when it was not drawn.
    std::optional<WidgetRect> widget(std::string_view label) const;
    //! The names of the widgets drawn in the last frame (for messages).
    std::vector<std::string> widget_names() const;

private:
    FileBrowser browser_;
    cmd::Dialog browser_purpose_ = cmd::Dialog::OpenMesh;
    std::string rename_buffer_;
    std::string renaming_;
    bool was_editing_ = false;    // a widget was active in the last frame
    std::string toast_dismissed_; // the error message whose box was closed
    bool toast_expanded_ = false; // the error box shows the whole text
    WidgetMap widgets_, drawing_;
};

} // namespace meshfair::app
