// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_session.h"
#include "app/editor/user_files.h"

#include <algorithm>
#include <utility>

#include "app/editor/constraint_glyphs.h"
#include "app/editor/editor_ui.h"
#include "app/editor/script.h"
#include "app/editor/weight_paint.h"
#include "app/tools/selection_gesture.h"
#include "core/geometry/face_geometry.h"

namespace meshfair::app {

EditorSession::EditorSession(Document document, Renderer& renderer)
    : document_(std::move(document)), renderer_(renderer), solver_(document_, history_)
{
    renderer_.set_mesh(document_.mesh, document_.draw_data);
}

EditorSession::~EditorSession() = default;

double EditorSession::aspect() const
{
    return double(view_.width) / std::max(view_.height, 1);
}

ToolContext EditorSession::tool_context()
{
    ToolContext c;
    c.view = ToolView{&document_.mesh,
                      &renderer_,
                      &camera_,
                      view_,
                      [this]() -> const Visibility& { return visibility(); },
                      [this] { return face_points(); }};
    c.settings = state_.tools;
    c.pin_handles = [this] { return grab_handles(ToolKind::MovePins); };
    c.normal_handles = [this] { return grab_handles(ToolKind::AimNormals); };
    if (state_.tool == ToolKind::MovePins)
        c.dome = dome_settings(document_.sets, document_.solver);
    return c;
}

std::vector<GrabHandle> EditorSession::pin_handles() const
{
    std::vector<GrabHandle> handles;
    for (const ConstraintSet& s : document_.sets)
    {
        if (s.kind != ConstraintKind::Pin || !s.visible)
            continue;
        for (size_t v = 0; v < s.vertices.size(); ++v)
        {
            const size_t i = 3 * static_cast<size_t>(s.vertices[v]);
            const std::vector<Scalar>& x = document_.mesh.positions;
            handles.push_back({s.name,
                               s.targets.empty()
                                   ? glm::dvec3(x[i], x[i + 1], x[i + 2])
                                   : glm::dvec3(s.targets[v][0], s.targets[v][1], s.targets[v][2]),
                               {0, 0, 1},
                               std::nullopt});
        }
    }
    return handles;
}

std::vector<GrabHandle> EditorSession::normal_handles() const
{
    // The arrows the glyphs show, whole (normal_arrows), each with its set's mean normal: the
    // direction a drag turns.
    std::vector<GrabHandle> handles;
    for (const ConstraintSet& s : document_.sets)
    {
        if (!s.visible)
            continue;
        const std::vector<NormalArrow> arrows = normal_arrows(document_, s);
        if (arrows.empty())
            continue;
        const Vec3 direction = set_mean_normal(document_.mesh, document_.mesh.positions, s);
        for (const NormalArrow& a : arrows)
            handles.push_back({s.name,
                               {a.base[0], a.base[1], a.base[2]},
                               direction,
                               glm::dvec3(a.tip[0], a.tip[1], a.tip[2])});
    }
    return handles;
}

void EditorSession::mouse_press(MouseButton button, Modifiers mods, double x, double y)
{
    end_interaction(); // what this press starts is a step of its own
    cursor_ = {x, y, 0};
    cursor_in_view_ = true;
    if (gesture_ != nullptr || navigator_.dragging())
        return;
    // Alt + left always navigates, so a tool never locks the view.
    InteractiveTool* tool = tools_.find(state_.tool);
    if (button == MouseButton::Left && !mods.alt && tool != nullptr)
    {
        std::vector<Command> out;
        stroke_.clear();
        if (tool->press(tool_context(), mods, cursor_, out))
        {
            gesture_ = tool;
            for (const Command& c : out)
                dispatch(c, kGesture);
            return;
        }
    }
    navigator_.press(button, mods.alt && button == MouseButton::Left ? Modifiers{} : mods, x, y);
}

void EditorSession::mouse_move(double x, double y, bool in_view)
{
    cursor_ = {x, y, 0};
    cursor_in_view_ = in_view || gesture_ != nullptr || navigator_.dragging();
    if (gesture_ != nullptr)
    {
        std::vector<Command> out;
        gesture_->move(cursor_, out);
        for (const Command& c : out)
            dispatch(c, kGesture);
    }
    else
        navigator_.move(camera_, state_.orbit, x, y, view_.width, view_.height);
}

const std::vector<GrabHandle>& EditorSession::grab_handles(ToolKind tool)
{
    const auto key = std::make_tuple(tool, document_.versions.sets, document_.versions.positions);
    if (grab_cache_.key != key)
    {
        grab_cache_.handles = tool == ToolKind::MovePins ? pin_handles() : normal_handles();
        grab_cache_.key = key;
    }
    return grab_cache_.handles;
}

std::vector<ScreenPoint> EditorSession::grab_hover()
{
    const bool grabs = state_.tool == ToolKind::MovePins || state_.tool == ToolKind::AimNormals;
    if (!grabs || gesture_ != nullptr || navigator_.dragging() || !cursor_in_view_)
        return {};
    // The same handles and the same choice as the tool's press (nearest_handle), from the
    // camera of this frame: the highlight follows a zoom or a key's view too.
    const Grabbed grabbed = nearest_handle(grab_handles(state_.tool), camera_, view_, cursor_);
    if (grabbed.handle == nullptr)
        return {};
    const auto on_screen = [&](const glm::dvec3& p) {
        const glm::dvec3 w = camera_.project(p, view_.width, view_.height);
        return ScreenPoint{w.x + view_.x, w.y + view_.y, 0};
    };
    std::vector<ScreenPoint> ends{on_screen(grabbed.handle->point)};
    if (grabbed.handle->tip)
        ends.push_back(on_screen(*grabbed.handle->tip));
    return ends;
}

void EditorSession::mouse_release(MouseButton button, double x, double y)
{
    cursor_ = {x, y, 0};
    if (gesture_ != nullptr && button == MouseButton::Left)
    {
        std::vector<Command> out;
        InteractiveTool* tool = std::exchange(gesture_, nullptr);
        tool->release(cursor_, out);
        // Still part of the gesture's step, which ends with it.
        for (const Command& c : out)
            dispatch(c, kGesture);
        end_interaction();
        if (trace_ != nullptr)
        {
            // What the gesture made: the selection it leaves, or its command's message;
            // then the history's length (one step more per gesture).
            const auto selected = [](const SelectionMask& m) {
                return static_cast<size_t>(std::count(m.begin(), m.end(), 1));
            };
            const std::string made =
                dynamic_cast<const SelectionGesture*>(tool) != nullptr
                    ? std::to_string(selected(document_.selected_vertices)) + " vertices and " +
                          std::to_string(selected(document_.selected_faces)) + " faces selected"
                    : state_.message;
            std::fprintf(trace_, "gesture %s: %s%shistory: %zu undo steps\n", tool->gesture_name(),
                         made.c_str(), made.empty() ? "" : "; ", history_.undo_count());
            if (!stroke_.empty())
                std::fprintf(trace_, "stroke %s\n", stroke_action(stroke_).c_str());
            std::fflush(trace_);
        }
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
    const InteractiveTool* tool = tools_.find(state_.tool);
    if (tool == nullptr || (!cursor_in_view_ && gesture_ == nullptr))
        return {};
    return tool->overlay(cursor_, state_.tools, gesture_ == tool);
}

std::optional<size_t> EditorSession::set_named(const std::string& name) const
{
    for (size_t k = 0; k < document_.sets.size(); ++k)
        if (document_.sets[k].name == name)
            return k;
    return std::nullopt;
}

bool EditorSession::take_frame()
{
    const bool published = solver_.take_frame();
    update();
    return published;
}

void EditorSession::wait_for_heat()
{
    solver_.wait_for_heat();
    update();
}

void EditorSession::settle_solver()
{
    solver_.settle();
    update();
}

void EditorSession::set_trace(std::FILE* out)
{
    trace_ = out;
    listen_to_preparation();
}

void EditorSession::observe_preparation(
    std::function<void(const PreparationProgress::Snapshot&)> observer)
{
    preparation_observer_ = std::move(observer);
    listen_to_preparation();
}

void EditorSession::listen_to_preparation()
{
    if (trace_ == nullptr && !preparation_observer_)
        return solver_.set_phase_listener(nullptr);
    // Each phase as it begins, on the solver's thread (stdio locks the stream per call).
    solver_.set_phase_listener(
        [out = trace_, observer = preparation_observer_](const PreparationProgress::Snapshot& p) {
            if (out != nullptr && p.phase == PreparationProgress::Phase::Ordering)
                std::fprintf(out, "solver: preparing: ordering %lld unknowns\n",
                             static_cast<long long>(p.unknowns));
            if (out != nullptr && p.phase == PreparationProgress::Phase::Factoring)
                std::fprintf(out, "solver: preparing: factoring %.3g Gflop\n", p.flops / 1e9);
            if (out != nullptr)
                std::fflush(out);
            if (observer)
                observer(p);
        });
}

void EditorSession::settle_preparation()
{
    solver_.settle_preparation();
    update();
}

void EditorSession::update()
{
    // The plot's relative gradient costs a pass a frame where the step does not sum it:
    // only while the plot is shown.
    if (synced_.plot_gradient != state_.show_energy)
    {
        synced_.plot_gradient = state_.show_energy;
        solver_.set_plot_gradient(state_.show_energy);
    }
    const bool was_playing = solver_.playing();
    if (solver_.update())
    {
        renderer_.update_geometry(solver_.display());
        synced_.positions = document_.versions.positions; // uploaded, normals and all
    }
    if (state_.heat_map && solver_.take_heat(heat_))
    {
        renderer_.set_vertex_colors(heat_);
        state_.display.vertex_colors = true;
    }
    if (trace_ != nullptr && was_playing && !solver_.playing())
    {
        // With a tolerance, where the gradient stood (relative to the run's start) and
        // whether the run stopped on it.
        const SolverStatus st = solver_.status();
        if (st.relative_gradient >= 0)
            std::fprintf(
                trace_, "run stopped: %d steps from the base, gradient %.3g of the start's%s\n",
                document_.steps_from_base, st.relative_gradient, st.converged ? ", converged" : "");
        else
            std::fprintf(trace_, "run stopped: %d steps from the base\n",
                         document_.steps_from_base);
        // What the plot shows of the run: the energy of what moves and the whole mesh's.
        const std::vector<EnergySample> e = solver_.energies();
        if (e.size() >= 2)
        {
            const auto moving = [](const EnergySample& s) {
                return s.energy.total() - s.held.total();
            };
            std::fprintf(trace_, "energy of what moves: %.6g -> %.6g; whole mesh: %.6g -> %.6g\n",
                         moving(e.front()), moving(e.back()), e.front().energy.total(),
                         e.back().energy.total());
        }
        std::fflush(trace_);
    }
    if (trace_ != nullptr && solver_.solves_shown() > solves_traced_)
    {
        // The direct method's minimizer is on screen (after a restart, or pins moved).
        solves_traced_ = solver_.solves_shown();
        std::fprintf(trace_, "solved: the minimizer, %d steps from the base\n",
                     document_.steps_from_base);
        std::fflush(trace_);
    }
}

void EditorSession::apply_up_axis(UpAxis up)
{
    camera_.up_axis = up;
    document_.up_axis = up;
    camera_.set_view(StandardView::Front);
    camera_.frame(document_.box, aspect());
    if (!state_.offscreen) // remembered for the file (an offscreen run is a test's)
        save_up_axis(up_axes_path(), document_.path, up);
}

void EditorSession::autosave(double interval_s)
{
    document_.up_axis = camera_.up_axis;
    // Not while playing: the run's start is saved, and writing the positions of a large
    // mesh every few seconds would stall the frames; the end of the run is saved after it.
    if (solver_.playing())
        return;
    const std::string error = autosaver_.autosave(document_, interval_s);
    if (!error.empty())
    {
        state_.message = error;
        state_.message_is_error = true;
    }
}

void EditorSession::end_session()
{
    end_interaction();
    solver_.pause();
    autosaver_.end_session();
}

void EditorSession::reset_for_document()
{
    visibility_.reset(); // another mesh
    face_points_.reset();
    solver_.clear();
    history_.clear();
    open_step_.reset();
    gesture_ = nullptr;
    synced_ = {};
    grab_cache_ = {}; // (a new document's versions start again)
    autosaver_.forget();
}

void EditorSession::prepare_ui()
{
    state_.overlay = tool_overlay();
    for (ScreenPoint& p : state_.overlay.points)
    {
        p.x += view_.x;
        p.y += view_.y;
    }
    state_.grab_hover = grab_hover();
    state_.solver = solver_.status();
    if (synced_.energy != state_.solver.energy_version) // the curve, once per change
    {
        state_.energies = solver_.energies();
        synced_.energy = state_.solver.energy_version;
    }
    state_.problems = solver_.problems();
    if (trace_ != nullptr && synced_.preparing && !state_.solver.preparing &&
        state_.solver.cancelled)
    {
        std::fprintf(trace_, "solver: preparation cancelled\n");
        std::fflush(trace_);
    }
    synced_.preparing = state_.solver.preparing;
    if (synced_.restarts != state_.solver.restarts)
    {
        // What the new run does besides the recipe's letter (open components' volumes kept
        // by their capped boundary loops, ...): in the trace, and in the status bar unless
        // an error is there.
        synced_.restarts = state_.solver.restarts;
        // A restart the recipe did not fit (a free part nothing holds, under the direct
        // method): said in the status line, where the artist looks after pressing Space.
        // And a recipe without a unique minimizer, for which the panel greys "until
        // converged".
        const SolverStatus& st = state_.solver;
        if (!st.error.empty())
        {
            state_.message = "cannot solve: " + st.error;
            state_.message_is_error = true;
        }
        if (trace_ != nullptr && !st.error.empty())
            std::fprintf(trace_, "solver failed: %s\n", st.error.c_str());
        if (trace_ != nullptr && st.factor_ms > 0)
            std::fprintf(trace_, "solver: factored%s\n",
                         st.analysis_kept ? " on the analysis kept" : " after its analysis");
        if (trace_ != nullptr && !st.no_minimizer.empty())
            std::fprintf(trace_, "solver: no minimizer: %s\n", st.no_minimizer.c_str());
        state_.run_notes = solver_.notes();
        std::string told;
        for (const std::string& note : state_.run_notes)
        {
            told += (told.empty() ? "" : "; ") + note;
            if (trace_ != nullptr)
                std::fprintf(trace_, "run note: %s\n", note.c_str());
        }
        if (trace_ != nullptr && !told.empty())
            std::fflush(trace_);
        if (!told.empty() && !(state_.message_is_error && !state_.message.empty()))
        {
            state_.message = told;
            state_.message_is_error = false;
        }
    }
    const std::pair<std::uint64_t, std::uint64_t> directions_key{document_.versions.sets,
                                                                 document_.versions.positions};
    if (synced_.directions != directions_key &&
        (!synced_.directions || synced_.directions->first != directions_key.first ||
         !state_.solver.playing))
    {
        state_.set_directions.clear();
        for (const ConstraintSet& s : document_.sets)
            state_.set_directions.push_back(
                kind_info(s.kind).normals
                    ? set_mean_normal(document_.mesh, document_.mesh.positions, s)
                    : Vec3{0, 0, 1});
        synced_.directions = directions_key;
    }
    if (synced_.notes != document_.versions.set_members)
    {
        state_.notes = constraint_notes(document_.sets);
        state_.region_holes.clear();
        // A painted region fades to 0 at its edge, where a vertex left out is no spike.
        for (const ConstraintSet& s : document_.sets)
            if (s.kind == ConstraintKind::Region && s.weights.empty())
                if (const size_t n = region_holes(s, document_.mesh, document_.topology).size())
                {
                    state_.region_holes.emplace_back(s.name, n);
                    state_.notes.push_back(
                        "region '" + s.name + "' leaves out " + std::to_string(n) +
                        " vertices it encloses (hidden from the view when selected): they "
                        "would stay fixed among moving ones; 'close holes' takes them in");
                }
        synced_.notes = document_.versions.set_members;
    }
    state_.playing = solver_.playing();
    HistoryStatus& h = state_.history;
    h.undo_count = history_.undo_count();
    h.redo_count = history_.redo_count();
    h.undo_label = history_.undo_label();
    h.redo_label = history_.redo_label();
    h.bytes = history_.bytes();
    h.limit = history_.limit();
    h.dropped = history_.dropped();
    if (synced_.counts != document_.versions.selection)
    {
        state_.selected_vertices = static_cast<std::size_t>(
            std::count(document_.selected_vertices.begin(), document_.selected_vertices.end(), 1));
        state_.selected_faces = static_cast<std::size_t>(
            std::count(document_.selected_faces.begin(), document_.selected_faces.end(), 1));
        synced_.counts = document_.versions.selection;
    }
}

EditorSession::VisibilityKey EditorSession::view_key() const
{
    return {camera_.view_matrix(), camera_.projection_matrix(aspect()), view_.width, view_.height,
            document_.versions.positions};
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
        sync_renderer(); // the ID buffer of the positions shown
        visibility_ = renderer_.visibility(camera_, view_);
        visibility_key_ = key;
    }
    return *visibility_;
}

void EditorSession::sync_renderer()
{
    const DocumentVersions& v = document_.versions;
    if (synced_.positions != v.positions)
    {
        renderer_.update_positions(document_.mesh.positions);
        synced_.positions = v.positions;
    }
    if (synced_.selection != v.selection)
    {
        renderer_.set_selection(document_.selected_vertices, document_.selected_faces);
        synced_.selection = v.selection;
    }
    // The border ring depends on which vertices the regions hold, not on where pins go.
    if (synced_.border != v.set_members)
    {
        border_ = region_border(document_);
        synced_.border = v.set_members;
    }
    // The weight map being painted, in colour while the Paint tool is on (not over a heat
    // map, which was asked for); that set's dots are then left out of the glyphs.
    const bool painting = state_.tool == ToolKind::Paint && !state_.heat_map;
    const std::string painted = !painting                        ? std::string()
                                : state_.tools.paint.set.empty() ? std::string(kPaintSet)
                                                                 : state_.tools.paint.set;
    if (painting)
    {
        const std::string& name = painted;
        const std::pair<std::uint64_t, std::string> key{v.sets, name};
        if (synced_.weights != key)
        {
            const std::optional<size_t> k = set_named(name);
            renderer_.set_vertex_colors(weight_colors(k ? document_.sets[*k] : ConstraintSet{},
                                                      document_.mesh.vertex_count(),
                                                      state_.display.surface_color));
            state_.display.vertex_colors = true;
            synced_.weights = key;
        }
    }
    else if (synced_.weights)
    {
        synced_.weights.reset();
        if (!state_.heat_map)
        {
            renderer_.set_vertex_colors({});
            state_.display.vertex_colors = false;
        }
    }
    const bool sets_changed = synced_.glyphs_sets != v.sets;
    // Glyphs sit on the surface: they follow the positions when there are sets.
    if (sets_changed || synced_.glyphs_hidden != painted ||
        (synced_.glyphs_positions != v.positions && !document_.sets.empty()))
    {
        renderer_.set_glyphs(constraint_glyphs(document_, border_, painted));
        synced_.glyphs_hidden = painted;
        synced_.glyphs_sets = v.sets;
        synced_.glyphs_positions = v.positions;
    }
}

void EditorSession::draw()
{
    sync_renderer();
    renderer_.draw(camera_, state_.display, view_);
}

void EditorSession::remember(const std::string& path)
{
    // An offscreen run (a script, a test) leaves the user's recent files alone.
    if (state_.offscreen)
        return;
    remember_recent(state_.recent, path);
    save_recent(recent_files_path(), state_.recent);
}

} // namespace meshfair::app
