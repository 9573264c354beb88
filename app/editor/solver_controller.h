// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/document.h"
#include "app/editor/history.h"
#include "app/editor/live_solver.h"

namespace meshfair::app {

//! \brief Live solving of a document: the LiveSolver restarted when the recipe (the sets
//! and settings) or the shape changed by an edit, precomputed once per change and never per
//! frame; runs (play, pause, step) and what they leave in the history. Each Play→Pause
//! segment is an undo step, and a segment also ends where a setting changes during the
//! run, so any shape seen at a pause or at a change can be returned to.
class SolverController
{
public:
    SolverController(Document& document, History& history);

    //! \brief Why the sets cannot run (constraint_problems), for the sets and settings as
    //! they are now; empty when they can.
    const std::vector<std::string>& problems();
    //! \brief Starts live solving; `frames` > 0: pauses by itself after that many frames.
    //! False (with `why`) when the sets cannot run.
    bool play(int frames, std::string& why);
    //! Stops playing: the run since play (or the last segment) is one undo step.
    void pause();
    bool playing() const { return run_open_; }
    //! While playing: the run so far becomes an undo step and the run goes on.
    void segment();
    //! \brief While playing: waits for the solver's next frame and takes it (update());
    //! false when playing stopped instead. For scripts, which need no display's pace.
    bool take_frame();
    //! \brief Runs `n` steps now on this thread (the caller records the undo step); false
    //! (with `why`) when the sets cannot run.
    bool step(int n, std::string& why);
    //! \brief A smoothing-brush dab's run: the solver restarted from where the stroke began
    //! (`began`, the stroke's open step: its shape and what made it) with the sets as they
    //! are now, and `n` steps run on the worker. Returns at once, before the run is
    //! prepared: the interface thread runs no step of it. A dab's run supersedes the
    //! stroke's run not yet finished (LiveSolver::restart); the document keeps the shape it
    //! shows until the newest run's positions come (update()). False (with `why`) when the
    //! sets cannot run.
    bool run_stroke(const EditState& began, int n, std::string& why);
    //! A stroke's run was asked for and the stroke has not ended (end_stroke).
    bool stroke_running() const { return stroke_.has_value(); }
    //! Waits until the stroke's last run is done: its positions are the next update()'s.
    void wait_for_stroke() { solver_.wait_idle(); }
    //! \brief The stroke ends, once update() took its last run's positions; when that run
    //! could not be made (the recipe did not fit, the preparation was cancelled), the shape
    //! goes back to where the stroke began, as it was before the runs were asynchronous.
    void end_stroke();
    //! wait_for_stroke, update, end_stroke.
    void finish_stroke();
    void set_iterations_per_frame(int n) { solver_.set_iterations_per_frame(n); }
    //! LiveSolver::set_phase_listener.
    void set_phase_listener(std::function<void(const PreparationProgress::Snapshot&)> listener)
    {
        solver_.set_phase_listener(std::move(listener));
    }
    //! The shape is the base: no steps from it, and the next run starts there.
    void start_from_base();
    //! A new document: nothing runs until the next update.
    void clear();
    //! \brief Stops the solver's preparation (LiveSolver::cancel_preparation); nothing is
    //! prepared again for these sets until prepare_again() (Play, Step, Solve) or a change
    //! of the sets or the shape. False when nothing was preparing.
    bool cancel_preparation();
    //! After a cancelled preparation: the next update prepares the sets again. False
    //! when none was cancelled.
    bool prepare_again();

    //! \brief Once per frame: restarts the solver when the recipe or the shape changed since
    //! the last restart, takes the newest positions (bumping the positions' version) and
    //! closes a run that converged. True when new positions came (display() holds their
    //! geometry, computed on the solver's thread).
    bool update();
    const DisplayGeometry& display() const { return display_; }

    void set_heat(std::optional<EnergyTerm> term) { solver_.set_heat(term); }
    //! The energy curve's points carry the gradient (LiveSolver::set_plot_gradient).
    void set_plot_gradient(bool on) { solver_.set_plot_gradient(on); }
    bool take_heat(std::vector<float>& heat) { return solver_.take_heat(heat); }
    //! Waits for the solver's shares of the heat map's term (scripts).
    void wait_for_heat() { settle(); }
    //! Restarts if needed and waits until the solver is idle, then takes its positions.
    void settle();
    //! Restarts if needed and waits until the restart is prepared (a run goes on playing).
    void settle_preparation()
    {
        update();
        solver_.wait_prepared();
        update();
    }
    SolverStatus status() const { return solver_.status(); }
    //! The direct method's solves that the document's positions include (LiveSolver).
    int solves_shown() const { return solver_.solves_taken(); }
    std::vector<EnergySample> energies() const { return solver_.energies(); }
    std::vector<std::string> notes() const { return solver_.notes(); }
    //! How many base shapes were made for the solver's runs: one per document and per change
    //! of its base (Apply, noise, undo of them), never one per restart.
    int base_copies() const { return base_copies_; }
    //! The current run solves on that shared base, not on a copy of it.
    bool run_shares_base() const
    {
        return shared_base_ != nullptr && solver_.run_mesh() == shared_base_.get();
    }

private:
    //! The run since it began (or since the last segment) as one undo step.
    void record_segment();
    //! The solver's newest positions into the document, if it published any since the last
    //! take; true when it did.
    bool take_positions();
    void restart_if_needed();
    //! \brief Whether the current shape, made by `steps_from_base` steps of its own recipe,
    //! is what the current sets and settings give after as many steps.
    bool shape_made_by_current_recipe() const
    {
        return made_by_current_recipe(document_.shape_recipe);
    }
    bool made_by_current_recipe(const std::shared_ptr<const ShapeRecipe>& made) const;

    //! The base shape, order and faces around each vertex the solver's runs share (made once
    //! per document, the base again when it changes: versions.base), never copied per restart.
    void share_base();

    Document& document_;
    History& history_;
    LiveSolver solver_;
    std::uint64_t shared_document_ = 0, shared_base_version_ = 0;
    std::shared_ptr<const Mesh> shared_base_;
    std::shared_ptr<const LocalityOrder> shared_order_;
    std::shared_ptr<const VertexFaces> shared_faces_;
    int base_copies_ = 0;
    std::vector<std::string> problems_;
    std::optional<DocumentVersions> problems_for_;
    //! The sets and settings the solver runs (null: no run), as the shapes it makes record.
    std::shared_ptr<const ShapeRecipe> running_;
    std::optional<DocumentVersions> seen_; // the versions of the last restart decision
    int steps_at_restart_ = 0;             // steps_from_base when the solver last restarted
    bool run_open_ = false;                // play() began a run not yet recorded
    bool cancelled_ = false;               // the last preparation was cancelled
    std::optional<EditState> run_before_;
    //! The smoothing stroke whose runs the solver makes (run_stroke): where it began, and
    //! whether its runs' shapes are reproducible from the base.
    struct Stroke
    {
        std::vector<Scalar> positions;
        int steps_from_base = 0;
        bool reproducible = true;
        std::shared_ptr<const ShapeRecipe> shape_recipe;
        bool runs_reproducible = true;
    };
    std::optional<Stroke> stroke_;
    DisplayGeometry display_;      // the solver's newest display geometry
    std::vector<Scalar> incoming_; // the solver's newest positions, before they are shown
};

} // namespace meshfair::app
