// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// EditorSession::dispatch: the one place every editor action is carried out.
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "app/editor/editor_session.h"
#include "app/editor/editor_ui.h"
#include "core/errors.h"
#include "core/geometry/noise.h"

namespace meshfair::app {

//! Carries out each command on the session (dispatch has done the undo bookkeeping).
struct CommandExecutor
{
    EditorSession& s;
    Document& d = s.document_;
    EditorState& st = s.state_;

    void say(std::string message) const
    {
        st.message = std::move(message);
        st.message_is_error = false;
    }
    bool fail(std::string message) const
    {
        st.message = std::move(message);
        st.message_is_error = true;
        return false;
    }
    size_t set_index(const std::string& name) const
    {
        const std::optional<size_t> k = s.set_named(name);
        if (!k)
            throw InvalidInputError("no set named '" + name + "'");
        return *k;
    }

    // --- Selection and tools.
    bool operator()(const cmd::SetTool& c) const
    {
        st.tool = c.tool;
        return true;
    }
    bool operator()(const cmd::SetElements& c) const
    {
        st.tools.elements = c.elements;
        return true;
    }
    bool operator()(const cmd::ToggleElements&) const
    {
        st.tools.elements =
            st.tools.elements == ElementKind::Vertices ? ElementKind::Faces : ElementKind::Vertices;
        return true;
    }
    bool operator()(const cmd::SetThrough& c) const
    {
        st.tools.through = c.through;
        return true;
    }
    bool operator()(const cmd::SetBrushRadius& c) const
    {
        st.tools.brush_radius_px = std::clamp(c.pixels, 1.0, 1000.0);
        return true;
    }
    bool operator()(const cmd::ScaleBrushRadius& c) const
    {
        st.tools.brush_radius_px = std::clamp(st.tools.brush_radius_px * c.factor, 2.0, 400.0);
        return true;
    }
    bool operator()(const cmd::RunSelection& c) const
    {
        run_selection_command(c.command, st.tools.elements, d.mesh, d.topology, d.selected_vertices,
                              d.selected_faces);
        return true;
    }
    bool operator()(const cmd::ApplySelection& c) const
    {
        SelectionMask& mask =
            c.elements == ElementKind::Vertices ? d.selected_vertices : d.selected_faces;
        for (const Index i : c.indices)
            if (i < 0 || static_cast<size_t>(i) >= mask.size())
                throw InvalidInputError("selection index " + std::to_string(i) +
                                        " is out of range");
        if (c.op == SelectOp::Replace)
            std::fill(mask.begin(), mask.end(), 0);
        apply_selection(mask, c.indices,
                        c.op == SelectOp::Subtract ? SelectOp::Subtract : SelectOp::Add);
        return true;
    }

    // --- History.
    bool travel(bool back) const
    {
        const unsigned parts = back ? s.history_.undo(d) : s.history_.redo(d);
        if (parts == 0)
            return false;
        s.after_history(parts);
        say(back ? "undid " + s.history_.redo_label() : "redid " + s.history_.undo_label());
        return true;
    }
    bool operator()(const cmd::Undo&) const { return travel(true); }
    bool operator()(const cmd::Redo&) const { return travel(false); }

    // --- The view.
    bool operator()(const cmd::FrameAll&) const
    {
        s.camera_.frame(d.box, s.aspect());
        return true;
    }
    bool operator()(const cmd::FrameSelection&) const
    {
        s.camera_.frame(selection_box(d), d.box, s.aspect());
        return true;
    }
    bool operator()(const cmd::SetView& c) const
    {
        s.camera_.set_view(c.view);
        return true;
    }
    bool operator()(const cmd::SetProjection& c) const
    {
        s.camera_.projection = c.projection;
        return true;
    }
    bool operator()(const cmd::ToggleProjection&) const
    {
        s.camera_.projection = s.camera_.projection == Projection::Perspective
                                   ? Projection::Orthographic
                                   : Projection::Perspective;
        return true;
    }
    bool operator()(const cmd::SetOrbit& c) const
    {
        st.orbit = c.orbit;
        return true;
    }
    bool operator()(const cmd::ToggleOrbit&) const
    {
        st.orbit =
            st.orbit == OrbitStyle::Turntable ? OrbitStyle::Trackball : OrbitStyle::Turntable;
        return true;
    }
    bool operator()(const cmd::SetUpAxis& c) const
    {
        s.camera_.up_axis = c.up;
        s.camera_.set_view(StandardView::Front);
        s.camera_.frame(d.box, s.aspect());
        if (!st.offscreen)
            save_up_axis(up_axes_path(), d.path, c.up);
        return true;
    }
    bool operator()(const cmd::Toggle& c) const
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
        }
        return true;
    }
    bool operator()(const cmd::SetDisplay& c) const
    {
        const bool colors = st.display.vertex_colors; // the heat map's, not the panel's
        st.display = c.display;
        st.display.vertex_colors = colors;
        return true;
    }

    // --- Constraint sets.
    //! The selection as a set of `kind` takes it: vertex kinds take the selected vertices
    //! (or the vertices of the selected faces), face kinds the selected faces (or the faces
    //! whose vertices are all selected); a region keeps faces as faces.
    void selected_elements(ConstraintKind kind, std::vector<Index>& vertices,
                           std::vector<Index>& faces) const
    {
        const bool faces_mode = st.tools.elements == ElementKind::Faces;
        if (kind == ConstraintKind::Region && faces_mode)
            faces = selected_indices(d.selected_faces);
        else if (takes_vertices(kind))
            vertices = selected_indices(faces_mode ? vertices_of_faces(d.mesh, d.selected_faces)
                                                   : d.selected_vertices);
        else
            faces = selected_indices(faces_mode ? d.selected_faces
                                                : faces_of_vertices(d.mesh, d.selected_vertices));
    }
    bool operator()(const cmd::CreateSet& c) const
    {
        ConstraintSet set;
        set.kind = c.kind;
        set.color = default_color(c.kind);
        selected_elements(c.kind, set.vertices, set.faces);
        if (set.vertices.empty() && set.faces.empty())
            return fail("nothing selected for a " + std::string(kind_name(c.kind)) + " set");
        std::string name = c.name;
        if (name.empty())
        {
            int k = 1;
            do
                name = std::string(kind_name(c.kind)) + " " + std::to_string(k++);
            while (s.set_named(name));
        }
        else if (s.set_named(name))
            return fail("there is already a set named '" + name + "'");
        set.name = std::move(name);
        say("set '" + set.name + "': " + std::to_string(set.vertices.size() + set.faces.size()) +
            (set.vertices.empty() ? " faces" : " vertices"));
        d.sets.push_back(std::move(set));
        return true;
    }
    bool operator()(const cmd::DeleteSet& c) const
    {
        const size_t k = set_index(c.set);
        d.sets.erase(d.sets.begin() + static_cast<std::ptrdiff_t>(k));
        say("deleted set '" + c.set + "'");
        return true;
    }
    bool operator()(const cmd::RenameSet& c) const
    {
        const size_t k = set_index(c.set);
        if (c.name.empty())
            return fail("a set's name must not be empty");
        if (c.name != c.set && s.set_named(c.name))
            return fail("there is already a set named '" + c.name + "'");
        d.sets[k].name = c.name;
        return true;
    }
    bool operator()(const cmd::ShowSet& c) const
    {
        d.sets[set_index(c.set)].visible = c.visible;
        return true;
    }
    bool operator()(const cmd::SetColor& c) const
    {
        d.sets[set_index(c.set)].color = c.color;
        return true;
    }
    bool operator()(const cmd::SelectSet& c) const
    {
        const ConstraintSet& set = d.sets[set_index(c.set)];
        const bool faces = set.vertices.empty();
        SelectionMask& mask = faces ? d.selected_faces : d.selected_vertices;
        std::fill(mask.begin(), mask.end(), 0);
        apply_selection(mask, faces ? set.faces : set.vertices, SelectOp::Add);
        st.tools.elements = faces ? ElementKind::Faces : ElementKind::Vertices;
        return true;
    }
    bool operator()(const cmd::AddToSet& c) const
    {
        ConstraintSet& set = d.sets[set_index(c.set)];
        // A region made of faces takes faces; the other kinds what they hold.
        const bool vertex_set =
            set.faces.empty() && (takes_vertices(set.kind) || !set.vertices.empty());
        std::vector<Index> vertices, faces;
        selected_elements(vertex_set ? ConstraintKind::Pin : ConstraintKind::Centroid, vertices,
                          faces);
        std::vector<Index>& list = vertex_set ? set.vertices : set.faces;
        const std::vector<Index>& add = vertex_set ? vertices : faces;
        std::vector<Index> sorted_list = list;
        std::sort(sorted_list.begin(), sorted_list.end());
        size_t added = 0;
        for (const Index e : add)
            if (!std::binary_search(sorted_list.begin(), sorted_list.end(), e))
            {
                list.push_back(e);
                ++added;
                // The new elements of a moved pin set, or of a set with its own normals,
                // start where they are.
                if (!set.targets.empty())
                {
                    const size_t k = 3 * static_cast<size_t>(e);
                    set.targets.push_back(
                        {d.base_positions[k], d.base_positions[k + 1], d.base_positions[k + 2]});
                }
                if (!set.normals.empty())
                    set.normals.push_back(set.normals.front());
            }
        if (added == 0)
            return fail("nothing selected that is not in '" + c.set + "' already");
        say("added " + std::to_string(added) + (vertex_set ? " vertices" : " faces") + " to '" +
            c.set + "'");
        return true;
    }
    bool operator()(const cmd::RemoveFromSet& c) const
    {
        ConstraintSet& set = d.sets[set_index(c.set)];
        const bool vertex_set = !set.vertices.empty();
        std::vector<Index> vertices, faces;
        selected_elements(vertex_set ? ConstraintKind::Pin : ConstraintKind::Centroid, vertices,
                          faces);
        std::vector<Index> gone = vertex_set ? vertices : faces;
        std::sort(gone.begin(), gone.end());
        std::vector<Index>& list = vertex_set ? set.vertices : set.faces;
        size_t kept = 0, removed = 0;
        for (size_t k = 0; k < list.size(); ++k)
        {
            if (std::binary_search(gone.begin(), gone.end(), list[k]))
            {
                ++removed;
                continue;
            }
            // Targets and normals stay with their elements.
            if (!set.targets.empty())
                set.targets[kept] = set.targets[k];
            if (!set.normals.empty())
                set.normals[kept] = set.normals[k];
            list[kept++] = list[k];
        }
        if (removed == 0)
            return fail("nothing selected is in '" + c.set + "'");
        list.resize(kept);
        if (!set.targets.empty())
            set.targets.resize(kept);
        if (!set.normals.empty())
            set.normals.resize(kept);
        say("removed " + std::to_string(removed) + (vertex_set ? " vertices" : " faces") +
            " from '" + c.set + "'" +
            (kept == 0 ? " (it is empty now: left out of the solve)" : ""));
        return true;
    }
    bool operator()(const cmd::CloseHoles& c) const
    {
        ConstraintSet& set = d.sets[set_index(c.set)];
        if (set.kind != ConstraintKind::Region)
            return fail("only a region has holes to close");
        const size_t holes = close_region_holes(set, d.mesh, d.topology);
        if (holes == 0)
            return fail("region '" + c.set + "' encloses nothing it leaves out");
        say("region '" + c.set + "': the " + std::to_string(holes) +
            " enclosed vertices it left out now move");
        return true;
    }
    bool operator()(const cmd::EnableSet& c) const
    {
        d.sets[set_index(c.set)].enabled = c.enabled;
        return true;
    }
    bool operator()(const cmd::SetSetWeight& c) const
    {
        ConstraintSet& set = d.sets[set_index(c.set)];
        if (!takes_weight(set.kind))
            return fail("a " + std::string(kind_name(set.kind)) + " set has no weight");
        if (!(c.mu >= 0) || !std::isfinite(c.mu))
            return fail("a set's weight must be a number >= 0");
        set.mu = c.mu;
        return true;
    }
    bool operator()(const cmd::SetNormalDirection& c) const
    {
        ConstraintSet& set = d.sets[set_index(c.set)];
        if (set.faces.empty())
            return fail("set '" + c.set + "' has no faces");
        Vec3 v = c.direction;
        const Scalar length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(length > 0) || !std::isfinite(length))
            return fail("a normal direction must not be zero");
        for (Scalar& x : v)
            x /= length;
        set.normals.assign(set.faces.size(), v);
        return true;
    }
    bool operator()(const cmd::MovePins& c) const
    {
        ConstraintSet& set = d.sets[set_index(c.set)];
        if (set.kind != ConstraintKind::Pin)
            return fail("set '" + c.set + "' is not a pin set");
        if (set.targets.empty())
            for (const Index v : set.vertices)
            {
                const size_t k = 3 * static_cast<size_t>(v);
                set.targets.push_back(
                    {d.base_positions[k], d.base_positions[k + 1], d.base_positions[k + 2]});
            }
        for (Vec3& t : set.targets)
            for (size_t a = 0; a < 3; ++a)
                t[a] += c.offset[a];
        return true;
    }

    // --- Solving.
    bool operator()(const cmd::SetSolverSettings& c) const
    {
        if (c.settings == d.solver)
            return false;
        d.solver = c.settings;
        s.solver_.set_iterations_per_frame(c.settings.iterations_per_frame);
        return true;
    }
    bool operator()(const cmd::Play& c) const
    {
        std::string why;
        return s.solver_.play(c.frames, why) || fail(why);
    }
    bool operator()(const cmd::Pause&) const
    {
        s.solver_.pause();
        return true;
    }
    bool operator()(const cmd::TogglePlay&) const
    {
        if (s.solver_.playing())
            return (*this)(cmd::Pause{});
        return (*this)(cmd::Play{});
    }
    bool operator()(const cmd::Step& c) const
    {
        const int n = c.steps > 0 ? c.steps : d.solver.iterations_per_frame;
        std::string why;
        if (!s.solver_.step(n, why))
            return fail(why);
        s.open_step_->label = "step " + std::to_string(n);
        s.update();
        return true;
    }
    bool operator()(const cmd::ResetShape&) const
    {
        d.mesh.positions = d.base_positions;
        s.solver_.start_from_base();
        return true;
    }
    bool operator()(const cmd::ApplyShape&) const
    {
        d.base_positions = d.mesh.positions;
        s.solver_.start_from_base();
        return true;
    }
    bool operator()(const cmd::AddNoise& c) const
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
    bool operator()(const cmd::SetHeatMap& c) const
    {
        st.heat_map = c.term;
        s.solver_.set_heat(c.term);
        if (!c.term)
            st.display.vertex_colors = false;
        return true;
    }

    // --- Files and the program.
    bool operator()(const cmd::OpenMesh& c) const
    {
        Document next = load_document(c.path); // on failure the document stays
        s.renderer_.set_mesh(next.mesh, next.draw_data);
        d = std::move(next);
        s.reset_for_document();
        // The up axis this file was last seen with.
        s.camera_.up_axis = load_up_axis(up_axes_path(), c.path).value_or(s.camera_.up_axis);
        s.camera_.set_view(StandardView::Front);
        s.camera_.frame(d.box, s.aspect());
        s.remember(c.path);
        st.recovery_saved_at.reset();
        if (const std::optional<RecoveryInfo> offer = s.recovery_offer())
            st.recovery_saved_at = offer->saved_at;
        say("opened " + c.path);
        return true;
    }
    bool operator()(const cmd::SaveMesh& c) const
    {
        const std::string path = c.path.empty() ? d.path : c.path;
        save_document(d, path);
        s.remember(path);
        say("saved " + path);
        return true;
    }
    bool operator()(const cmd::ExportRecipe& c) const
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
    bool operator()(const cmd::ImportRecipe& c) const
    {
        ImportedRecipe imported = import_recipe(d, c.path);
        imported.settings.iterations_per_frame = d.solver.iterations_per_frame;
        d.sets = std::move(imported.sets);
        d.solver = imported.settings;
        say("imported " + c.path + " (" + std::to_string(imported.iterations) +
            " iterations in the file: Step runs them)");
        return true;
    }
    bool operator()(const cmd::ShowDialog& c) const
    {
        st.dialog = c.dialog;
        return true;
    }
    bool operator()(const cmd::Screenshot& c) const
    {
        st.screenshot = c.path;
        return true;
    }
    bool operator()(const cmd::Quit&) const
    {
        if (d.modified)
            st.quit_prompt = true;
        else
            st.quit = true;
        return true;
    }
    bool operator()(const cmd::QuitDiscarding&) const
    {
        st.quit = true;
        return true;
    }
    bool operator()(const cmd::Recover&) const
    {
        const RecoveryInfo info = s.autosaver_.recover(d);
        s.history_.clear();
        s.solver_.clear();
        d.versions.bump(kSelection | kSets | kSettings | kPositions | kBasePositions);
        st.recovery_saved_at.reset();
        say("recovered the session saved at " + info.saved_at);
        return true;
    }
    bool operator()(const cmd::DiscardRecovery&) const
    {
        s.autosaver_.discard(d);
        st.recovery_saved_at.reset();
        return true;
    }
    bool operator()(const cmd::Autosave&) const
    {
        s.autosave(0);
        return true;
    }
};

bool EditorSession::dispatch(const Command& command, const Interaction& from)
{
    const CommandSpec spec = spec_of(command);
    const bool from_gesture = from.key == kGesture.key;
    if (gesture_ != nullptr && !from_gesture && spec.waits_for_gesture)
        return false;
    if (spec.stops_run)
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
    if (ok && spec.bumps != 0)
    {
        document_.versions.bump(spec.bumps);
        if (spec.bumps & (kPositions | kBasePositions))
            document_.modified = true;
    }
    if (from.key.empty())
        close_step();
    if (trace_ != nullptr && !from_gesture)
    {
        std::fprintf(trace_, "command %s: %s%s\n", std::string(command_name(command)).c_str(),
                     ok                        ? "ok"
                     : state_.message_is_error ? "failed: "
                                               : "nothing to do",
                     ok || !state_.message_is_error ? "" : state_.message.c_str());
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
    OpenStep step = std::move(*open_step_);
    open_step_.reset();
    history_.record(std::move(step.label), std::move(step.before), document_);
}

void EditorSession::after_history(unsigned parts)
{
    document_.versions.bump(parts);
    if (parts & (kPositions | kBasePositions))
        document_.modified = true;
}

} // namespace meshfair::app
