// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "app/edit/command.h"
#include "app/editor/constraint_glyphs.h"
#include "app/editor/document.h"
#include "app/editor/editor_state.h"
#include "app/editor/history.h"
#include "app/editor/persistence.h"
#include "app/editor/solver_controller.h"
#include "app/render/renderer.h"
#include "app/tools/navigation.h"
#include "app/tools/tool_registry.h"

namespace meshfair::app {

//! \brief The editor without its window: the document, the interaction state, the camera,
//! the tools, the history and the solver. Every action reaches it as a Command through
//! dispatch() (from the key map, the menus, the panels, the tools and scripts), and raw
//! view input through the InputRouter's calls below, so a script does what a person does.
//!
//! What changed in the document is known from its versions (Document::versions), which
//! dispatch bumps; the renderer, the glyphs, the solver and the autosave compare them
//! with what they last saw.
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
    const History& history() const { return history_; }
    History& history() { return history_; }
    const ToolSettings& tool_settings() const { return state_.tools; }
    ToolKind tool() const { return state_.tool; }

    //! Where the 3D view is in the framebuffer (set before input of a frame is handled).
    void set_view_rect(const ViewRect& view) { view_ = view; }
    const ViewRect& view_rect() const { return view_; }
    double aspect() const;

    //! \brief Carries out a command: captures the undo state of what it edits, records the
    //! step (commands of one interaction merge into one step, see Interaction), reports
    //! errors in the status bar and bumps the document's versions. False when the command
    //! did nothing or failed (the message says why).
    bool dispatch(const Command& command, const Interaction& from = {});
    //! Ends the interaction under way (a widget let go, a script's action done).
    void end_interaction();
    //! \brief Prints each command (but a gesture's own) and its outcome, and each gesture's
    //! end, on `out` (nullptr: nothing).
    //! Where the trace goes (null: none), with the solver's preparation phases.
    void set_trace(std::FILE* out);
    //! \brief Called on the solver's thread as each phase of its preparation begins (after
    //! the trace's line), as LiveSolver::set_phase_listener: a tool that shows it, a test
    //! that holds a phase to cancel it.
    void observe_preparation(std::function<void(const PreparationProgress::Snapshot&)> observer);

    // Raw input of the view, in its pixels ((0, 0) its top-left corner), from the
    // InputRouter: the active tool's gestures and the navigation.
    void mouse_press(MouseButton button, Modifiers mods, double x, double y);
    //! `in_view`: the cursor is over the view (not over a panel).
    void mouse_move(double x, double y, bool in_view = true);
    void mouse_release(MouseButton button, double x, double y);
    void scroll(double notches, double x, double y);
    //! True while a tool's gesture (a stroke, a rectangle, a drag of pins) is under way.
    bool in_gesture() const { return gesture_ != nullptr; }
    //! What the active tool draws over the view now, in the view's pixels.
    ToolOverlay tool_overlay() const;
    //! \brief The dabs of the last Paint stroke made with the mouse (stroke_action replays
    //! them); the trace prints them when the stroke ends.
    const std::vector<cmd::PaintDab>& last_stroke() const { return stroke_; }

    //! The index of the set named `name`, if any.
    std::optional<size_t> set_named(const std::string& name) const;
    //! Why the sets cannot run as they are (constraint_problems); empty when they can.
    const std::vector<std::string>& problems() { return solver_.problems(); }
    bool playing() const { return solver_.playing(); }
    //! \brief While playing: waits for the solver's next frame and takes it; false when
    //! playing stopped instead. For scripts, which need no display's pace.
    bool take_frame();
    SolverStatus solver_status() const { return solver_.status(); }
    const SolverController& solver() const { return solver_; }
    std::vector<EnergySample> energies() const { return solver_.energies(); }
    //! Waits for the solver's shares of the heat map's term and shows them (scripts).
    void wait_for_heat();
    //! \brief Waits until the solver is idle (restarted for the sets as they are, the direct
    //! method's minimizer solved) and shows its positions: what a script sees next is the
    //! shape for its last command, as a person sees it a moment later.
    void settle_solver();
    //! SolverController::settle_preparation, then an update (scripts' widget clicks).
    void settle_preparation();

    //! \brief Once per frame, before drawing: restarts the solver when the recipe or the
    //! shape changed, takes its newest positions, and autosaves when it is time.
    void update();
    //! Recovery files of this mesh left by an editor that crashed, if any.
    std::optional<RecoveryInfo> recovery_offer() const { return autosaver_.offer(document_); }
    //! \brief At a clean exit: stops the solver and removes the recovery files this session
    //! wrote or recovered (not those of another session it never touched).
    void end_session();
    //! Where recovery files go (recovery_root() unless set; empty: no autosave).
    void set_recovery_root(std::string root) { autosaver_.set_root(std::move(root)); }
    //! \brief Writes the recovery files when something changed since the last time and at
    //! least `interval_s` seconds went by (never while a run plays).
    void autosave(double interval_s = 3.0);
    //! \brief The world's up axis for this mesh: the camera's and the document's, the front
    //! view framed, remembered for the file (not offscreen). SetUpAxis and Recover call it.
    void apply_up_axis(UpAxis up);

    //! Fills the state the interface shows: the tool's overlay, the history, the counts.
    void prepare_ui();
    //! \brief What the view shows now (Renderer::visibility), kept until the camera, the
    //! view's size or the geometry changes, so that gestures from one view render the ID
    //! buffer once between them.
    const Visibility& visibility();
    //! The face centroids projected into the view, kept likewise.
    std::span<const ScreenPoint> face_points();
    //! Sends what changed since the last frame to the renderer.
    void sync_renderer();
    //! sync_renderer, then draws the view.
    void draw();

private:
    friend struct CommandExecutor;
    //! The undo step under way: its name, what it may change as it was before, and the
    //! interaction whose commands merge into it.
    struct OpenStep
    {
        std::string label;
        unsigned parts = 0;
        EditState before;
        std::string interaction;
    };
    void close_step();
    void after_history(unsigned parts);
    ToolContext tool_context();
    std::vector<GrabHandle> pin_handles() const;
    std::vector<GrabHandle> normal_handles() const;
    //! \brief The handles of the M tool (pins) or the D tool (arrows), made once per change
    //! of the sets or the shape: the press and the cursor's highlight share them.
    const std::vector<GrabHandle>& grab_handles(ToolKind tool);
    //! What a press of the active tool would grab at the cursor (EditorState::grab_hover).
    std::vector<ScreenPoint> grab_hover();
    void reset_for_document();
    void remember(const std::string& path);

    Document document_;
    Renderer& renderer_;
    EditorState state_;
    Camera camera_;
    Navigator navigator_;
    History history_;
    ToolRegistry tools_;
    SolverController solver_;
    Autosaver autosaver_;
    ViewRect view_ = ViewRect::whole(640, 480);
    std::optional<OpenStep> open_step_;
    InteractiveTool* gesture_ = nullptr; // the tool of the gesture under way
    ScreenPoint cursor_;
    struct GrabCache
    {
        //! The tool and the sets' and positions' versions the handles were made for.
        std::optional<std::tuple<ToolKind, std::uint64_t, std::uint64_t>> key;
        std::vector<GrabHandle> handles;
    } grab_cache_;
    bool cursor_in_view_ = true;
    std::FILE* trace_ = nullptr;
    std::function<void(const PreparationProgress::Snapshot&)> preparation_observer_;
    //! The solver's phase listener: the trace's lines, then the observer.
    void listen_to_preparation();
    int solves_traced_ = 0;             // the direct solves the trace has named ("solved: ...")
    std::vector<cmd::PaintDab> stroke_; // the dabs of the current or last mouse stroke

    // What the renderer and the panels last got, by the document's versions.
    struct Synced
    {
        std::optional<std::uint64_t> selection, glyphs_sets, glyphs_positions, positions, notes,
            border, counts;
        std::optional<std::uint64_t> energy;
        std::optional<bool> plot_gradient; //!< asked of the solver (the plot shown)
        //! The sets' and positions' versions of state_.set_directions.
        std::optional<std::pair<std::uint64_t, std::uint64_t>> directions;
        int restarts = 0;       //!< the solver's restarts whose notes the status bar has told
        bool preparing = false; //!< the solver was preparing at the last frame
        //! The weight map shown (the sets' version and the set painted), if any.
        std::optional<std::pair<std::uint64_t, std::string>> weights;
        std::string glyphs_hidden; //!< the set left out of the glyphs (its map is shown)
    } synced_;
    RegionBorder border_; // of the current sets
    std::vector<float> heat_;

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

//! The interaction key of a tool's gesture: its commands merge into one undo step.
inline const Interaction kGesture{"gesture"};

} // namespace meshfair::app
