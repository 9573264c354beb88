// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/live_solver.h"

#include <algorithm>
#include <chrono>
#include <thread>
#include <utility>

#include "app/editor/heat_map.h"
#include "app/render/mesh_draw_data.h"
#include "core/solver/solver.h"
#include "core/topology/topology.h"

namespace meshfair::app {

namespace {

constexpr size_t kMaxEnergySamples = 20000;
// The direct method's solve: its first step lands on the minimizer, the others refine it
// to rounding when the guard or rounding left something (DirectConvergence stops them).
constexpr int kDirectSolveSteps = 4;

// A frame of conjugate gradients (no factor) runs kProgressiveWork / #free iterations a
// right-hand side, 4 to 400: about the same work a frame at any size up to 750k free.
constexpr double kProgressiveWork = 3e6;

int progressive_iterations(size_t free_count)
{
    return static_cast<int>(std::clamp(
        kProgressiveWork / static_cast<double>(std::max<size_t>(free_count, 1)), 4.0, 400.0));
}

} // namespace

LiveSolver::LiveSolver() : thread_([this] { worker(); }) {}

LiveSolver::~LiveSolver()
{
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void LiveSolver::restart(std::shared_ptr<const Mesh> base,
                         std::shared_ptr<const LocalityOrder> order, Recipe recipe,
                         std::vector<Scalar> start, std::shared_ptr<const VertexFaces> vertex_faces,
                         int steps)
{
    {
        std::lock_guard lock(mutex_);
        // (A pending restart is replaced, never queued behind: only the newest is prepared.)
        restart_ = Restart{std::move(base),         std::move(order), std::move(recipe),
                           std::move(vertex_faces), std::move(start), std::max(steps, 0)};
        steps_due_ = 0; // the run before owes nothing now
        ++generation_;
        pending_pins_.reset(); // the recipe has the newest targets
        status_.playing = false;
        status_.ready = false;
        status_.cancelled = false;
        status_.converged = false;
        status_.error.clear();
        status_.steps = 0;
        energies_.clear();
        known_energy_.reset();
        ++rule_epoch_;
        energy_due_ = false;
        solve_due_ = false; // the restart decides
        ++status_.energy_version;
        fresh_ = false;
    }
    wake_.notify_all();
}

bool LiveSolver::cancel_preparation()
{
    std::unique_lock lock(mutex_);
    if (!restart_ && !preparing_)
        return false;
    restart_.reset();
    pending_pins_.reset();
    steps_due_ = 0;
    ++generation_; // what the preparation under way makes is dropped
    if (preparing_)
        progress_->cancel();
    status_.playing = false;
    status_.ready = false;
    status_.cancelled = true;
    status_.error.clear();
    solve_due_ = false;
    fresh_ = false;
    if (!preparing_)
    {
        // The run before the dropped restart: not stepped nor shown again (a frame of its
        // steps may be under way), kept for the next restart's topology and factor.
        done_.wait(lock, [&] { return !busy_; });
        if (run_)
            superseded_ = std::move(run_);
    }
    done_.notify_all();
    return true;
}

void LiveSolver::set_phase_listener(
    std::function<void(const PreparationProgress::Snapshot&)> listener)
{
    std::lock_guard lock(mutex_);
    phase_listener_ = std::move(listener);
}

void LiveSolver::clear()
{
    std::unique_lock lock(mutex_);
    restart_.reset();
    pending_pins_.reset();
    steps_due_ = 0;
    ++generation_;
    if (preparing_)
        progress_->cancel(); // (it is dropped: a long factorization need not end first)
    done_.wait(lock, [&] { return !busy_; });
    run_.reset();
    superseded_.reset();
    const int restarts = status_.restarts, on_caller = status_.steps_on_caller;
    const std::uint64_t version = status_.energy_version;
    status_ = {};
    status_.restarts = restarts;
    status_.steps_on_caller = on_caller;
    status_.energy_version = version + 1; // the curve is gone
    energies_.clear();
    known_energy_.reset();
    energy_due_ = false;
    solve_due_ = false;
    fresh_ = false;
}

void LiveSolver::set_playing(bool playing, int frames, int steps, Scalar stop_tolerance,
                             int settle_fallback)
{
    {
        std::lock_guard lock(mutex_);
        const bool was = status_.playing;
        status_.playing = playing && (run_ != nullptr || restart_.has_value() || busy_);
        if (playing && !was)
        {
            frames_left_ = std::max(frames, 0);
            steps_left_ = std::max(steps, 0);
            settle_fallback_ = frames > 0 ? 0 : std::max(settle_fallback, 0);
            stop_tolerance_ = std::max(stop_tolerance, Scalar(0));
            status_.played = 0;
            status_.goal = steps_left_;
            status_.converged = false;
            ++rule_epoch_; // a run's gradients are relative to its first step's
        }
        if (!playing)
            frames_left_ = steps_left_ = 0;
    }
    wake_.notify_all();
}

void LiveSolver::resume()
{
    {
        std::lock_guard lock(mutex_);
        status_.playing = run_ != nullptr || restart_.has_value() || busy_;
    }
    wake_.notify_all();
}

void LiveSolver::set_iterations_per_frame(int n)
{
    std::lock_guard lock(mutex_);
    iterations_per_frame_ = std::max(1, n);
}

void LiveSolver::step_now(int n)
{
    std::unique_lock lock(mutex_);
    status_.playing = false;
    // (After a restart's own steps, if any: these go on from them.)
    done_.wait(lock, [&] { return !busy_ && !restart_ && !(steps_due_ > 0 && run_); });
    if (run_ && n > 0)
        run_steps(n, lock);
}

bool LiveSolver::wait_published()
{
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] {
        return fresh_ || (!status_.playing && !busy_ && !restart_ && !(solve_due_ && run_) &&
                          !(pending_pins_ && run_) && !(steps_due_ > 0 && run_));
    });
    return fresh_;
}

void LiveSolver::move_hard_targets(std::span<const Scalar> targets)
{
    {
        std::lock_guard lock(mutex_);
        if (busy_ || restart_)
        {
            // Not waited for: a preparation may take seconds, a frame of steps a while.
            pending_pins_.emplace(targets.begin(), targets.end());
        }
        else if (run_)
            place_pins(targets);
    }
    wake_.notify_all();
}

void LiveSolver::place_pins(std::span<const Scalar> targets)
{
    Session& session = run_->session();
    session.move_pins(targets); // (the free vertices stay: the minimizer on record)
    known_energy_.reset();      // new positions at the same step count
    energy_due_ = false;
    held_.reset();                    // the pins are fixed vertices that moved
    display_run_ = new_display_run(); // pins may move outside the changing part
    back_.assign(session.positions().begin(), session.positions().end());
    compute_display(back_, run_->mesh());
    std::swap(back_, published_);
    published_steps_ = status_.steps;
    std::swap(display_back_, display_published_);
    fresh_ = true;
    solve_due_ = solves_for_minimizer(session.recipe().method);
    done_.notify_all();
}

void LiveSolver::wait_prepared()
{
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return !preparing_ && !restart_; });
}

void LiveSolver::wait_idle()
{
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] {
        return !busy_ && !restart_ && !(heat_dirty_ && run_) &&
               !(energy_due_ && run_ && !status_.playing) && !(solve_due_ && run_) &&
               !(pending_pins_ && run_) && !(steps_due_ > 0 && run_);
    });
}

void LiveSolver::compute_display(std::span<const Scalar> x, const Mesh& mesh)
{
    update_display_geometry(x, mesh, vertex_faces_->offsets, vertex_faces_->faces, display_run_,
                            changing_, display_back_);
}

bool LiveSolver::take(std::vector<Scalar>& positions, DisplayGeometry& geometry, int& steps)
{
    {
        std::lock_guard lock(mutex_);
        if (!fresh_)
            return false;
        std::swap(positions, published_);
        std::swap(geometry, display_published_);
        steps = published_steps_;
        solves_taken_ = published_solves_;
        fresh_ = false;
    }
    wake_.notify_all(); // a playing worker waits for this
    return true;
}

const Mesh* LiveSolver::run_mesh() const
{
    std::lock_guard lock(mutex_);
    return run_ ? &run_->mesh() : nullptr;
}

int LiveSolver::solves_taken() const
{
    std::lock_guard lock(mutex_);
    return solves_taken_;
}

void LiveSolver::set_heat(std::optional<EnergyTerm> term)
{
    {
        std::lock_guard lock(mutex_);
        heat_term_ = term;
        heat_dirty_ = term.has_value();
        heat_fresh_ = false;
    }
    wake_.notify_all();
}

bool LiveSolver::take_heat(std::vector<float>& heat)
{
    std::lock_guard lock(mutex_);
    if (!heat_fresh_)
        return false;
    std::swap(heat, heat_published_);
    heat_fresh_ = false;
    return true;
}

void LiveSolver::compute_heat(std::optional<EnergyTerm> term)
{
    if (!term || !run_)
        return;
    shares_.resize(run_->session().positions().size() / 3);
    run_->session().vertex_energy(run_->session().positions(), *term, shares_);
    // The colours too (the interface only uploads them), of the free vertices alone: the
    // fixed ones' energy is the same whatever the run does.
    heat_back_ = heat_colors(shares_, heat_free_);
}

void LiveSolver::set_plot_gradient(bool on)
{
    std::lock_guard lock(mutex_);
    plot_gradient_ = on;
}

EnergySample LiveSolver::sample_now(int step, bool want_gradient, Scalar gradient)
{
    Session& session = run_->session();
    if (!held_)
        held_ = session.held_energy(session.positions());
    if (gradient < 0 && want_gradient)
        gradient = session.gradient(session.positions());
    return EnergySample{step, run_->energy(), *held_, gradient};
}

SolverStatus LiveSolver::status() const
{
    std::lock_guard lock(mutex_);
    SolverStatus status = status_;
    status.preparing = preparing_ || restart_.has_value();
    if (preparing_)
        status.preparation = progress_->snapshot();
    return status;
}

std::vector<EnergySample> LiveSolver::energies() const
{
    std::lock_guard lock(mutex_);
    return energies_;
}

std::vector<std::string> LiveSolver::notes() const
{
    std::lock_guard lock(mutex_);
    return notes_;
}

void LiveSolver::run_steps(int n, std::unique_lock<std::mutex>& lock)
{
    busy_ = true;
    const std::uint64_t generation = generation_;
    // A run until it settles, of a recipe with no unique minimizer: the energy's decrease
    // only slows as the unheld part shrinks toward a point, so it plays the steps of a run.
    if (status_.playing && status_.played == 0 && steps_left_ == 0 && settle_fallback_ > 0 &&
        !status_.no_minimizer.empty())
    {
        steps_left_ = settle_fallback_;
        status_.goal = settle_fallback_;
    }
    const Scalar tolerance =
        stop_tolerance_ > 0 ? stop_tolerance_ : run_->session().recipe().tolerance;
    if (status_.playing && steps_left_ > 0)
        n = std::min(n, steps_left_); // the run's last frame: only the steps left
    const int first = status_.steps;  // the step count of the positions now
    // Whether the run pauses after this frame unless the tolerance stops it first (then the
    // plot's last point must be the energy of the positions shown).
    const bool last_frame =
        !status_.playing || (steps_left_ > 0 && steps_left_ <= n) || frames_left_ == 1;
    std::optional<EnergySample> known = known_energy_;
    const std::optional<EnergyTerm> heat = heat_term_;
    const std::uint64_t rule_epoch = rule_epoch_;
    const bool want_gradient = plot_gradient_;
    lock.unlock();

    // Outside the lock: the interface keeps drawing while the steps run.
    const auto t = std::chrono::steady_clock::now();
    int done = 0;
    bool converged_now = false;
    bool solve_goes_on = false; // a frame of a progressive solve: the next one is due
    Scalar relative_gradient = -1;
    Session& session = run_->session();
    // A restart meanwhile drops this frame: its steps stop at the next one (a brush dab's
    // run superseded by the next dab's is not stepped to its end).
    const auto superseded = [&] {
        return generation_.load(std::memory_order_relaxed) != generation;
    };
    if (!held_) // (the steps move no fixed vertex: the same before and after them)
        held_ = session.held_energy(session.positions());
    if (solves_for_minimizer(session.recipe().method))
    {
        // Each step solves for the minimizer from where it starts: the run stops by run()'s
        // rule on the gradient, after one step (two when rounding leaves some to refine).
        DirectConvergence rule(session.recipe().tolerance);
        Scalar gradient_now = -1; // |r| where the frame ends, when the rule computed it
        // A pin drag: the minimizer follows the pins without a solve where it can.
        if (solving_ && session.follow_pins())
        {
            done = 1;
            converged_now = true;
        }
        else if (solving_ && session.can_solve_progressively())
        {
            // No factor: the step's conjugate gradients a frame at a time, the same sequence
            // going on from frame to frame (its iterations those of one solve), each frame
            // showing the shape so far (lower in energy every frame, the flip guard aside). A pin
            // moved meanwhile begins another step from the shape shown (place_pins). Once solved,
            // the rule judges it as a direct step.
            if (!session.progressive_solve_under_way())
                session.begin_progressive_solve();
            bool finished = false;
            const StepInfo info = session.advance_progressive_solve(
                progressive_iterations(session.free_vertices().size()), finished);
            done = 1;
            solve_goes_on = !finished;
            if (finished)
            {
                gradient_now = session.gradient(session.positions());
                converged_now = rule.stop_after(info.gradient, gradient_now);
            }
        }
        for (; done < n && !converged_now && !solve_goes_on && !superseded(); ++done)
        {
            const StepInfo info = run_->step();
            gradient_now = session.gradient(session.positions());
            converged_now = rule.stop_after(info.gradient, gradient_now);
        }
        known = sample_now(first + done, want_gradient, gradient_now);
    }
    else
    {
        // As run() steps: each step gives the energy and, with a tolerance, the gradient of
        // the positions it starts from (the fused sweep sums both); the run learns one step
        // late that they had converged (StepConvergence, from the run's first step), and
        // undoes that step.
        const bool tracked = tolerance > 0;
        if (!step_rule_ || step_rule_epoch_ != rule_epoch)
        {
            step_rule_.emplace(tolerance);
            step_rule_epoch_ = rule_epoch;
        }
        // Without the energy from the sweep nor a tolerance, the steps alone: the plot's
        // point is the frame's last positions' (below), not a pass per step.
        const bool per_step = session.fuses_energy() || tracked;
        // The fused sweep sums the gradient at little cost: the plot's, when shown.
        const bool step_gradient = tracked || (want_gradient && session.fuses_energy());
        for (; done < n && !per_step && !superseded(); ++done)
            session.step();
        for (; done < n && per_step && !superseded(); ++done)
        {
            TermEnergies start;
            const StepInfo info = session.step(start, step_gradient);
            known = EnergySample{first + done, start, *held_, step_gradient ? info.gradient : -1};
            if (tracked && step_rule_->converged_at(info.gradient))
            {
                session.revert_step();
                converged_now = true;
                break;
            }
        }
        // The frame's last step is one behind the positions (the next frame's first step
        // checks it); when the run stops here the plot ends on the shape shown, and its
        // gradient is checked as run() checks it.
        if (!converged_now && done > 0 && last_frame)
        {
            const Scalar gradient = tracked ? session.gradient(session.positions()) : -1;
            known = sample_now(first + done, want_gradient, gradient);
            converged_now = tracked && step_rule_->converged_at(gradient);
        }
        if (!per_step && done > 0)
            known = sample_now(first + done, want_gradient);
        if (tracked)
            relative_gradient = step_rule_->relative();
    }
    // (Nothing of a superseded frame is shown: its positions, geometry and colours are not
    // made.)
    const bool dropped = superseded();
    if (!dropped)
    {
        back_.assign(run_->session().positions().begin(), run_->session().positions().end());
        compute_display(back_, run_->mesh());
        compute_heat(heat);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();

    lock.lock();
    busy_ = false;
    if (generation == generation_) // (never after `dropped`: generations only grow)
    {
        status_.steps += done;
        if (std::this_thread::get_id() != worker_id_)
            status_.steps_on_caller += done;
        status_.step_ms = ms;
        status_.converged = converged_now;
        status_.relative_gradient = relative_gradient;
        status_.stop_tolerance = relative_gradient >= 0 ? tolerance : 0;
        if (status_.playing)
        {
            status_.played += done;
            const bool steps_done = steps_left_ > 0 && (steps_left_ -= done) <= 0;
            const bool frames_done = frames_left_ > 0 && --frames_left_ == 0;
            if (converged_now || steps_done || frames_done)
                status_.playing = false;
        }
        if (known && (energies_.empty() || energies_.back().step < known->step))
        {
            energies_.push_back(*known);
            ++status_.energy_version;
        }
        known_energy_ = known;
        // Paused meanwhile with the plot a step behind: the worker adds the last point.
        energy_due_ = known && known->step != status_.steps;
        if (energies_.size() > kMaxEnergySamples) // keep the whole curve, at half the detail
        {
            size_t kept = 0;
            for (size_t k = 0; k < energies_.size(); k += 2)
                energies_[kept++] = energies_[k];
            energies_.resize(kept);
        }
        std::swap(back_, published_);
        published_steps_ = status_.steps;
        if (solve_goes_on && !restart_)
            solve_due_ = true; // (a move of the pins meanwhile is pending: it comes first)
        else if (solving_ && !solve_due_) // not overtaken by another move of the pins
            ++solves_;
        published_solves_ = solves_;
        std::swap(display_back_, display_published_);
        fresh_ = true;
        if (heat && heat == heat_term_)
        {
            std::swap(heat_back_, heat_published_);
            heat_fresh_ = true;
            heat_dirty_ = false;
        }
    }
    done_.notify_all();
    wake_.notify_all();
}

LiveSolver::Prepared LiveSolver::prepare(Restart& r, std::unique_ptr<LocalityRun> previous,
                                         const std::shared_ptr<PreparationProgress>& progress,
                                         bool want_gradient)
{
    Prepared p;
    try
    {
        progress->enter(PreparationProgress::Phase::Assembling);
        const Mesh& base = *r.base;
        check_recipe(r.recipe, base);
        // The pins go where the recipe puts them: their targets, or without targets their
        // place in the base shape, wherever a run before put them. Only if one of them
        // moves are the start positions published: otherwise the interface already shows
        // them, and taking them would change nothing.
        const std::vector<Scalar>& shown = r.start.empty() ? base.positions : r.start;
        if (r.recipe.hard)
            for (size_t k = 0; k < r.recipe.hard->vertices.size(); ++k)
                for (size_t a = 0; a < 3; ++a)
                {
                    const size_t i = 3 * static_cast<size_t>(r.recipe.hard->vertices[k]) + a;
                    const Scalar place = r.recipe.hard->targets.empty()
                                             ? base.positions[i]
                                             : r.recipe.hard->targets[k][a];
                    p.moved = p.moved || shown[i] != place;
                    if (!r.start.empty())
                        r.start[i] = place;
                }
        // The same mesh: the factorization of the run before, whose analysis is kept when
        // the new system has its pattern (a weight's slider, "keep volume" ticked; at 1.25M
        // vertices 6 s of 15 are the analysis); and with the same parts its topology too (a
        // dab of the smoothing brush changes weights, not connectivity).
        std::unique_ptr<SparseCholesky> analysed;
        std::optional<Topology> topology;
        if (previous && (previous->shared_mesh() == r.base ||
                         (previous->topology().vertex_count == base.vertex_count() &&
                          previous->mesh().face_offsets == base.face_offsets &&
                          previous->mesh().face_vertices == base.face_vertices)))
        {
            analysed = previous->session().take_factorization();
            if (previous->topology().parts == required_topology(r.recipe))
                topology = std::move(*previous).take_topology();
        }
        previous.reset(); // (its arrays go before the new run's are built)
        if (!topology)
            topology = build_topology(base, required_topology(r.recipe));
        if (!analysed)
            analysed = std::make_unique<SparseCholesky>();
        analysed->report_to(progress);
        p.run = std::make_unique<LocalityRun>(r.base, r.order, r.recipe, std::move(*topology),
                                              std::move(analysed), std::move(r.start));
        p.notes = p.run->session().notes();
        if (const SparseCholesky* f = p.run->session().factorization())
            p.factor_stats = f->stats();
        // The curve's first point: the held part as of now (the pins are placed).
        Session& session = p.run->session();
        p.start = EnergySample{0, p.run->energy(), session.held_energy(session.positions()),
                               want_gradient ? session.gradient(session.positions()) : -1};
        p.free = session.free_flags();
        vertex_faces_ = r.vertex_faces;
        // Frames of this run recompute and upload only what its steps move.
        display_run_ = new_display_run();
        changing_ = std::make_shared<const ChangingPart>(
            changing_part(p.run->mesh(), vertex_faces_->offsets, vertex_faces_->faces,
                          p.run->session().free_vertices()));
        // Published only when a pin moved: the interface shows the start otherwise, and
        // the next steps publish their own (a brush dab steps at once).
        if (p.moved)
        {
            p.published.assign(p.run->session().positions().begin(),
                               p.run->session().positions().end());
            compute_display(p.published, p.run->mesh());
        }
        // (A restart of the minimizer's methods has checked it: it failed, or all is held.)
        if (r.recipe.method == Method::Taubin)
            p.no_minimizer = kTaubinHasNoMinimizer;
        else if (!solves_for_minimizer(r.recipe.method))
            p.no_minimizer = p.run->session().unheld_part().value_or("");
        progress->enter(PreparationProgress::Phase::Done);
    }
    catch (const PreparationCancelled&)
    {
        p = Prepared{};
        p.cancelled = true;
    }
    catch (const std::exception& e)
    {
        p = Prepared{};
        p.error = e.what();
    }
    return p;
}

void LiveSolver::worker()
{
    std::unique_lock lock(mutex_);
    worker_id_ = std::this_thread::get_id();
    for (;;)
    {
        wake_.wait(lock, [&] {
            return quit_ || (restart_ && !busy_) ||
                   (pending_pins_ && run_ && !busy_ && !restart_) ||
                   (status_.playing && run_ && !fresh_ && !busy_ && !restart_) ||
                   (heat_dirty_ && run_ && !busy_ && !restart_) ||
                   (energy_due_ && run_ && !busy_ && !restart_ && !status_.playing) ||
                   (solve_due_ && run_ && !busy_ && !restart_ && !status_.playing) ||
                   (steps_due_ > 0 && run_ && !busy_ && !restart_ && !status_.playing);
        });
        if (quit_)
            return;
        if (pending_pins_ && run_ && !busy_ && !restart_)
        {
            // Targets given while this thread prepared or stepped: the pins first, then
            // the direct method's solve for them.
            const std::vector<Scalar> targets = std::move(*pending_pins_);
            pending_pins_.reset();
            place_pins(targets);
            continue;
        }
        if (solve_due_ && run_ && !restart_ && !status_.playing && !busy_)
        {
            // The direct method's minimizer for the recipe as it is now (at most a few
            // refining steps; the first lands on it).
            solve_due_ = false;
            solving_ = true;
            run_steps(kDirectSolveSteps, lock);
            solving_ = false;
            continue;
        }
        if (steps_due_ > 0 && run_ && !restart_ && !status_.playing && !busy_)
        {
            // The restart's own steps (a brush dab's run), after the direct method's solve,
            // as step_now would run them on the caller's thread: the same bits.
            run_steps(std::exchange(steps_due_, 0), lock);
            continue;
        }
        if (energy_due_ && !restart_ && !status_.playing && !(heat_dirty_ && run_))
        {
            // The plot's last point for the positions shown (the run paused between the
            // frame's steps and its publication).
            busy_ = true;
            const std::uint64_t generation = generation_;
            const bool want_gradient = plot_gradient_;
            const int steps = status_.steps;
            lock.unlock();
            const EnergySample sample = sample_now(steps, want_gradient);
            lock.lock();
            busy_ = false;
            if (generation == generation_ && energy_due_)
            {
                known_energy_ = sample;
                energies_.push_back(*known_energy_);
                ++status_.energy_version;
            }
            energy_due_ = false;
            done_.notify_all();
            continue;
        }
        if (heat_dirty_ && !restart_ && !status_.playing)
        {
            // Shares for the positions as they are (the heat map was just turned on).
            busy_ = true;
            const std::optional<EnergyTerm> heat = heat_term_;
            const std::uint64_t generation = generation_;
            lock.unlock();
            compute_heat(heat);
            lock.lock();
            busy_ = false;
            if (generation == generation_ && heat == heat_term_)
            {
                std::swap(heat_back_, heat_published_);
                heat_fresh_ = true;
            }
            heat_dirty_ = false;
            done_.notify_all();
            continue;
        }
        if (restart_)
        {
            Restart r = std::move(*restart_);
            restart_.reset();
            busy_ = true;
            preparing_ = true;
            const std::uint64_t generation = generation_;
            progress_ = std::make_shared<PreparationProgress>();
            progress_->set_listener(phase_listener_);
            const std::shared_ptr<PreparationProgress> progress = progress_;
            // The run before is this thread's while it restarts: taken under the lock, as
            // the interface thread reads run_ (whether there is one) under it.
            std::unique_ptr<LocalityRun> previous = run_ ? std::move(run_) : std::move(superseded_);
            superseded_.reset();
            held_.reset();
            const bool want_gradient = plot_gradient_;
            lock.unlock();

            const auto t = std::chrono::steady_clock::now();
            Prepared p = prepare(r, std::move(previous), progress, want_gradient);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t)
                    .count();

            lock.lock();
            busy_ = false;
            preparing_ = false;
            if (generation != generation_)
                superseded_ = std::move(p.run); // (null when cancelled)
            else
            {
                run_ = std::move(p.run);
                status_.ready = run_ != nullptr;
                status_.error = p.error;
                status_.cancelled = p.cancelled;
                status_.no_minimizer = std::move(p.no_minimizer);
                notes_ = std::move(p.notes);
                status_.precompute_ms = ms;
                status_.analyse_ms = 1e3 * p.factor_stats.analyse_seconds;
                status_.factor_ms = 1e3 * p.factor_stats.factor_seconds;
                status_.analysis_kept = p.factor_stats.factorizations > 1;
                ++status_.restarts;
                // Playing if asked for since the restart was requested (and it worked).
                status_.playing = status_.playing && run_ != nullptr;
                if (run_)
                {
                    heat_dirty_ = heat_term_.has_value();
                    energies_ = {p.start};
                    held_ = p.start.held;
                    heat_free_ = std::move(p.free);
                    known_energy_ = energies_.back();
                    energy_due_ = false;
                    ++status_.energy_version;
                    solve_due_ = solves_for_minimizer(r.recipe.method);
                    steps_due_ = r.steps;
                    if (p.moved)
                    {
                        published_ = std::move(p.published);
                        published_steps_ = 0;
                        std::swap(display_back_, display_published_);
                    }
                    fresh_ = p.moved;
                }
            }
            done_.notify_all();
            continue;
        }
        run_steps(iterations_per_frame_, lock);
    }
}

} // namespace meshfair::app
