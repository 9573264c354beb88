// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_session.h"

#include <algorithm>
#include <array>
#include <utility>

#include "app/tools/brush_tool.h"
#include "app/tools/click_tool.h"
#include "app/tools/lasso_tool.h"
#include "app/tools/rectangle_tool.h"
#include "core/errors.h"
#include "core/io/io.h"

namespace meshfair::app {

namespace {

// Shift adds to the selection, Ctrl takes away from it; neither replaces it.
SelectOp op_of(Modifiers mods)
{
    if (mods.ctrl)
        return SelectOp::Subtract;
    if (mods.shift)
        return SelectOp::Add;
    return SelectOp::Replace;
}

const char* gesture_label(ToolKind tool)
{
    switch (tool)
    {
        case ToolKind::Click:
            return "click select";
        case ToolKind::Brush:
            return "brush stroke";
        case ToolKind::Rectangle:
            return "rectangle select";
        case ToolKind::Lasso:
            return "lasso select";
        case ToolKind::Navigate:
            break;
    }
    return "";
}

} // namespace

EditorSession::EditorSession(Document document, Renderer& renderer)
    : document_(std::move(document)), renderer_(renderer)
{
    tools_[static_cast<int>(ToolKind::Click)] = std::make_unique<ClickTool>();
    tools_[static_cast<int>(ToolKind::Brush)] = std::make_unique<BrushTool>();
    tools_[static_cast<int>(ToolKind::Rectangle)] = std::make_unique<RectangleTool>();
    tools_[static_cast<int>(ToolKind::Lasso)] = std::make_unique<LassoTool>();
    renderer_.set_mesh(document_.mesh, document_.draw_data);
}

EditorSession::~EditorSession() = default;

double EditorSession::aspect() const
{
    return double(view_.width) / std::max(view_.height, 1);
}

SelectionTool& EditorSession::tool_object(ToolKind tool)
{
    return *tools_[static_cast<int>(tool)];
}

void EditorSession::set_tool(ToolKind tool)
{
    if (gesture_ == nullptr)
        state_.tool = tool;
}

void EditorSession::mouse_press(MouseButton button, Modifiers mods, double x, double y)
{
    cursor_ = {x, y, 0};
    if (gesture_ != nullptr)
        return;
    // Alt + left always navigates, so a tool never locks the view.
    if (button == MouseButton::Left && !mods.alt && state_.tool != ToolKind::Navigate &&
        !navigator_.dragging())
    {
        gesture_ = &tool_object(state_.tool);
        gesture_op_ = op_of(mods);
        gesture_elements_ = state_.tools.elements;
        begin_step();
        if (gesture_op_ == SelectOp::Replace)
        {
            SelectionMask& mask = gesture_elements_ == ElementKind::Vertices
                                      ? document_.selected_vertices
                                      : document_.selected_faces;
            std::fill(mask.begin(), mask.end(), 0);
            selection_changed();
        }
        const ToolView view{&document_.mesh,
                            &renderer_,
                            &camera_,
                            view_,
                            [this]() -> const Visibility& { return visibility(); },
                            [this] { return face_points(); }};
        apply(gesture_->press(view, state_.tools, cursor_));
        return;
    }
    navigator_.press(button, mods.alt && button == MouseButton::Left ? Modifiers{} : mods, x, y);
}

void EditorSession::mouse_move(double x, double y)
{
    cursor_ = {x, y, 0};
    if (gesture_ != nullptr)
        apply(gesture_->drag(cursor_));
    else
        navigator_.move(camera_, state_.orbit, x, y, view_.width, view_.height);
}

void EditorSession::mouse_release(MouseButton button, double x, double y)
{
    cursor_ = {x, y, 0};
    if (gesture_ != nullptr && button == MouseButton::Left)
    {
        apply(gesture_->release(cursor_));
        gesture_ = nullptr;
        end_step(gesture_label(state_.tool));
        return;
    }
    navigator_.release(button);
}

void EditorSession::scroll(double notches, double x, double y)
{
    navigator_.scroll(camera_, notches, x, y, view_.width, view_.height);
}

ToolOverlay EditorSession::tool_overlay() const
{
    if (state_.tool == ToolKind::Navigate)
        return {};
    if (state_.tool == ToolKind::Brush && gesture_ == nullptr)
        return {ToolOverlay::Shape::Circle, {cursor_}, state_.tools.brush_radius_px};
    return tools_[static_cast<int>(state_.tool)]->overlay(cursor_);
}

void EditorSession::apply(std::span<const Index> elements)
{
    if (elements.empty())
        return;
    SelectionMask& mask = gesture_elements_ == ElementKind::Vertices ? document_.selected_vertices
                                                                     : document_.selected_faces;
    apply_selection(mask, elements,
                    gesture_op_ == SelectOp::Subtract ? SelectOp::Subtract : SelectOp::Add);
    selection_changed();
}

void EditorSession::begin_step()
{
    step_before_ = capture(document_);
}

void EditorSession::end_step(std::string label)
{
    if (step_before_)
        history_.record(std::move(label), std::move(*step_before_), document_);
    step_before_.reset();
}

void EditorSession::run(SelectionCommand command)
{
    if (gesture_ != nullptr)
        return;
    begin_step();
    run_selection_command(command, state_.tools.elements, document_.mesh, document_.topology,
                          document_.selected_vertices, document_.selected_faces);
    selection_changed();
    end_step("select " + std::string(command_name(command)));
}

void EditorSession::set_elements(ElementKind kind)
{
    if (gesture_ == nullptr)
        state_.tools.elements = kind;
}

bool EditorSession::undo()
{
    if (gesture_ != nullptr || !history_.undo(document_))
        return false;
    selection_changed();
    state_.message = "undid " + history_.redo_label();
    return true;
}

bool EditorSession::redo()
{
    if (gesture_ != nullptr || !history_.redo(document_))
        return false;
    selection_changed();
    state_.message = "redid " + history_.undo_label();
    return true;
}

void EditorSession::carry_out(const UiRequests& r)
{
    if (r.frame_all)
        camera_.frame(document_.box, aspect());
    if (r.frame_selection)
        camera_.frame(selection_box(document_), document_.box, aspect());
    if (r.view)
        camera_.set_view(*r.view);
    if (r.toggle_projection)
        camera_.projection = camera_.projection == Projection::Perspective
                                 ? Projection::Orthographic
                                 : Projection::Perspective;
    if (r.tool)
        set_tool(*r.tool);
    if (r.elements)
        set_elements(*r.elements);
    if (r.command)
        run(*r.command);
    if (r.undo)
        undo();
    if (r.redo)
        redo();
    if (r.open_path)
        open(*r.open_path);
    if (r.save_path)
        save(*r.save_path);
}

bool EditorSession::open(const std::string& path)
{
    if (gesture_ != nullptr)
        return false;
    try
    {
        Document next = load_document(path);
        renderer_.set_mesh(next.mesh, next.draw_data);
        document_ = std::move(next);
        reset_for_document();
        camera_.frame(document_.box, aspect());
        remember(path);
        state_.message = "opened " + path;
        return true;
    }
    catch (const InvalidInputError& e)
    {
        state_.message = e.what(); // the document on screen stays as it was
        return false;
    }
}

void EditorSession::remember(const std::string& path)
{
    // An offscreen run (a script, a test) leaves the user's recent files alone.
    if (state_.offscreen)
        return;
    remember_recent(state_.recent, path);
    save_recent(recent_files_path(), state_.recent);
}

void EditorSession::reset_for_document()
{
    visibility_.reset(); // another mesh
    face_points_.reset();
    history_.clear();
    step_before_.reset();
    selection_changed();
}

bool EditorSession::save(const std::string& path)
{
    try
    {
        io::write_mesh(document_.mesh, path);
        document_.path = path;
        document_.modified = false;
        remember(path);
        state_.message = "saved " + path;
        return true;
    }
    catch (const std::exception& e)
    {
        state_.message = e.what();
        return false;
    }
}

void EditorSession::prepare_ui()
{
    state_.overlay = tool_overlay();
    for (ScreenPoint& p : state_.overlay.points)
    {
        p.x += view_.x;
        p.y += view_.y;
    }
    HistoryStatus& h = state_.history;
    h.undo_count = history_.undo_count();
    h.redo_count = history_.redo_count();
    h.undo_label = history_.undo_label();
    h.redo_label = history_.redo_label();
    h.bytes = history_.bytes();
    h.limit = history_.limit();
    h.dropped = history_.dropped();
    if (counts_dirty_)
    {
        state_.selected_vertices = static_cast<std::size_t>(
            std::count(document_.selected_vertices.begin(), document_.selected_vertices.end(), 1));
        state_.selected_faces = static_cast<std::size_t>(
            std::count(document_.selected_faces.begin(), document_.selected_faces.end(), 1));
        counts_dirty_ = false;
    }
}

EditorSession::VisibilityKey EditorSession::view_key() const
{
    return {camera_.view_matrix(), camera_.projection_matrix(aspect()), view_.width, view_.height};
}

std::span<const ScreenPoint> EditorSession::face_points()
{
    const VisibilityKey key = view_key();
    if (!face_points_ || !(key == face_points_key_))
    {
        face_points_ = project_face_centroids(document_.mesh, camera_, view_.width, view_.height);
        face_points_key_ = key;
    }
    return *face_points_;
}

const Visibility& EditorSession::visibility()
{
    const VisibilityKey key = view_key();
    if (!visibility_ || !(key == visibility_key_))
    {
        visibility_ = renderer_.visibility(camera_, view_);
        visibility_key_ = key;
    }
    return *visibility_;
}

void EditorSession::sync_renderer()
{
    if (selection_dirty_)
    {
        renderer_.set_selection(document_.selected_vertices, document_.selected_faces);
        selection_dirty_ = false;
    }
}

void EditorSession::draw()
{
    sync_renderer();
    renderer_.draw(camera_, state_.display, view_);
}

} // namespace meshfair::app
