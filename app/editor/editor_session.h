// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "app/editor/document.h"
#include "app/editor/editor_ui.h"
#include "app/editor/history.h"
#include "app/editor/navigation.h"
#include "app/render/renderer.h"
#include "app/tools/selection_commands.h"
#include "app/tools/selection_tool.h"

namespace meshfair::app {

//! \brief The editor without its window: the document, the interaction state, the camera,
//! the tools and the history, driven by input events in the view's pixels and by
//! commands. The GLFW window and the offscreen script player both drive one, through the
//! same calls, so a script does what the mouse and keys do.
//!
//! The renderer is told of every change (the mesh, the selection) before the next draw.
class EditorSession
{
public:
    //! \pre the renderer's context is current whenever the session is called.
    EditorSession(Document document, Renderer& renderer);
    ~EditorSession();

    Document& document() { return document_; }
    const Document& document() const { return document_; }
    EditorState& state() { return state_; }
    const EditorState& state() const { return state_; }
    Camera& camera() { return camera_; }
    const Camera& camera() const { return camera_; }
    Renderer& renderer() { return renderer_; }
    History& history() { return history_; }
    const History& history() const { return history_; }
    ToolSettings& tool_settings() { return state_.tools; }
    ToolKind tool() const { return state_.tool; }
    void set_tool(ToolKind tool);

    //! Where the 3D view is in the framebuffer (set before input of a frame is handled).
    void set_view_rect(const ViewRect& view) { view_ = view; }
    const ViewRect& view_rect() const { return view_; }
    double aspect() const;

    // Input in the view's pixels, (0, 0) its top-left corner.
    void mouse_press(MouseButton button, Modifiers mods, double x, double y);
    void mouse_move(double x, double y);
    void mouse_release(MouseButton button, double x, double y);
    void scroll(double notches, double x, double y);
    //! True while a tool gesture (a stroke, a rectangle, a lasso) is under way.
    bool in_gesture() const { return gesture_ != nullptr; }
    //! What the active tool draws over the view now.
    ToolOverlay tool_overlay() const;

    void run(SelectionCommand command);
    //! Vertex or face mode for the tools and the selection commands.
    void set_elements(ElementKind kind);
    bool undo();
    bool redo();

    //! Carries out what the interface or the keys asked for (views, files, ...); quit and
    //! screenshots are the caller's.
    void carry_out(const UiRequests& requests);
    //! \brief Opens a mesh as the new document (history cleared); on failure the message
    //! says why and the document stays as it was. Returns whether it opened.
    bool open(const std::string& path);
    //! Saves the mesh (format from the extension, atomic); false and a message on failure.
    bool save(const std::string& path);

    //! Fills the state the interface shows: the tool's overlay, the history, the counts.
    void prepare_ui();
    //! \brief What the view shows now (Renderer::visibility), kept until the camera, the
    //! view's size or the geometry changes, so that gestures from one view render the ID
    //! buffer once between them.
    const Visibility& visibility();
    //! The face centroids projected into the view, kept likewise.
    std::span<const ScreenPoint> face_points();
    //! Sends what changed since the last frame to the renderer (the selection flags).
    void sync_renderer();
    //! sync_renderer, then draws the view.
    void draw();

private:
    SelectionTool& tool_object(ToolKind tool);
    void apply(std::span<const Index> elements);
    void begin_step();
    void end_step(std::string label);
    void selection_changed()
    {
        selection_dirty_ = true;
        counts_dirty_ = true;
    }
    void reset_for_document();
    void remember(const std::string& path);

    Document document_;
    Renderer& renderer_;
    EditorState state_;
    Camera camera_;
    Navigator navigator_;
    History history_;
    std::unique_ptr<SelectionTool> tools_[5];
    ViewRect view_ = ViewRect::whole(640, 480);

    SelectionTool* gesture_ = nullptr; // the tool of the gesture under way
    SelectOp gesture_op_ = SelectOp::Replace;
    ElementKind gesture_elements_ = ElementKind::Vertices;
    std::optional<EditState> step_before_; // the state when the current step began
    ScreenPoint cursor_;
    bool selection_dirty_ = true;
    bool counts_dirty_ = true;

    // The visibility kept for the camera and view it was computed for.
    struct VisibilityKey
    {
        glm::dmat4 view{0.0}, projection{0.0};
        int width = 0, height = 0;
        bool operator==(const VisibilityKey&) const = default;
    };
    std::optional<Visibility> visibility_;
    VisibilityKey visibility_key_;
    std::optional<std::vector<ScreenPoint>> face_points_;
    VisibilityKey face_points_key_;
    VisibilityKey view_key() const;
};

} // namespace meshfair::app
