// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "app/editor/constraint_glyphs.h"
#include "app/editor/document.h"
#include "app/editor/editor_ui.h"
#include "app/editor/history.h"
#include "app/editor/live_solver.h"
#include "app/editor/navigation.h"
#include "app/editor/recovery.h"
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
    //! The next edit is an undo step of its own (see History::seal).
    void seal_history() { history_.seal(); }

    //! Carries out what the interface or the keys asked for (views, files, ...); quit and
    //! screenshots are the caller's.
    void carry_out(const UiRequests& requests);
    //! \brief Opens a mesh as the new document (history cleared); on failure the message
    //! says why and the document stays as it was. Returns whether it opened.
    bool open(const std::string& path);
    //! Saves the mesh (format from the extension, atomic); false and a message on failure.
    bool save(const std::string& path);

    // --- Constraint sets; each change is one undo step.
    //! \brief Makes a set of `kind` from the selection of the current mode (vertex kinds
    //! from selected vertices, or the vertices of selected faces; face kinds from selected
    //! faces, or the faces whose vertices are all selected; a region keeps faces as faces).
    //! False, with a message, when that gives no element.
    bool create_set(ConstraintKind kind, std::string name = {});
    //! The index of the set named `name`, if any.
    std::optional<size_t> set_named(const std::string& name) const;
    void delete_set(size_t index);
    void rename_set(size_t index, std::string name);
    void set_visible(size_t index, bool visible);
    void set_color(size_t index, std::array<float, 3> color);
    //! Replaces the selection with the set's elements (and switches to its mode).
    void select_set(size_t index);
    //! Gives every face of a normal set the unit direction of `direction` (not zero).
    void set_normal_direction(size_t index, Vec3 direction);
    //! \brief Moves a pin set's targets by `offset` (the view-plane drag of its glyphs):
    //! the paper's hard constraints moved to targets.
    void move_pins(size_t index, Vec3 offset);
    //! \brief New solver settings; with `merge`, a series of changes of one control is one
    //! undo step.
    void set_solver_settings(const SolverSettings& settings, bool merge = true);
    //! Why the sets cannot run as they are (constraint_problems); empty when they can.
    const std::vector<std::string>& problems() const { return problems_; }

    // --- Solving. The recipe is precomputed on the solver's thread once per change of the
    // sets or settings, never per frame.
    //! \brief Starts live solving: steps run on the worker, the view shows the newest
    //! positions; with `frames` > 0 it pauses by itself after that many frames.
    void play(int frames = 0);
    //! Stops: the run since play() is one undo step.
    void pause();
    bool playing() const { return run_open_; }
    //! \brief While playing: waits for the solver's next frame and takes it (update());
    //! false when playing stopped instead. For scripts, which need no display's pace.
    bool take_frame();
    //! Runs `n` steps now (one undo step).
    void step(int n);
    //! Back to the base shape (one undo step).
    void reset_shape();
    //! Makes the current shape the base the recipe starts from (one undo step).
    void apply_shape();
    //! \brief Adds Gaussian noise of `sigma` mean edge lengths to the current shape, as
    //! `meshfair-cli noise` does, and makes it the base (a noisy copy for demos; one undo
    //! step).
    void add_noise(Scalar sigma, std::uint64_t seed);
    SolverStatus solver_status() const { return solver_.status(); }
    std::vector<EnergySample> energies() const { return solver_.energies(); }
    //! \brief The recipe of the sets and settings with the steps taken from the base shape,
    //! in the document's (locality) numbering:
    //! what `meshfair-cli smooth BASE --recipe R.json` runs to reproduce the current shape
    //! (bit for bit when document().reproducible).
    Recipe current_recipe() const;
    //! current_recipe() in the file's numbering: what Export recipe writes.
    Recipe file_recipe() const;
    //! Writes file_recipe() as JSON (atomic); false and a message on failure.
    bool export_recipe(const std::string& path);
    //! Replaces the sets and settings by a recipe's (one undo step); false and a message when
    //! it cannot be read or does not fit the mesh.
    bool import_recipe(const std::string& path);
    //! \brief Colours each vertex by its share of `term`'s energy, updated with the solver's
    //! frames (nullopt: the heat map off). Display only, not an undo step.
    void set_heat_map(std::optional<EnergyTerm> term);
    //! Waits for the solver's shares of the heat map's term and shows them (scripts).
    void wait_for_heat();
    //! \brief Once per frame, before drawing: restarts the solver when the recipe changed,
    //! takes its newest positions and hands them to the renderer.
    void update();

    // --- Autosave and recovery (app/editor/recovery.h).
    //! \brief Writes the recovery files when something changed since the last time and
    //! at least `interval_s` seconds went by (0: now). Failures only set the message.
    void autosave(double interval_s = 3.0);
    //! Recovery files of this mesh left by an editor that crashed, if any.
    std::optional<RecoveryInfo> recovery_offer() const;
    //! \brief Restores them (the history starts again from there); false and a message
    //! when they cannot be read.
    bool recover();
    //! Removes this mesh's recovery files (the offer declined).
    void discard_recovery();
    //! \brief At a clean exit: removes the recovery files this session wrote or recovered
    //! (not those of another session it never touched).
    void end_session();
    //! Where recovery files go (recovery_root() unless set; empty: no autosave).
    void set_recovery_root(std::string root) { recovery_root_ = std::move(root); }

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
    //! Records a step of `parts` begun with `before`.
    void record(const std::string& label, EditState before, bool merge = false);
    void sets_changed();
    void after_history(unsigned parts);
    //! Undo (back) or redo.
    bool travel(bool back);
    void positions_changed();
    //! The positions changed: the renderer gets them (with display_'s normals when
    //! `computed`, else computing its own).
    void geometry_changed(bool computed);
    DisplayGeometry display_;      // the solver's newest display geometry
    std::vector<Scalar> incoming_; // the solver's newest positions, before they are shown
    void close_run();
    //! The current shape is the base: the step count and the solver start again from it.
    void start_from_base();
    //! The base shape as a mesh, for the solver's restarts (a copy: the solver keeps it).
    Mesh base_mesh() const;

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
    LiveSolver solver_;
    std::vector<std::string> problems_;
    bool recipe_dirty_ = true; // the sets or settings changed since the last restart
    //! The sets and settings of the solver's last restart (none: restart at the next update).
    struct RunInputs
    {
        std::vector<ConstraintSet> sets;
        SolverSettings solver;
    };
    std::optional<RunInputs> restarted_;
    std::optional<size_t> dragged_pins_; // the pin set the MovePins tool drags
    double dragged_depth_ = 0;           // its grabbed glyph's window depth
    glm::dvec3 dragged_from_{0.0};       // the grabbed point, in the world
    bool press_pins(double x, double y);
    std::optional<size_t> aimed_normals_; // the normal set the AimNormals tool turns
    double aim_x_ = 0, aim_y_ = 0;        // the cursor at the last turn
    bool press_normals(double x, double y);
    void aim_normals(double x, double y);
    void drag_pins(double x, double y);
    int steps_at_restart_ = 0; // steps_from_base when the solver last restarted
    bool run_open_ = false;    // play() began a run not yet recorded
    std::optional<EditState> run_before_;
    std::uint64_t geometry_ = 0;
    std::vector<float> heat_;                                // the newest heat-map colours
    std::uint64_t shown_energy_version_ = ~std::uint64_t(0); // the curve in state_.energies
    std::string recovery_root_ = recovery_root();
    std::uint64_t edits_ = 0, autosaved_edits_ = 0; // changes so far, and at the last autosave
    double last_autosave_ = 0;                      // seconds on the steady clock
    bool owns_recovery_ = false;                    // this session wrote or recovered the files...
    std::string recovery_path_;                     // ...of this mesh path // changes of the
                                                    // positions, for the visibility key
    ScreenPoint cursor_;
    bool selection_dirty_ = true;
    bool counts_dirty_ = true;
    bool glyphs_dirty_ = true;
    RegionBorder border_; // of the current sets

    // The visibility kept for the camera and view it was computed for.
    struct VisibilityKey
    {
        glm::dmat4 view{0.0}, projection{0.0};
        int width = 0, height = 0;
        std::uint64_t geometry = 0;
        bool operator==(const VisibilityKey&) const = default;
    };
    std::optional<Visibility> visibility_;
    VisibilityKey visibility_key_;
    std::optional<std::vector<ScreenPoint>> face_points_;
    VisibilityKey face_points_key_;
    VisibilityKey view_key() const;
};

} // namespace meshfair::app
