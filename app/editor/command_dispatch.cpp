// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// EditorSession::dispatch: the one place every editor action is carried out.
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "app/editor/command_executor.h"
#include "app/editor/editor_session.h"
#include "app/editor/editor_ui.h"
#include "app/editor/user_files.h"
#include "app/tools/selection_commands.h"
#include "core/errors.h"
#include "core/geometry/noise.h"

namespace meshfair::app {

// --- Selection and tools.
bool CommandExecutor::operator()(const cmd::SetTool& c) const
{
    st.tool = c.tool;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetElements& c) const
{
    st.tools.elements = c.elements;
    return true;
}

bool CommandExecutor::operator()(const cmd::ToggleElements&) const
{
    st.tools.elements =
        st.tools.elements == ElementKind::Vertices ? ElementKind::Faces : ElementKind::Vertices;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetThrough& c) const
{
    st.tools.through = c.through;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetBrushRadius& c) const
{
    st.tools.brush_radius_px = std::clamp(c.pixels, 1.0, 1000.0);
    return true;
}

bool CommandExecutor::operator()(const cmd::ScaleBrushRadius& c) const
{
    st.tools.brush_radius_px = std::clamp(st.tools.brush_radius_px * c.factor, 2.0, 400.0);
    return true;
}

bool CommandExecutor::operator()(const cmd::RunSelection& c) const
{
    run_selection_command(c.command, st.tools.elements, d.mesh, d.topology, d.selected_vertices,
                          d.selected_faces);
    return true;
}

bool CommandExecutor::operator()(const cmd::ApplySelection& c) const
{
    SelectionMask& mask =
        c.elements == ElementKind::Vertices ? d.selected_vertices : d.selected_faces;
    for (const Index i : c.indices)
        if (i < 0 || static_cast<size_t>(i) >= mask.size())
            throw InvalidInputError("selection index " + std::to_string(i) + " is out of range");
    if (c.op == SelectOp::Replace)
        std::fill(mask.begin(), mask.end(), 0);
    apply_selection(mask, c.indices,
                    c.op == SelectOp::Subtract ? SelectOp::Subtract : SelectOp::Add);
    return true;
}

// --- History.
bool CommandExecutor::travel(bool back) const
{
    const unsigned parts = back ? s.history_.undo(d) : s.history_.redo(d);
    if (parts == 0)
        return false;
    s.after_history(parts);
    say(back ? "undid " + s.history_.redo_label() : "redid " + s.history_.undo_label());
    return true;
}

// --- The view.
bool CommandExecutor::operator()(const cmd::FrameAll&) const
{
    s.camera_.frame(d.box, s.aspect());
    return true;
}

bool CommandExecutor::operator()(const cmd::FrameSelection&) const
{
    s.camera_.frame(selection_box(d), d.box, s.aspect());
    return true;
}

bool CommandExecutor::operator()(const cmd::SetView& c) const
{
    s.camera_.set_view(c.view);
    return true;
}

bool CommandExecutor::operator()(const cmd::SetProjection& c) const
{
    s.camera_.projection = c.projection;
    return true;
}

bool CommandExecutor::operator()(const cmd::ToggleProjection&) const
{
    s.camera_.projection = s.camera_.projection == Projection::Perspective
                               ? Projection::Orthographic
                               : Projection::Perspective;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetOrbit& c) const
{
    st.orbit = c.orbit;
    return true;
}

bool CommandExecutor::operator()(const cmd::ToggleOrbit&) const
{
    st.orbit = st.orbit == OrbitStyle::Turntable ? OrbitStyle::Trackball : OrbitStyle::Turntable;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetUpAxis& c) const
{
    s.apply_up_axis(c.up);
    return true;
}

bool CommandExecutor::operator()(const cmd::Toggle& c) const
{
    DisplayOptions& o = st.display;
    switch (c.what)
    {
        case cmd::DisplayToggle::Shading:
            o.shading = o.shading == Shading::Smooth ? Shading::Flat : Shading::Smooth;
            break;
        case cmd::DisplayToggle::Wireframe:
            o.wireframe = !o.wireframe;
            break;
        case cmd::DisplayToggle::BoundaryEdges:
            o.boundary_edges = !o.boundary_edges;
            break;
        case cmd::DisplayToggle::VertexPoints:
            o.vertex_points = !o.vertex_points;
            break;
        case cmd::DisplayToggle::BackFaceTint:
            o.back_face_tint = !o.back_face_tint;
            break;
        case cmd::DisplayToggle::SidePanel:
            st.show_side_panel = !st.show_side_panel;
            break;
        case cmd::DisplayToggle::Help:
            st.show_help = !st.show_help;
            break;
        case cmd::DisplayToggle::EnergyPlot:
            st.show_energy = !st.show_energy;
            break;
        case cmd::DisplayToggle::EnergyLogScale:
            st.energy_log_scale = !st.energy_log_scale;
            break;
        case cmd::DisplayToggle::EnergyWholeMesh:
            st.energy_whole_mesh = !st.energy_whole_mesh;
            break;
    }
    return true;
}

bool CommandExecutor::operator()(const cmd::SetDisplay& c) const
{
    const bool colors = st.display.vertex_colors; // the heat map's, not the panel's
    st.display = c.display;
    st.display.vertex_colors = colors;
    return true;
}

// --- Solving.
bool CommandExecutor::operator()(const cmd::SetSolverSettings& c) const
{
    if (c.settings == d.solver)
        return false;
    d.solver = c.settings;
    s.solver_.set_iterations_per_frame(c.settings.iterations_per_frame);
    return true;
}

bool CommandExecutor::operator()(const cmd::Play& c) const
{
    std::string why;
    return s.solver_.play(c.frames, why) || fail(why);
}

bool CommandExecutor::operator()(const cmd::Pause&) const
{
    s.solver_.pause();
    return true;
}

bool CommandExecutor::operator()(const cmd::TogglePlay&) const
{
    if (s.solver_.playing())
        return (*this)(cmd::Pause{});
    return (*this)(cmd::Play{});
}

bool CommandExecutor::operator()(const cmd::Step& c) const
{
    const int n = c.steps > 0 ? c.steps : d.solver.iterations_per_frame;
    std::string why;
    if (!s.solver_.step(n, why))
        return fail(why);
    s.open_step_->label = "step " + std::to_string(n);
    s.update();
    return true;
}

bool CommandExecutor::operator()(const cmd::Solve&) const
{
    if (solves_for_minimizer(d.solver.method))
    {
        if (s.solver_.prepare_again())
        {
            say("solving for the minimizer of the sets again (method: direct)");
            return true;
        }
        say("the shape is the minimizer of the sets (method: direct)");
        return false;
    }
    SolverSettings settings = d.solver;
    settings.method = Method::Direct;
    // What the direct method does not take would leave nothing to show (the volume it
    // keeps: the minimizer under it).
    settings.optimal_step = false;
    settings.joint = false;
    d.solver = settings;
    say("solving for the minimizer of the sets (method: direct)");
    return true;
}

bool CommandExecutor::operator()(const cmd::CancelPreparation&) const
{
    if (!s.solver_.cancel_preparation())
    {
        say("nothing to cancel: the solver is not preparing");
        return false;
    }
    say("preparation cancelled: the shape is as it was; Solve (Enter), Play or Step "
        "prepares again");
    return true;
}

bool CommandExecutor::operator()(const cmd::ResetShape&) const
{
    d.mesh.positions = d.base_positions;
    s.solver_.start_from_base();
    return true;
}

bool CommandExecutor::operator()(const cmd::ApplyShape&) const
{
    d.base_positions = d.mesh.positions;
    s.solver_.start_from_base();
    return true;
}

bool CommandExecutor::operator()(const cmd::AddNoise& c) const
{
    if (!(c.sigma >= 0) || !std::isfinite(c.sigma))
        return fail("the noise's sigma must be a number >= 0");
    // In the file's numbering, so that the same seed gives meshfair-cli noise's shape.
    const Scalar unit = mean_edge_length(d.topology, d.mesh.positions);
    Mesh noisy = file_order_mesh(d);
    add_gaussian_noise(noisy, c.sigma * unit, c.seed);
    for (size_t k = 0; k < d.order.vertex_order.size(); ++k)
        for (size_t a = 0; a < 3; ++a)
            d.mesh.positions[3 * k + a] =
                noisy.positions[3 * static_cast<size_t>(d.order.vertex_order[k]) + a];
    d.base_positions = d.mesh.positions;
    s.solver_.start_from_base();
    return true;
}

bool CommandExecutor::operator()(const cmd::SetHeatMap& c) const
{
    st.heat_map = c.term;
    s.solver_.set_heat(c.term);
    s.synced_.weights.reset(); // a painted map shows again when the heat map goes
    if (!c.term)
        st.display.vertex_colors = false;
    return true;
}

// --- Files and the program.
bool CommandExecutor::operator()(const cmd::OpenMesh& c) const
{
    Document next = load_document(c.path); // on failure the document stays
    s.renderer_.set_mesh(next.mesh, next.draw_data);
    d = std::move(next);
    s.reset_for_document();
    // The up axis this file was last seen with.
    s.camera_.up_axis = load_up_axis(up_axes_path(), c.path).value_or(s.camera_.up_axis);
    d.up_axis = s.camera_.up_axis;
    s.camera_.set_view(StandardView::Front);
    s.camera_.frame(d.box, s.aspect());
    s.remember(c.path);
    st.recovery_saved_at.reset();
    if (const std::optional<RecoveryInfo> offer = s.recovery_offer())
        st.recovery_saved_at = offer->saved_at;
    say("opened " + c.path);
    return true;
}

bool CommandExecutor::operator()(const cmd::SaveMesh& c) const
{
    const std::string path = c.path.empty() ? d.path : c.path;
    const std::vector<std::string> notes = save_document(d, path);
    s.remember(path);
    if (!st.offscreen) // the copy opens as this one shows (Save As)
        save_up_axis(up_axes_path(), path, s.camera_.up_axis);
    std::string message = "saved " + path;
    for (const std::string& note : notes) // what the format could not hold, never silent
        message += "; " + note;
    say(message);
    return true;
}

bool CommandExecutor::operator()(const cmd::ExportRecipe& c) const
{
    if (!s.problems().empty())
        return fail("cannot export the recipe: " + s.problems().front());
    export_recipe(d, c.path);
    say("exported " + c.path +
        (d.reproducible ? std::string(" (reproduces the shape from the base)")
                        : std::string(" (the recipe changed during the run: Reset and run "
                                      "again for a recipe that reproduces the shape)")));
    return true;
}

bool CommandExecutor::operator()(const cmd::ImportRecipe& c) const
{
    ImportedRecipe imported = import_recipe(d, c.path);
    d.sets = std::move(imported.sets);
    // A recipe says nothing of the pace; the editor's own settings do.
    d.solver = imported.editor ? imported.settings : with_pace(imported.settings, d.solver);
    if (imported.up && *imported.up != s.camera_.up_axis)
        s.apply_up_axis(*imported.up);
    say("imported " + c.path + " (" + std::to_string(imported.iterations) +
        " iterations in the file: Step runs them)" +
        (imported.note.empty() ? std::string() : "; " + imported.note));
    return true;
}

bool CommandExecutor::operator()(const cmd::ApplyPreset& c) const
{
    const std::string path = preset_path(c.preset);
    ImportedRecipe preset = import_recipe(d, path);
    d.sets = merge_preset(d.sets, std::move(preset.sets));
    d.solver = with_pace(preset.settings, d.solver);
    // A run plays the preset's own steps: its settings were tuned for that many.
    d.solver.steps_per_run = std::max(1, preset.iterations);
    st.preset_applied = {c.preset, d.solver};
    say("preset " + c.preset + (preset.description.empty() ? "" : " (" + preset.description + ")") +
        ": its settings, with your regions and pins" +
        (s.problems().empty() ? std::string() : " (" + s.problems().front() + ")"));
    return true;
}

bool CommandExecutor::operator()(const cmd::ShowDialog& c) const
{
    st.dialog = c.dialog;
    return true;
}

bool CommandExecutor::operator()(const cmd::Screenshot& c) const
{
    st.screenshot = c.path;
    return true;
}

bool CommandExecutor::operator()(const cmd::Quit&) const
{
    if (d.modified)
        st.quit_prompt = true;
    else
        st.quit = true;
    return true;
}

bool CommandExecutor::operator()(const cmd::QuitDiscarding&) const
{
    st.quit = true;
    return true;
}

bool CommandExecutor::operator()(const cmd::Recover&) const
{
    const RecoveryInfo info = s.autosaver_.recover(d);
    if (s.camera_.up_axis != d.up_axis) // the session's up axis with it
        s.apply_up_axis(d.up_axis);
    s.history_.clear();
    s.solver_.clear();
    d.versions.bump(kSelection | kSets | kSetMembers | kSettings | kPositions | kBasePositions);
    st.recovery_saved_at.reset();
    say("recovered the session saved at " + info.saved_at);
    return true;
}

bool CommandExecutor::operator()(const cmd::DiscardRecovery&) const
{
    s.autosaver_.discard(d);
    st.recovery_saved_at.reset();
    return true;
}

bool CommandExecutor::operator()(const cmd::Autosave&) const
{
    s.autosave(0);
    return true;
}

//! Carries out each command on the session (dispatch has done the undo bookkeeping).

bool EditorSession::dispatch(const Command& command, const Interaction& from)
{
    const CommandSpec spec = spec_of(command);
    const bool from_gesture = from.key == kGesture.key;
    document_.up_axis = camera_.up_axis; // (the file's, as the view shows it)
    if (gesture_ != nullptr && !from_gesture && spec.waits_for_gesture)
        return false;
    // A command that goes on with the open step of its interaction (a stroke's next dab)
    // keeps it; another closes it first.
    const bool continues = open_step_ && !from.key.empty() && open_step_->interaction == from.key &&
                           open_step_->label == spec.label;
    if (spec.stops_run && !continues)
    {
        close_step();
        solver_.pause();
    }
    if (spec.captures != 0)
    {
        if (open_step_ && (from.key.empty() || open_step_->interaction != from.key ||
                           open_step_->label != spec.label))
            close_step();
        if (!open_step_)
        {
            // A change of the recipe during a run: the run so far is a step of its own.
            if (solver_.playing() && (spec.captures & (kSets | kSettings)))
                solver_.segment();
            open_step_ =
                OpenStep{spec.label, spec.captures, capture(document_, spec.captures), from.key};
        }
    }
    if (!from_gesture)
        state_.message.clear(); // the status bar tells of the newest action only
    bool ok = false;
    try
    {
        ok = std::visit(CommandExecutor{*this}, command);
    }
    catch (const std::exception& e)
    {
        state_.message = e.what();
        state_.message_is_error = true;
        ok = false;
    }
    if (from_gesture && (ok || !state_.message_is_error))
        if (const auto* dab = std::get_if<cmd::PaintDab>(&command))
            stroke_.push_back(*dab);
    if (ok && spec.bumps != 0)
    {
        document_.versions.bump(spec.bumps);
        if (spec.bumps & (kPositions | kBasePositions))
            document_.modified = true;
    }
    if (from.key.empty())
        close_step();
    // A gesture's own commands are many (a dab, a move per mouse event): the trace shows
    // the gesture's end instead, and those of its commands that fail.
    if (trace_ != nullptr && (!from_gesture || (!ok && state_.message_is_error)))
    {
        // With what the command said of itself (the set made and its size, ...).
        const std::string said = !ok && state_.message_is_error  ? state_.message
                                 : ok && !state_.message.empty() ? " (" + state_.message + ")"
                                                                 : "";
        std::fprintf(trace_, "command %s: %s%s\n", std::string(command_name(command)).c_str(),
                     ok                        ? "ok"
                     : state_.message_is_error ? "failed: "
                                               : "nothing to do",
                     said.c_str());
        std::fflush(trace_);
    }
    return ok;
}

void EditorSession::end_interaction()
{
    close_step();
}

void EditorSession::close_step()
{
    if (!open_step_)
        return;
    if (solver_.stroke_running())
    {
        // A smoothing stroke's step holds its last dab's run, whole: waited for, then taken
        // as a frame takes it (uploaded), before the step is recorded.
        solver_.wait_for_stroke();
        update();
        solver_.end_stroke();
    }
    OpenStep step = std::move(*open_step_);
    open_step_.reset();
    history_.record(std::move(step.label), std::move(step.before), document_);
}

void EditorSession::after_history(unsigned parts)
{
    // The sets restored may hold other elements: their membership counts as changed.
    document_.versions.bump((parts & kSets) ? parts | kSetMembers : parts);
    if (parts & (kPositions | kBasePositions))
        document_.modified = true;
}

} // namespace meshfair::app
