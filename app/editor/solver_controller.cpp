// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/solver_controller.h"

#include <utility>

namespace meshfair::app {

namespace {

// The base shape with the document's connectivity, for a restart (the solver keeps it).
Mesh base_mesh(const Document& d)
{
    Mesh base;
    base.positions = d.base_positions;
    base.face_offsets = d.mesh.face_offsets;
    base.face_vertices = d.mesh.face_vertices;
    return base;
}

} // namespace

SolverController::SolverController(Document& document, History& history)
    : document_(document), history_(history)
{
}

const std::vector<std::string>& SolverController::problems()
{
    const DocumentVersions& v = document_.versions;
    if (!problems_for_ || problems_for_->sets != v.sets || problems_for_->settings != v.settings)
    {
        problems_ = constraint_problems(document_.sets, document_.solver);
        problems_for_ = v;
    }
    return problems_;
}

void SolverController::clear()
{
    stroke_.reset();
    run_open_ = false;
    run_before_.reset();
    solver_.clear();
    running_.reset();
    seen_.reset();
    problems_for_.reset();
}

bool SolverController::cancel_preparation()
{
    if (!solver_.cancel_preparation())
        return false;
    cancelled_ = true;
    run_open_ = false; // (a run asked for before it was prepared: nothing to record)
    run_before_.reset();
    return true;
}

bool SolverController::prepare_again()
{
    if (!cancelled_)
        return false;
    cancelled_ = false;
    seen_.reset(); // the next update restarts
    return true;
}

void SolverController::start_from_base()
{
    document_.steps_from_base = 0;
    document_.reproducible = true;
    document_.shape_recipe.reset();
    running_.reset(); // the next update restarts from the base
    seen_.reset();
}

bool SolverController::made_by_current_recipe(const std::shared_ptr<const ShapeRecipe>& made) const
{
    // Steps depend on the positions and the recipe only: a run restarted from a shape its
    // own recipe made gives the same bits as the run that made it, going on.
    return made != nullptr &&
           same_run(document_.sets, document_.solver, made->sets, made->solver, false);
}

void SolverController::restart_if_needed()
{
    const DocumentVersions& v = document_.versions;
    const auto same = [&](const DocumentVersions& w) {
        return w.sets == v.sets && w.settings == v.settings && w.positions == v.positions &&
               w.base == v.base;
    };
    if (seen_ && same(*seen_))
        return;
    // A smoothing stroke's dabs restart the solver themselves (run_stroke), and nothing else
    // changes the sets or the shape before the stroke ends (any other command ends it).
    if (stroke_)
        return;
    const std::optional<DocumentVersions> before = std::exchange(seen_, v);
    if (!problems().empty())
    {
        solver_.clear();
        running_.reset(); // a valid recipe restarts from scratch
        return;
    }
    const std::vector<ConstraintSet>& sets = document_.sets;
    const SolverSettings& settings = document_.solver;
    // An edit of the shape (undo, reset, noise, apply) starts the run again from it.
    const bool shape_edited =
        !running_ || !before || before->positions != v.positions || before->base != v.base;
    if (!shape_edited && same_run(sets, settings, running_->sets, running_->solver, false))
        return; // names, colours, visibility or the pace changed: nothing for the solver
    if (!shape_edited && same_run(sets, settings, running_->sets, running_->solver, true))
    {
        // Only the pins moved: new right-hand sides, the run goes on. (The pin sets alone
        // are read: the recipe's other sets did not change.)
        const std::optional<HardVertices> hard = pin_constraints(sets, document_.base_positions);
        std::vector<Scalar> targets;
        for (const Vec3& t : hard->targets)
            targets.insert(targets.end(), t.begin(), t.end());
        if (targets.empty()) // no set has targets any more: the pins' base places
            for (const Index vertex : hard->vertices)
                for (size_t a = 0; a < 3; ++a)
                    targets.push_back(
                        document_.base_positions[3 * static_cast<size_t>(vertex) + a]);
        solver_.move_hard_targets(targets);
        if (document_.steps_from_base > 0)
            document_.reproducible = document_.reproducible && shape_made_by_current_recipe();
    }
    else
    {
        // From the base (the recipe's input shape), starting at the current positions.
        const bool at_base = document_.steps_from_base == 0;
        cancelled_ = false; // prepared again
        share_base();
        solver_.restart(shared_base_, shared_order_,
                        build_recipe(sets, settings, document_.mesh, document_.base_positions, 0),
                        at_base ? std::vector<Scalar>{} : document_.mesh.positions, shared_faces_);
        if (!at_base)
            document_.reproducible = document_.reproducible && shape_made_by_current_recipe();
        steps_at_restart_ = document_.steps_from_base;
        if (run_open_)
            solver_.resume();
    }
    running_ = std::make_shared<const ShapeRecipe>(ShapeRecipe{sets, settings});
}

void SolverController::share_base()
{
    if (shared_document_ != document_.id || !shared_order_)
    {
        shared_order_ = std::make_shared<const LocalityOrder>(document_.order);
        shared_faces_ = std::make_shared<const VertexFaces>(
            VertexFaces{document_.draw_data.vertex_face_offsets, document_.draw_data.vertex_faces});
        shared_base_.reset();
        shared_document_ = document_.id;
    }
    if (!shared_base_ || shared_base_version_ != document_.versions.base)
    {
        shared_base_ = std::make_shared<const Mesh>(base_mesh(document_));
        shared_base_version_ = document_.versions.base;
        ++base_copies_;
    }
}

bool SolverController::update()
{
    restart_if_needed();
    bool fresh = take_positions();
    const SolverStatus st = solver_.status();
    if (run_open_ && !st.playing && !st.ready && !st.preparing)
    {
        // The restart the run waited for failed (the recipe did not fit: status().error
        // says why) or was cancelled: there is nothing to run, and the run ends with no
        // step to record, rather than waiting for frames that never come.
        run_open_ = false;
        run_before_.reset();
        return fresh;
    }
    if (run_open_ && !st.playing && st.ready)
    {
        // The solver may have published the run's last frame after the take above (it
        // publishes and stops in one step): those positions belong to this run's undo step.
        fresh = take_positions() || fresh;
        run_open_ = false; // converged, or the frames asked for are done
        record_segment();
    }
    return fresh;
}

bool SolverController::take_positions()
{
    int steps = 0;
    bool fresh = false;
    if (solver_.take(incoming_, display_, steps))
    {
        // The step count of these positions, taken with them: a frame the solver finishes
        // meanwhile counts in status() before its positions are taken.
        std::swap(incoming_, document_.mesh.positions);
        document_.steps_from_base = steps_at_restart_ + steps;
        if (stroke_)
        {
            // A stroke's run from where it began: what made the shape is known from there.
            document_.reproducible = stroke_->runs_reproducible;
            document_.shape_recipe = steps > 0 ? running_ : stroke_->shape_recipe;
        }
        else if (steps > 0)
            document_.shape_recipe = running_;
        document_.modified = true;
        document_.versions.bump(kPositions);
        // The run's own positions: no restart for them.
        if (seen_)
            seen_->positions = document_.versions.positions;
        fresh = true;
    }
    return fresh;
}

bool SolverController::play(int frames, std::string& why)
{
    finish_stroke(); // the run plays on from the stroke's shape
    if (run_open_)
        return true;
    prepare_again();
    update(); // the recipe restarted if it changed
    if (!problems().empty())
    {
        why = "cannot solve: " + problems().front();
        return false;
    }
    // The recipe's restart failed already: said now, where Space was pressed (one still
    // preparing that fails ends the run at once, update()).
    const SolverStatus st = solver_.status();
    if (!st.ready && !st.preparing && !st.error.empty())
    {
        why = "cannot solve: " + st.error;
        return false;
    }
    run_before_ = capture(document_, kPositions);
    run_open_ = true;
    // A run stops by itself: after its steps, or once the gradient relative to the
    // run's start falls to the tolerance (1e-6 "until converged" when the recipe has none).
    const SolverSettings& s = document_.solver;
    solver_.set_playing(true, frames, frames > 0 || s.until_converged ? 0 : s.steps_per_run,
                        s.until_converged && s.tolerance == 0 ? Scalar(1e-6) : Scalar(0),
                        s.steps_per_run);
    return true;
}

void SolverController::record_segment()
{
    if (!run_before_)
        return;
    const int steps = document_.steps_from_base - *run_before_->steps_from_base;
    history_.record("solve " + std::to_string(steps) + " steps", std::move(*run_before_),
                    document_);
    run_before_.reset();
}

void SolverController::pause()
{
    if (!run_open_)
        return;
    run_open_ = false; // before update(), which would close a converged run
    solver_.set_playing(false);
    solver_.wait_idle();
    update(); // the last frame's positions
    record_segment();
}

void SolverController::segment()
{
    if (!run_open_)
        return;
    update();
    record_segment();
    run_before_ = capture(document_, kPositions);
}

bool SolverController::take_frame()
{
    update(); // a change of the recipe restarts the run before its next frame
    const bool published = solver_.wait_published();
    update();
    return published;
}

bool SolverController::step(int n, std::string& why)
{
    finish_stroke(); // the steps go on from the stroke's shape
    pause();
    prepare_again();
    update();
    if (!problems().empty())
    {
        why = "cannot solve: " + problems().front();
        return false;
    }
    solver_.step_now(n);
    update();
    return true;
}

bool SolverController::run_stroke(const EditState& began, int n, std::string& why)
{
    pause();
    prepare_again();
    if (!problems().empty())
    {
        why = "cannot solve: " + problems().front();
        return false;
    }
    if (!stroke_) // the stroke's first run: where it began, for each of its dabs
        stroke_ = Stroke{*began.positions, *began.steps_from_base, *began.reproducible,
                         *began.shape_recipe, true};
    Stroke& stroke = *stroke_;
    // As restart_if_needed restarts from a shape that was edited: from the base, or from
    // the stroke's start, which is reproducible only if the current recipe made it.
    const bool at_base = stroke.steps_from_base == 0;
    stroke.runs_reproducible =
        stroke.reproducible && (at_base || made_by_current_recipe(stroke.shape_recipe));
    cancelled_ = false;
    share_base();
    const std::vector<ConstraintSet>& sets = document_.sets;
    const SolverSettings& settings = document_.solver;
    solver_.restart(shared_base_, shared_order_,
                    build_recipe(sets, settings, document_.mesh, document_.base_positions, 0),
                    at_base ? std::vector<Scalar>{} : stroke.positions, shared_faces_, n);
    steps_at_restart_ = stroke.steps_from_base;
    running_ = std::make_shared<const ShapeRecipe>(ShapeRecipe{sets, settings});
    seen_ = document_.versions;
    return true;
}

void SolverController::end_stroke()
{
    if (!stroke_)
        return;
    if (!solver_.status().ready)
    {
        // No run of the last dab's map to show: the stroke's shape is where it began.
        Stroke& stroke = *stroke_;
        document_.mesh.positions = std::move(stroke.positions);
        document_.steps_from_base = stroke.steps_from_base;
        document_.reproducible = stroke.reproducible;
        document_.shape_recipe = stroke.shape_recipe;
        document_.versions.bump(kPositions);
        if (seen_) // (not a shape to restart from: no run fits these sets)
            seen_->positions = document_.versions.positions;
    }
    stroke_.reset();
}

void SolverController::finish_stroke()
{
    if (!stroke_)
        return;
    wait_for_stroke();
    update();
    end_stroke();
}

void SolverController::settle()
{
    update(); // a pending restart first
    solver_.wait_idle();
    update();
}

} // namespace meshfair::app
