// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/render/mesh_draw_data.h"
#include "core/recipe/locality_run.h"
#include "core/solver/preparation_progress.h"

namespace meshfair::app {

//! One point of the energy curve: the energy after `step` steps of the current run.
struct EnergySample
{
    int step = 0;
    TermEnergies energy;
    //! The part of `energy` no step changes: its elements without a free vertex
    //! (Session::held_energy). energy - held is the energy of what moves, which the plot
    //! shows for a region (the rest of the mesh's energy would flatten its curve).
    TermEnergies held;
    //! |r| over the free vertices at these positions, when the plot asked for it
    //! (LiveSolver::set_plot_gradient) or the run's rule computed it; -1: not known.
    Scalar gradient = -1;
};

//! What the solver has done, for the solver panel.
struct SolverStatus
{
    bool ready = false;     //!< precomputed for the current recipe
    bool playing = false;   //!< stepping on the worker thread
    bool converged = false; //!< stopped by the recipe's tolerance
    int steps = 0;          //!< steps of the current run
    int played = 0;         //!< steps since the last play began
    int goal = 0;           //!< steps that play runs (0: until it settles)
    //! A run of steps with a tolerance: the gradient where the last frame's steps ended,
    //! relative to the run's first step's (StepConvergence), and the tolerance it stops
    //! at; -1 and 0 otherwise.
    Scalar relative_gradient = -1;
    Scalar stop_tolerance = 0;
    std::string error; //!< why the last restart failed (the recipe did not fit)
    //! Why the recipe has no unique minimizer (Session::unheld_part), or empty: a run
    //! "until it settles" would only shrink the free part that nothing holds.
    std::string no_minimizer;
    double step_ms = 0;       //!< the last frame's steps, on the worker
    double precompute_ms = 0; //!< the last precomputation
    //! Its factorization's analysis and numeric factorization (0 without a factor), and
    //! whether the analysis was the run before's, kept because only weights changed.
    double analyse_ms = 0;
    double factor_ms = 0;
    bool analysis_kept = false;
    //! A restart's preparation is pending or under way on the worker, and where it is
    //! (the phase of a pending one: Assembling, not yet begun).
    bool preparing = false;
    PreparationProgress::Snapshot preparation;
    //! The last restart's preparation was cancelled (cancel_preparation): no run until
    //! the next restart.
    bool cancelled = false;
    int restarts = 0; //!< precomputations so far
    //! Steps run on a caller's thread (step_now: the Step command), not on the worker; a
    //! smoothing-brush dab adds none (its run is the worker's).
    int steps_on_caller = 0;
    std::uint64_t energy_version = 0; //!< changes of the energy curve so far
};

//! The faces around each vertex (the draw data's vertex_face_offsets and vertex_faces), from
//! which the solver's thread computes each frame's display geometry.
struct VertexFaces
{
    std::vector<Index> offsets, faces;
};

//! \brief The editor's solver: a LocalityRun (the command line's pipeline) of the
//! document's base shape and recipe, stepped on a worker thread while playing, so that the
//! interface never waits for it, or on the caller's thread for a step or a script.
//!
//! The precomputation runs once per restart (a recipe change), on the worker. While
//! playing, the worker runs `iterations_per_frame` steps, publishes the positions and waits
//! until the interface has taken them, so the solver paces itself to the frames shown.
class LiveSolver
{
public:
    LiveSolver();
    ~LiveSolver();
    LiveSolver(const LiveSolver&) = delete;
    LiveSolver& operator=(const LiveSolver&) = delete;

    //! \brief Starts a run for `base` and `recipe`, both in the locality numbering `order`
    //! made (the document's; base's positions are the recipe's input shape), from the
    //! positions `start` (3 #V; empty: the base). Positions and shares are published in that
    //! numbering.
    //! Returns at once: the precomputation happens on the worker. Stops playing.
    //! `vertex_faces` (the draw data's faces around each vertex) lets the solver's thread
    //! compute the display geometry of each frame. The base, the order and the faces are
    //! shared with the caller, never copied (a restart per slider value or brush dab copies
    //! no mesh; the run before's topology and factor are kept without comparing
    //! connectivities when the base is the same object); they must stay unchanged while a
    //! run holds them: a new shape is a new object.
    //! `steps` > 0: once prepared (and, with the direct method, solved), the worker runs
    //! that many steps, as step_now would, and publishes them (a smoothing-brush dab's run).
    //! A restart supersedes the one before it: a pending one is dropped unprepared, one being
    //! prepared is never stepped nor shown, and steps under way stop at the next step.
    void restart(std::shared_ptr<const Mesh> base, std::shared_ptr<const LocalityOrder> order,
                 Recipe recipe, std::vector<Scalar> start,
                 std::shared_ptr<const VertexFaces> vertex_faces, int steps = 0);
    //! No run (no recipe, or one with problems): nothing steps.
    void clear();
    //! \brief Stops the restart pending or being prepared (a long factorization): it is
    //! dropped, with the run before it, and nothing runs until the next restart
    //! (status().cancelled). A preparation under way stops where its next phase would
    //! begin (PreparationProgress). Returns at once; false when nothing was preparing.
    bool cancel_preparation();
    //! \brief Called on the worker as each phase of a restart's preparation begins (a
    //! trace; a test that holds a phase to cancel it). Set before restarts are made.
    void set_phase_listener(std::function<void(const PreparationProgress::Snapshot&)> listener);

    //! \brief Plays (on the worker) or pauses. It pauses by itself after `frames` frames or
    //! `steps` steps when > 0 (the last frame runs only the steps left), and when the
    //! gradient relative to the run's first step's falls to `stop_tolerance` (> 0) or the
    //! recipe's tolerance (run()'s rule, StepConvergence; the direct method's own).
    //! With steps == 0 (until it settles), `settle_fallback` > 0 steps are played instead
    //! where the recipe has no unique minimizer (SolverStatus::no_minimizer).
    void set_playing(bool playing, int frames = 0, int steps = 0, Scalar stop_tolerance = 0,
                     int settle_fallback = 0);
    //! Plays on after a restart during a run, with what was left of its steps and frames.
    void resume();
    //! \brief New targets for the recipe's hard vertices (3 per vertex, in the recipe's
    //! order): the pins move there and the run goes on, with no precomputation (hard
    //! vertices are fixed: their targets are right-hand side only). Publishes the positions.
    //! With the direct method the worker then solves for the new minimizer (a
    //! back-substitution with the factorization kept) and publishes it too.
    //! Never waits for the worker: while it prepares a restart or steps, the targets are
    //! kept and the worker moves the pins when it is done (the newest targets only; a
    //! restart after them has them already).
    void move_hard_targets(std::span<const Scalar> targets);
    void set_iterations_per_frame(int n);
    //! \brief Runs `n` steps on the calling thread (waiting for the precomputation and for
    //! a frame in progress); publishes the result. Stops playing.
    void step_now(int n);
    //! \brief Waits until a frame is published or playing stops; true when there is one to
    //! take. For scripts and tests, which show frames as fast as they come.
    bool wait_published();
    //! Waits until the worker is idle (precomputed, not mid-frame, the direct method's
    //! minimizer solved, a restart's steps run); for tests, scripts and a stroke's end.
    void wait_idle();
    //! Waits until no restart is pending or being prepared (a run may go on playing).
    void wait_prepared();

    //! \brief Also publish each vertex's share of `term` with every frame (a heat map;
    //! nullopt: none). Computed on the worker, at once for the current positions.
    void set_heat(std::optional<EnergyTerm> term);
    //! \brief Also give each point of the energy curve the gradient |r| (the plot's
    //! relative gradient): free in the fused step's sweep, one pass a frame otherwise, so
    //! asked for only while the plot is shown. From the next frame on.
    void set_plot_gradient(bool on);
    //! The newest heat-map colours not yet taken (heat_colors of the shares), into `heat`.
    bool take_heat(std::vector<float>& heat);
    //! \brief The newest positions not yet taken, swapped into `positions`, with the
    //! frame's display geometry into `geometry` and the run's step count at those positions
    //! into `steps` (status() may already count a later frame's); false when there are
    //! none. Called once per frame by the interface.
    bool take(std::vector<Scalar>& positions, DisplayGeometry& geometry, int& steps);
    //! \brief How many of the direct method's own solves (after a restart, after pins
    //! moved) the positions last taken include: a trace can say when the shape shown is the
    //! minimizer.
    int solves_taken() const;
    //! The mesh the current run solves on (the base given to restart, when shared), or
    //! nullptr without a run.
    const Mesh* run_mesh() const;
    SolverStatus status() const;
    //! The energy after each published frame of the current run (step 0 first).
    std::vector<EnergySample> energies() const;
    //! \brief What the current run does besides the recipe's letter (Session::notes: how
    //! open components' volumes are kept, a falloff with nothing to fade from); new with
    //! each restart (status().restarts), so read once per restart, not once per frame.
    std::vector<std::string> notes() const;

private:
    void worker();
    //! Moves the run's pins to `targets` and publishes the positions; `lock` holds mutex_.
    void place_pins(std::span<const Scalar> targets);
    //! Steps `n` times on the run; `lock` holds mutex_, released while stepping.
    void run_steps(int n, std::unique_lock<std::mutex>& lock);

    mutable std::mutex mutex_;
    std::vector<std::string> notes_; //!< the current run's (notes()), under mutex_
    std::condition_variable wake_;   // to the worker: work to do
    std::condition_variable done_;   // to callers: a frame published, a restart finished
    struct Restart
    {
        std::shared_ptr<const Mesh> base;
        std::shared_ptr<const LocalityOrder> order;
        Recipe recipe;
        std::shared_ptr<const VertexFaces> vertex_faces;
        std::vector<Scalar> start;
        int steps = 0; // run once prepared (restart's `steps`)
    };
    //! What a restart's preparation made: the run (null when it failed or was cancelled)
    //! and what the status and the first frame take from it.
    struct Prepared
    {
        std::unique_ptr<LocalityRun> run;
        std::string error;
        bool cancelled = false;
        std::vector<std::string> notes;
        EnergySample start; // the curve's first point
        std::vector<char> free;
        bool moved = false;            // a pin moved: the start differs from what is shown
        std::vector<Scalar> published; // the start positions, when a pin moved
        FactorStats factor_stats;
        std::string no_minimizer;
    };
    //! The restart's preparation, on the worker with the lock released.
    Prepared prepare(Restart& r, std::unique_ptr<LocalityRun> previous,
                     const std::shared_ptr<PreparationProgress>& progress, bool want_gradient);
    std::optional<Restart> restart_;   // pending, for the worker
    std::unique_ptr<LocalityRun> run_; // touched by whoever holds `busy_`
    // A restart's run that a newer restart replaced before it was shown (a slider dragged
    // through many values): never stepped nor shown, kept for the next restart's topology
    // and factorization, as run_ is. The worker's, under the lock.
    std::unique_ptr<LocalityRun> superseded_;
    // The preparation under way (preparing_), the worker's; read and cancelled under the lock.
    std::shared_ptr<PreparationProgress> progress_;
    bool preparing_ = false;
    std::function<void(const PreparationProgress::Snapshot&)> phase_listener_;
    // Targets for the pins given while the worker was busy (move_hard_targets).
    std::optional<std::vector<Scalar>> pending_pins_;
    bool busy_ = false; // the worker is precomputing or stepping
    // Steps the current run owes its restart (restart's `steps`): run on the worker once
    // prepared and solved, not playing.
    int steps_due_ = 0;
    std::thread::id worker_id_; // (steps_on_caller counts the others' steps)
    bool quit_ = false;
    int iterations_per_frame_ = 1;
    int frames_left_ = 0;          // > 0: frames to play before pausing
    int steps_left_ = 0;           // > 0: steps to play before pausing
    int settle_fallback_ = 0;      // steps in place of "until it settles" without a minimizer
    Scalar stop_tolerance_ = 0;    // > 0: pause when the relative gradient falls to it
    std::uint64_t rule_epoch_ = 0; // a new run (played from its start) or a restart
    // The worker's stopping rule of step methods and the rule_epoch_ it began in; only
    // the thread that steps (busy_) touches them.
    std::optional<StepConvergence> step_rule_;
    std::uint64_t step_rule_epoch_ = 0;
    // Restarts so far: a frame of an older run is dropped. Written under the lock; read
    // without it by the stepping thread, which stops the steps of a run superseded meanwhile.
    std::atomic<std::uint64_t> generation_ = 0;
    SolverStatus status_;
    std::vector<Scalar> published_; // file order, newest
    int published_steps_ = 0;       // the run's step count at published_
    int published_solves_ = 0;      // direct solves finished at published_ (solves())
    int solves_ = 0;                // direct solves finished so far
    int solves_taken_ = 0;          // published_solves_ of the positions last taken
    bool solving_ = false;          // the worker runs a direct solve (not a played frame)
    std::vector<Scalar> back_;      // file order, being written (while busy_)
    DisplayGeometry display_published_, display_back_;
    std::shared_ptr<const VertexFaces> vertex_faces_; // of the run (set at a restart)
    //! The display geometry's run (a new one at each restart and when pins move: positions
    //! outside the free vertices change) and the part of it the steps change.
    std::uint64_t display_run_ = 0;
    std::shared_ptr<const ChangingPart> changing_;
    //! The display geometry of `x` into display_back_ (outside the lock, while busy_): its
    //! changing part only when display_back_ holds a frame of the same display run.
    void compute_display(std::span<const Scalar> x, const Mesh& mesh);
    bool fresh_ = false; // published_ not yet taken
    std::vector<EnergySample> energies_;
    //! The newest energy known and the step count of the positions it is of: a step's
    //! sweep gives the energy of the positions it starts from, one step behind.
    std::optional<EnergySample> known_energy_;
    //! The run's held energy at the current positions of its fixed vertices (none: to
    //! compute, after a restart or a move of the pins); the worker's.
    std::optional<TermEnergies> held_;
    //! The energy at the run's positions now, as a point of the curve at `step` (the
    //! held part and, when asked for or `gradient` >= 0 is given, the gradient); on the
    //! worker, outside the lock.
    EnergySample sample_now(int step, bool want_gradient, Scalar gradient = -1);
    bool plot_gradient_ = false;
    bool energy_due_ = false; // the plot's last point is behind the positions (paused)
    // The direct method's run shows its minimizer by itself: solved on the worker after a
    // restart and after the pins move, without playing.
    bool solve_due_ = false;

    std::optional<EnergyTerm> heat_term_;
    bool heat_dirty_ = false;           // shares wanted for the current positions
    std::vector<float> heat_published_; // colours (heat_colors), newest
    std::vector<float> heat_back_;      // being written (while busy_)
    std::vector<Scalar> shares_;        // the shares behind heat_back_
    std::vector<char> heat_free_;       // the run's free vertices (the map shows only them)
    bool heat_fresh_ = false;
    //! The shares and their colours into heat_back_ (outside the lock, while busy_).
    void compute_heat(std::optional<EnergyTerm> term);
    std::thread thread_; // last: started once everything else exists
};

} // namespace meshfair::app
