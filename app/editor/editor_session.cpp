// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_session.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <utility>

#include <glm/gtc/quaternion.hpp>

#include "app/tools/brush_tool.h"
#include "app/tools/click_tool.h"
#include "app/tools/lasso_tool.h"
#include "app/tools/rectangle_tool.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/geometry/noise.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"

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
        case ToolKind::MovePins:
        case ToolKind::AimNormals:
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
    problems_ = constraint_problems(document_.sets, document_.solver);
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
    history_.seal(); // what this press starts is a step of its own
    cursor_ = {x, y, 0};
    if (gesture_ != nullptr)
        return;
    if (button == MouseButton::Left && !mods.alt && state_.tool == ToolKind::MovePins)
    {
        if (press_pins(x, y))
            return;
    }
    if (button == MouseButton::Left && !mods.alt && state_.tool == ToolKind::AimNormals)
    {
        if (press_normals(x, y))
            return;
    }
    // Alt + left always navigates, so a tool never locks the view.
    if (button == MouseButton::Left && !mods.alt && state_.tool != ToolKind::Navigate &&
        state_.tool != ToolKind::MovePins && state_.tool != ToolKind::AimNormals &&
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
    if (dragged_pins_)
        drag_pins(x, y);
    else if (aimed_normals_)
        aim_normals(x, y);
    else if (gesture_ != nullptr)
        apply(gesture_->drag(cursor_));
    else
        navigator_.move(camera_, state_.orbit, x, y, view_.width, view_.height);
}

void EditorSession::mouse_release(MouseButton button, double x, double y)
{
    struct Seal
    {
        History& h;
        ~Seal() { h.seal(); } // the drag's merged steps end with it
    } seal{history_};
    cursor_ = {x, y, 0};
    if (dragged_pins_ && button == MouseButton::Left)
    {
        drag_pins(x, y);
        dragged_pins_.reset();
        return;
    }
    if (aimed_normals_ && button == MouseButton::Left)
    {
        aim_normals(x, y);
        aimed_normals_.reset();
        return;
    }
    if (gesture_ != nullptr && button == MouseButton::Left)
    {
        apply(gesture_->release(cursor_));
        gesture_ = nullptr;
        end_step(gesture_label(state_.tool));
        return;
    }
    navigator_.release(button);
}

bool EditorSession::press_pins(double x, double y)
{
    // The visible pin glyph nearest to the cursor, within 12 pixels.
    double best = 12 * 12;
    for (size_t k = 0; k < document_.sets.size(); ++k)
    {
        const ConstraintSet& s = document_.sets[k];
        if (s.kind != ConstraintKind::Pin || !s.visible)
            continue;
        for (size_t v = 0; v < s.vertices.size(); ++v)
        {
            const size_t i = 3 * static_cast<size_t>(s.vertices[v]);
            const glm::dvec3 world =
                s.targets.empty()
                    ? glm::dvec3(document_.mesh.positions[i], document_.mesh.positions[i + 1],
                                 document_.mesh.positions[i + 2])
                    : glm::dvec3(s.targets[v][0], s.targets[v][1], s.targets[v][2]);
            const glm::dvec3 w = camera_.project(world, view_.width, view_.height);
            const double d2 = (w.x - x) * (w.x - x) + (w.y - y) * (w.y - y);
            if (w.z >= 0 && w.z <= 1 && d2 < best)
            {
                best = d2;
                dragged_pins_ = k;
                dragged_depth_ = w.z;
                dragged_from_ = camera_.unproject({x, y, w.z}, view_.width, view_.height);
            }
        }
    }
    if (dragged_pins_)
        state_.message = "moving the pins of '" + document_.sets[*dragged_pins_].name + "'";
    return dragged_pins_.has_value();
}

bool EditorSession::press_normals(double x, double y)
{
    // The normal set whose arrow base (a face centroid) is nearest to the cursor, within 12
    // pixels, among the faces its glyphs show.
    double best = 12 * 12;
    const Mesh& mesh = document_.mesh;
    for (size_t k = 0; k < document_.sets.size(); ++k)
    {
        const ConstraintSet& s = document_.sets[k];
        const bool normal = s.kind == ConstraintKind::Normal ||
                            s.kind == ConstraintKind::HardNormal ||
                            s.kind == ConstraintKind::SoftNormal;
        if (!normal || !s.visible)
            continue;
        const size_t step = std::max<size_t>(1, (s.faces.size() + 23) / 24);
        for (size_t f = 0; f < s.faces.size(); f += step)
        {
            const Vec3 c = face_centroid(mesh, mesh.positions, s.faces[f]);
            const glm::dvec3 w = camera_.project({c[0], c[1], c[2]}, view_.width, view_.height);
            const double d2 = (w.x - x) * (w.x - x) + (w.y - y) * (w.y - y);
            if (w.z >= 0 && w.z <= 1 && d2 < best)
            {
                best = d2;
                aimed_normals_ = k;
            }
        }
    }
    aim_x_ = x;
    aim_y_ = y;
    if (aimed_normals_)
        state_.message = "turning the normals of '" + document_.sets[*aimed_normals_].name + "'";
    return aimed_normals_.has_value();
}

void EditorSession::aim_normals(double x, double y)
{
    // A drag turns the direction about the view-plane axis across it, one radian per 100
    // pixels, as a trackball turns the object under the mouse.
    const double dx = x - aim_x_, dy = y - aim_y_;
    const double angle = std::sqrt(dx * dx + dy * dy) / 100.0;
    if (angle == 0)
        return;
    const glm::dvec3 right = camera_.rotation * glm::dvec3(1, 0, 0);
    const glm::dvec3 up = camera_.rotation * glm::dvec3(0, 1, 0);
    const glm::dvec3 axis = glm::normalize(dy * right + dx * up); // screen y points down
    const ConstraintSet& s = document_.sets[*aimed_normals_];
    Vec3 d0 = s.normals.empty() ? face_normal(document_.mesh, document_.mesh.positions, s.faces[0])
                                : s.normals[0];
    const glm::dvec3 d = glm::angleAxis(angle, axis) * glm::dvec3(d0[0], d0[1], d0[2]);
    set_normal_direction(*aimed_normals_, {d.x, d.y, d.z});
    aim_x_ = x;
    aim_y_ = y;
}

void EditorSession::drag_pins(double x, double y)
{
    // The grabbed point follows the cursor in the plane through it parallel to the view.
    const glm::dvec3 to = camera_.unproject({x, y, dragged_depth_}, view_.width, view_.height);
    const glm::dvec3 d = to - dragged_from_;
    if (d == glm::dvec3(0.0))
        return;
    move_pins(*dragged_pins_, {d.x, d.y, d.z});
    dragged_from_ = to;
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
    step_before_ = capture(document_, kSelection);
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
    return travel(true);
}

bool EditorSession::redo()
{
    return travel(false);
}

bool EditorSession::travel(bool back)
{
    if (gesture_ != nullptr)
        return false;
    close_run(); // a run under way is a step of its own first
    const unsigned parts = back ? history_.undo(document_) : history_.redo(document_);
    if (parts == 0)
        return false;
    after_history(parts);
    state_.message = back ? "undid " + history_.redo_label() : "redid " + history_.undo_label();
    return true;
}

void EditorSession::after_history(unsigned parts)
{
    if (parts & kSelection)
        selection_changed();
    if (parts & (kSets | kSettings))
        sets_changed();
    if (parts & (kPositions | kBasePositions))
    {
        positions_changed();
        recipe_dirty_ = true; // the solver starts again from the restored shape
        restarted_.reset();
    }
}

void EditorSession::record(const std::string& label, EditState before, bool merge)
{
    if (history_.record(label, std::move(before), document_, merge))
        ++edits_;
}

namespace {

double steady_seconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

void EditorSession::autosave(double interval_s)
{
    // Not while playing: the run's start is saved, and writing the positions of a large
    // mesh every few seconds would stall the frames; the end of the run is saved after it.
    if (recovery_root_.empty() || edits_ == autosaved_edits_ || run_open_)
        return;
    const double now = steady_seconds();
    if (interval_s > 0 && now - last_autosave_ < interval_s)
        return;
    try
    {
        write_recovery(document_, recovery_root_);
        if (owns_recovery_ && recovery_path_ != document_.path)
            remove_recovery(recovery_path_, recovery_root_); // saved under another name since
        owns_recovery_ = true;
        recovery_path_ = document_.path;
        autosaved_edits_ = edits_;
        last_autosave_ = now;
    }
    catch (const std::exception& e)
    {
        state_.message = std::string("autosave failed: ") + e.what();
        last_autosave_ = now; // not again at once
    }
}

std::optional<RecoveryInfo> EditorSession::recovery_offer() const
{
    return find_recovery(document_.path, recovery_root_);
}

bool EditorSession::recover()
{
    const std::optional<RecoveryInfo> info = recovery_offer();
    if (!info)
    {
        state_.message = "no recovery files for " + document_.path;
        return false;
    }
    close_run();
    try
    {
        restore_recovery(*info, document_);
    }
    catch (const InvalidInputError& e)
    {
        state_.message = e.what();
        return false;
    }
    owns_recovery_ = true;
    recovery_path_ = document_.path;
    history_.clear();
    positions_changed();
    selection_changed();
    sets_changed();
    restarted_.reset();
    recipe_dirty_ = true;
    ++edits_;
    state_.message = "recovered the session saved at " + info->saved_at;
    return true;
}

void EditorSession::discard_recovery()
{
    remove_recovery(document_.path, recovery_root_);
    state_.recovery_saved_at.reset();
}

void EditorSession::end_session()
{
    close_run();
    if (owns_recovery_)
        remove_recovery(recovery_path_, recovery_root_);
}

void EditorSession::sets_changed()
{
    problems_ = constraint_problems(document_.sets, document_.solver);
    border_ = region_border(document_);
    glyphs_dirty_ = true;
    recipe_dirty_ = true;
}

void EditorSession::positions_changed()
{
    geometry_changed(false);
}

void EditorSession::geometry_changed(bool computed)
{
    ++edits_;
    if (computed)
        renderer_.update_geometry(display_.positions, display_.normals, display_.face_areas);
    else
        renderer_.update_positions(document_.mesh.positions);
    ++geometry_;
    glyphs_dirty_ = glyphs_dirty_ || !document_.sets.empty();
    document_.modified = true;
}

Mesh EditorSession::base_mesh() const
{
    Mesh base;
    base.positions = document_.base_positions;
    base.face_offsets = document_.mesh.face_offsets;
    base.face_vertices = document_.mesh.face_vertices;
    return base;
}

bool EditorSession::create_set(ConstraintKind kind, std::string name)
{
    if (gesture_ != nullptr)
        return false;
    const Mesh& mesh = document_.mesh;
    const bool faces_mode = state_.tools.elements == ElementKind::Faces;
    ConstraintSet set;
    set.kind = kind;
    set.color = default_color(kind);
    if (kind == ConstraintKind::Region && faces_mode)
        set.faces = selected_indices(document_.selected_faces);
    else if (takes_vertices(kind))
        set.vertices =
            selected_indices(faces_mode ? vertices_of_faces(mesh, document_.selected_faces)
                                        : document_.selected_vertices);
    else
        set.faces =
            selected_indices(faces_mode ? document_.selected_faces
                                        : faces_of_vertices(mesh, document_.selected_vertices));
    if (set.vertices.empty() && set.faces.empty())
    {
        state_.message = "nothing selected for a " + std::string(kind_name(kind)) + " set";
        return false;
    }
    if (name.empty())
    {
        int k = 1;
        do
            name = std::string(kind_name(kind)) + " " + std::to_string(k++);
        while (set_named(name));
    }
    set.name = std::move(name);
    EditState before = capture(document_, kSets);
    state_.message = "set '" + set.name +
                     "': " + std::to_string(set.vertices.size() + set.faces.size()) +
                     (set.vertices.empty() ? " faces" : " vertices");
    document_.sets.push_back(std::move(set));
    record("new set", std::move(before));
    sets_changed();
    return true;
}

std::optional<size_t> EditorSession::set_named(const std::string& name) const
{
    for (size_t k = 0; k < document_.sets.size(); ++k)
        if (document_.sets[k].name == name)
            return k;
    return std::nullopt;
}

void EditorSession::delete_set(size_t index)
{
    if (index >= document_.sets.size())
        return;
    EditState before = capture(document_, kSets);
    document_.sets.erase(document_.sets.begin() + static_cast<std::ptrdiff_t>(index));
    record("delete set", std::move(before));
    sets_changed();
}

void EditorSession::rename_set(size_t index, std::string name)
{
    if (index >= document_.sets.size() || name.empty())
        return;
    EditState before = capture(document_, kSets);
    document_.sets[index].name = std::move(name);
    record("rename set", std::move(before), true);
    sets_changed();
}

void EditorSession::set_visible(size_t index, bool visible)
{
    if (index >= document_.sets.size())
        return;
    EditState before = capture(document_, kSets);
    document_.sets[index].visible = visible;
    record(visible ? "show set" : "hide set", std::move(before));
    sets_changed();
}

void EditorSession::set_color(size_t index, std::array<float, 3> color)
{
    if (index >= document_.sets.size())
        return;
    EditState before = capture(document_, kSets);
    document_.sets[index].color = color;
    record("set colour", std::move(before), true);
    sets_changed();
}

void EditorSession::select_set(size_t index)
{
    if (index >= document_.sets.size() || gesture_ != nullptr)
        return;
    const ConstraintSet& set = document_.sets[index];
    EditState before = capture(document_, kSelection);
    const bool faces = set.vertices.empty();
    SelectionMask& mask = faces ? document_.selected_faces : document_.selected_vertices;
    std::fill(mask.begin(), mask.end(), 0);
    apply_selection(mask, faces ? set.faces : set.vertices, SelectOp::Add);
    state_.tools.elements = faces ? ElementKind::Faces : ElementKind::Vertices;
    selection_changed();
    record("select set", std::move(before));
}

void EditorSession::set_normal_direction(size_t index, Vec3 d)
{
    if (index >= document_.sets.size() || document_.sets[index].faces.empty())
        return;
    const Scalar length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(length > 0) || !std::isfinite(length))
    {
        state_.message = "a normal direction must not be zero";
        return;
    }
    for (Scalar& c : d)
        c /= length;
    EditState before = capture(document_, kSets);
    ConstraintSet& set = document_.sets[index];
    set.normals.assign(set.faces.size(), d);
    record("normal direction", std::move(before), true);
    sets_changed();
}

void EditorSession::move_pins(size_t index, Vec3 offset)
{
    if (index >= document_.sets.size() || document_.sets[index].kind != ConstraintKind::Pin)
        return;
    EditState before = capture(document_, kSets);
    ConstraintSet& set = document_.sets[index];
    if (set.targets.empty())
        for (const Index v : set.vertices)
        {
            const size_t k = 3 * static_cast<size_t>(v);
            set.targets.push_back({document_.base_positions[k], document_.base_positions[k + 1],
                                   document_.base_positions[k + 2]});
        }
    for (Vec3& t : set.targets)
        for (int a = 0; a < 3; ++a)
            t[static_cast<size_t>(a)] += offset[static_cast<size_t>(a)];
    record("move pins", std::move(before), true);
    sets_changed();
}

void EditorSession::set_solver_settings(const SolverSettings& settings, bool merge)
{
    if (settings == document_.solver)
        return;
    EditState before = capture(document_, kSettings);
    const bool only_pace = [&] {
        SolverSettings a = settings, b = document_.solver;
        a.iterations_per_frame = b.iterations_per_frame = 0;
        return a == b;
    }();
    document_.solver = settings;
    solver_.set_iterations_per_frame(settings.iterations_per_frame);
    record("solver settings", std::move(before), merge);
    if (!only_pace) // how many steps a frame runs is not part of the recipe
        sets_changed();
}

Recipe EditorSession::current_recipe() const
{
    return build_recipe(document_.sets, document_.solver, document_.mesh, document_.base_positions,
                        document_.steps_from_base);
}

Recipe EditorSession::file_recipe() const
{
    return renumber_recipe(current_recipe(), document_.order.vertex_order,
                           document_.order.face_order);
}

bool EditorSession::export_recipe(const std::string& path)
{
    if (!problems_.empty())
    {
        state_.message = "cannot export the recipe: " + problems_.front();
        return false;
    }
    try
    {
        io::write_file_atomically(path, recipe_to_json(file_recipe()).dump(2) + "\n");
        state_.message = "exported " + path +
                         (document_.reproducible
                              ? std::string(" (reproduces the shape from the base)")
                              : std::string(" (the recipe changed during the run: Reset and run "
                                            "again for a recipe that reproduces the shape)"));
        return true;
    }
    catch (const std::exception& e)
    {
        state_.message = e.what();
        return false;
    }
}

bool EditorSession::import_recipe(const std::string& path)
{
    try
    {
        const Recipe recipe = read_recipe(path);
        check_recipe(recipe, document_.mesh); // the file's indices named in messages
        const Recipe internal =
            renumber_recipe(recipe, document_.order.vertex_index, document_.order.face_index);
        ImportedRecipe imported = sets_from_recipe(internal, document_.mesh);
        close_run();
        EditState before = capture(document_, kSets | kSettings);
        imported.settings.iterations_per_frame = document_.solver.iterations_per_frame;
        document_.sets = std::move(imported.sets);
        document_.solver = imported.settings;
        record("import recipe", std::move(before));
        sets_changed();
        state_.message = "imported " + path + " (" + std::to_string(imported.iterations) +
                         " iterations in the file: Step runs them)";
        return true;
    }
    catch (const InvalidInputError& e)
    {
        state_.message = e.what();
        return false;
    }
}

void EditorSession::play(int frames)
{
    if (run_open_ || gesture_ != nullptr)
        return;
    update(); // the recipe restarted if it changed
    if (!problems_.empty())
    {
        state_.message = "cannot solve: " + problems_.front();
        return;
    }
    run_before_ = capture(document_, kPositions);
    run_open_ = true;
    solver_.set_playing(true, frames);
}

void EditorSession::pause()
{
    if (!run_open_)
        return;
    solver_.set_playing(false);
    solver_.wait_idle();
    close_run();
}

bool EditorSession::take_frame()
{
    const bool published = solver_.wait_published();
    update();
    return published;
}

void EditorSession::close_run()
{
    if (!run_open_)
        return;
    run_open_ = false; // before update(), which closes a converged run
    solver_.set_playing(false);
    solver_.wait_idle();
    update(); // the last frame's positions
    const int steps = document_.steps_from_base - (run_before_ ? *run_before_->steps_from_base : 0);
    record("solve " + std::to_string(steps) + " steps", std::move(*run_before_));
    run_before_.reset();
}

void EditorSession::step(int n)
{
    if (gesture_ != nullptr || n <= 0)
        return;
    close_run();
    update();
    if (!problems_.empty())
    {
        state_.message = "cannot solve: " + problems_.front();
        return;
    }
    EditState before = capture(document_, kPositions);
    solver_.step_now(n);
    update();
    record("step " + std::to_string(n), std::move(before));
}

void EditorSession::reset_shape()
{
    if (gesture_ != nullptr)
        return;
    close_run();
    EditState before = capture(document_, kPositions);
    document_.mesh.positions = document_.base_positions;
    positions_changed();
    start_from_base();
    record("reset shape", std::move(before));
}

void EditorSession::apply_shape()
{
    if (gesture_ != nullptr)
        return;
    close_run();
    EditState before = capture(document_, kPositions | kBasePositions);
    document_.base_positions = document_.mesh.positions;
    start_from_base();
    record("apply shape", std::move(before));
}

void EditorSession::start_from_base()
{
    // The shape is the base: no steps from it, and the solver starts a run there.
    document_.steps_from_base = 0;
    document_.reproducible = true;
    recipe_dirty_ = true;
    restarted_.reset();
}

void EditorSession::add_noise(Scalar sigma, std::uint64_t seed)
{
    if (gesture_ != nullptr || !(sigma >= 0) || !std::isfinite(sigma))
        return;
    close_run();
    EditState before = capture(document_, kPositions | kBasePositions);
    // In the file's numbering, so that the same seed gives meshfair-cli noise's shape.
    const Scalar unit = mean_edge_length(document_.topology, document_.mesh.positions);
    Mesh noisy = file_order_mesh(document_);
    add_gaussian_noise(noisy, sigma * unit, seed);
    for (size_t k = 0; k < document_.order.vertex_order.size(); ++k)
        for (size_t a = 0; a < 3; ++a)
            document_.mesh.positions[3 * k + a] =
                noisy.positions[3 * static_cast<size_t>(document_.order.vertex_order[k]) + a];
    document_.base_positions = document_.mesh.positions;
    positions_changed();
    start_from_base();
    record("noise", std::move(before));
}

void EditorSession::set_heat_map(std::optional<EnergyTerm> term)
{
    state_.heat_map = term;
    solver_.set_heat(term);
    if (!term)
        state_.display.vertex_colors = false;
}

void EditorSession::wait_for_heat()
{
    update(); // a pending restart first
    solver_.wait_idle();
    update();
}

void EditorSession::update()
{
    if (recipe_dirty_)
    {
        recipe_dirty_ = false;
        if (!problems_.empty())
        {
            solver_.clear();
            restarted_.reset();
        }
        else
        {
            const std::vector<ConstraintSet>& sets = document_.sets;
            const SolverSettings& settings = document_.solver;
            if (restarted_ && same_run(sets, settings, restarted_->sets, restarted_->solver, false))
            {
                // Names, colours, visibility or the pace changed: nothing for the solver.
            }
            else if (restarted_ &&
                     same_run(sets, settings, restarted_->sets, restarted_->solver, true))
            {
                // Only the pins moved: new right-hand sides, the run goes on.
                const Recipe recipe =
                    build_recipe(sets, settings, document_.mesh, document_.base_positions, 0);
                std::vector<Scalar> targets;
                for (const Vec3& t : recipe.hard->targets)
                    targets.insert(targets.end(), t.begin(), t.end());
                if (targets.empty()) // no set has targets any more: the pins' base places
                    for (const Index v : recipe.hard->vertices)
                        for (size_t a = 0; a < 3; ++a)
                            targets.push_back(
                                document_.base_positions[3 * static_cast<size_t>(v) + a]);
                solver_.move_hard_targets(targets);
                if (document_.steps_from_base > 0)
                    document_.reproducible = false;
                restarted_ = RunInputs{sets, settings};
            }
            else
            {
                // From the base (the recipe's input shape), starting at the current positions.
                const bool at_base = document_.steps_from_base == 0;
                solver_.restart(
                    base_mesh(), document_.order,
                    build_recipe(sets, settings, document_.mesh, document_.base_positions, 0),
                    at_base ? std::vector<Scalar>{} : document_.mesh.positions,
                    document_.draw_data.vertex_face_offsets, document_.draw_data.vertex_faces);
                if (!at_base)
                    document_.reproducible = false;
                steps_at_restart_ = document_.steps_from_base;
                restarted_ = RunInputs{sets, settings};
                if (run_open_)
                    solver_.set_playing(true);
            }
        }
    }
    if (solver_.take(incoming_, display_))
    {
        std::swap(incoming_, document_.mesh.positions);
        document_.steps_from_base = steps_at_restart_ + solver_.status().steps;
        geometry_changed(true); // the solver's thread computed the normals: only uploads here
    }
    if (state_.heat_map && solver_.take_heat(heat_))
    {
        renderer_.set_vertex_colors(heat_);
        state_.display.vertex_colors = true;
    }
    if (run_open_ && !solver_.status().playing && solver_.status().ready)
        close_run(); // converged
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
    if (r.create_set)
        create_set(*r.create_set);
    if (r.set_edit)
    {
        using What = UiRequests::SetEdit::What;
        const UiRequests::SetEdit& e = *r.set_edit;
        switch (e.what)
        {
            case What::Delete:
                delete_set(e.index);
                break;
            case What::Rename:
                rename_set(e.index, e.name);
                break;
            case What::Show:
                set_visible(e.index, e.visible);
                break;
            case What::Color:
                set_color(e.index, e.color);
                break;
            case What::Select:
                select_set(e.index);
                break;
            case What::Direction:
                set_normal_direction(e.index, e.direction);
                break;
        }
    }
    if (r.solver)
        set_solver_settings(*r.solver, r.solver_merge);
    if (r.play)
        play();
    if (r.pause)
        pause();
    if (r.step)
        step(document_.solver.iterations_per_frame);
    if (r.reset_shape)
        reset_shape();
    if (r.apply_shape)
        apply_shape();
    if (r.heat_map)
        set_heat_map(*r.heat_map);
    if (r.recover)
    {
        recover();
        state_.recovery_saved_at.reset();
    }
    if (r.discard_recovery)
        discard_recovery();
    if (r.noise)
        add_noise(r.noise->first, r.noise->second);
    if (r.export_recipe_path)
        export_recipe(*r.export_recipe_path);
    if (r.import_recipe_path)
        import_recipe(*r.import_recipe_path);
    if (r.seal_history)
        history_.seal();
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
    run_open_ = false;
    run_before_.reset();
    solver_.clear();
    restarted_.reset();
    recipe_dirty_ = true;
    problems_ = constraint_problems(document_.sets, document_.solver);
    border_ = region_border(document_);
    glyphs_dirty_ = true;
    history_.clear();
    step_before_.reset();
    selection_changed();
}

bool EditorSession::save(const std::string& path)
{
    try
    {
        io::write_mesh(file_order_mesh(document_), path); // the file's numbering, kept
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
    state_.solver = solver_.status();
    if (state_.solver.energy_version != shown_energy_version_) // the curve, once per change
    {
        state_.energies = solver_.energies();
        shown_energy_version_ = state_.solver.energy_version;
    }
    state_.problems = problems_;
    state_.playing = run_open_;
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
    return {camera_.view_matrix(), camera_.projection_matrix(aspect()), view_.width, view_.height,
            geometry_};
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
    if (glyphs_dirty_)
    {
        const std::vector<GlyphGroup> glyphs = constraint_glyphs(document_, border_);
        renderer_.set_glyphs(glyphs);
        glyphs_dirty_ = false;
    }
}

void EditorSession::draw()
{
    sync_renderer();
    renderer_.draw(camera_, state_.display, view_);
}

} // namespace meshfair::app
