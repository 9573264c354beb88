// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/editor_drag.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/bench/bench_common.h"
#include "app/edit/constraint_sets.h"
#include "app/editor/persistence.h"
#include "app/render/mesh_draw_data.h"
#include "core/recipe/locality_run.h"

namespace meshfair::bench {

namespace {

using namespace meshfair::app;
using Clock = std::chrono::steady_clock;

double gigabytes(double bytes)
{
    return bytes / 1e9;
}

//! The largest distance between a vertex's places in two shapes (3 #V values each).
double max_distance(std::span<const Scalar> a, std::span<const Scalar> b)
{
    double d2 = 0;
    for (size_t k = 0; k < a.size(); k += 3)
    {
        const double x = a[k] - b[k], y = a[k + 1] - b[k + 1], z = a[k + 2] - b[k + 2];
        d2 = std::max(d2, x * x + y * y + z * z);
    }
    return std::sqrt(d2);
}

//! The pins' targets as the solver gets them: 3 per hard vertex, in the recipe's order.
std::vector<Scalar> hard_targets(const Document& d)
{
    const Recipe recipe = current_recipe(d);
    std::vector<Scalar> targets;
    for (const Vec3& t : recipe.hard->targets)
        targets.insert(targets.end(), t.begin(), t.end());
    return targets;
}

//! \brief The minimizer of the document's recipe for given pin targets, by a run of its
//! own (the recipe Export writes, the command line's pipeline, the direct method): what the
//! editor's shapes are checked against, outside the timings. It holds a second factor.
class Minimizer
{
public:
    explicit Minimizer(const Document& d) : run_(base_mesh(d), d.order, direct_recipe(d)) {}
    //! The minimizer for `targets` (hard_targets' form), from the last one.
    const std::vector<Scalar>& solve(std::span<const Scalar> targets)
    {
        Session& session = run_.session();
        session.set_hard_targets(targets);
        x_.assign(session.positions().begin(), session.positions().end());
        session.apply_hard_targets(x_);
        session.set_positions(x_);
        (void)run(session);
        x_.assign(session.positions().begin(), session.positions().end());
        return x_;
    }
    Session& session() { return run_.session(); }
    const Mesh& mesh() const { return run_.mesh(); }

private:
    static Mesh base_mesh(const Document& d)
    {
        Mesh base;
        base.positions = d.base_positions;
        base.face_offsets = d.mesh.face_offsets;
        base.face_vertices = d.mesh.face_vertices;
        return base;
    }
    static Recipe direct_recipe(const Document& d)
    {
        Recipe r = current_recipe(d);
        r.method = Method::Direct;
        r.iterations = 10; // the direct method's rule stops it after one or two
        return r;
    }
    LocalityRun run_;
    std::vector<Scalar> x_;
};

//! A rectangle of the Rectangle tool, as the mouse draws it: the selection it replaces.
void rectangle(EditorSession& s, double x0, double y0, double x1, double y1)
{
    s.dispatch(cmd::SetTool{ToolKind::Rectangle});
    s.mouse_press(MouseButton::Left, {}, x0, y0);
    s.mouse_move(x1, y1);
    s.mouse_release(MouseButton::Left, x1, y1);
}

//! \brief The region "patch" (a rectangle through the surface around the view's centre)
//! and the pins "pins" (a small one on the surface at the centre), in the front view, as
//! an artist makes them; false (with the editor's message) when either came out empty.
bool make_patch_and_pins(EditorSession& s, int width, int height, const DragOptions& o)
{
    s.dispatch(cmd::SetView{StandardView::Front});
    s.dispatch(cmd::FrameAll{});
    s.dispatch(cmd::SetElements{ElementKind::Vertices});
    const double cx = 0.5 * width, cy = 0.5 * height;
    const double rx = 0.5 * o.region * width, ry = 0.5 * o.region * height, p = 0.5 * o.pins_px;
    s.dispatch(cmd::SetThrough{true});
    rectangle(s, cx - rx, cy - ry, cx + rx, cy + ry);
    if (!s.dispatch(cmd::CreateSet{ConstraintKind::Region, "patch"}))
        return false;
    s.dispatch(cmd::SetThrough{false});
    rectangle(s, cx - p, cy - p, cx + p, cy + p);
    return s.dispatch(cmd::CreateSet{ConstraintKind::Pin, "pins"});
}

const ConstraintSet& set_named(const EditorSession& s, const std::string& name)
{
    return s.document().sets[*s.set_named(name)];
}

//! A frame the interface took after a move, and when.
struct Taken
{
    double ms = 0;
    std::vector<Scalar> x;
};

//! \brief What the interface saw after one move: the move's own time (the tool's command),
//! the next update's (the targets handed to the solver, a frame with the pins moved taken),
//! and each frame taken until the solver was idle, with its positions, as the window takes
//! them (EditorSession::update), waiting on the solver's publication (take_frame).
struct MoveFrames
{
    double move_ms = 0, update_ms = 0;
    std::vector<Taken> frames;
};

MoveFrames frames_after(EditorSession& s, const std::function<void()>& move)
{
    MoveFrames out;
    std::uint64_t seen = s.document().versions.positions;
    const auto t = Clock::now();
    const auto keep = [&] {
        const double ms = ms_since(t); // before the copy, which only the bench makes
        if (s.document().versions.positions == seen)
            return;
        seen = s.document().versions.positions;
        out.frames.push_back({ms, s.document().mesh.positions});
    };
    move();
    out.move_ms = ms_since(t);
    s.update();
    out.update_ms = ms_since(t) - out.move_ms;
    keep();
    while (s.take_frame()) // false once the solver is idle (the minimizer published)
        keep();
    return out;
}

//! \brief One move judged: the time of the first frame within `tolerance` of the minimizer
//! (nullopt: none was), and how far the shape before the move and the last frame were.
struct Judged
{
    std::optional<double> ms;
    double before = 0, last = 0;
};

Judged judge(const MoveFrames& m, std::span<const Scalar> before, std::span<const Scalar> minimizer,
             double tolerance)
{
    Judged j;
    j.before = max_distance(before, minimizer);
    for (const Taken& f : m.frames)
    {
        j.last = max_distance(f.x, minimizer);
        if (!j.ms && j.last <= tolerance)
            j.ms = f.ms;
    }
    return j;
}

//! The figures of the direct drag's timed moves.
struct DragSeries
{
    std::vector<double> latency, move, update, solver, before, last;
    int missed = 0, solves = 0, restarts = 0;
};

void print_row(const char* name, const std::vector<double>& v)
{
    std::printf("| %s | %zu | %.2f | %.2f |\n", name, v.size(), median(v), max_of(v));
}

//! The drag's figures as the bench prints them (medians and the largest sample).
void print_drag(const DragSeries& d, std::optional<double> first_ms, const SolverStatus& first,
                double diagonal, const DragOptions& o)
{
    std::printf("\n| M drag, %s with the thin plate | samples | median | max |\n",
                o.conjugate_gradients ? "conjugate gradients" : "direct method");
    std::printf("|---|---|---|---|\n");
    std::printf(
        "| first result: the first move (dome settings: analysis, factorization, solve) | 1 | "
        "%s | |\n",
        first_ms ? (std::to_string(std::lround(*first_ms)) + " ms").c_str() : "never within");
    std::printf(
        "| of which the solver's precomputation (the direct method's analysis, factorization) | 1 "
        "| %.0f ms | |\n",
        first.precompute_ms);
    std::printf("| of which the solver's solve frame | 1 | %.0f ms | |\n", first.step_ms);
    print_row("a move: the minimizer shown within the tolerance, ms", d.latency);
    print_row("of which the mouse move (the M tool's MovePins), ms", d.move);
    print_row("of which the next update (targets to the solver, pins moved), ms", d.update);
    print_row("the solver's frame (solves, energy, display geometry), ms", d.solver);
    std::vector<double> before_rel, last_rel;
    for (const double b : d.before)
        before_rel.push_back(b / diagonal);
    for (const double l : d.last)
        last_rel.push_back(l / diagonal);
    std::printf("| the shape before a move, from its minimizer (diagonals) | %zu | %.2e | %.2e |\n",
                before_rel.size(), median(before_rel), max_of(before_rel));
    std::printf(
        "| the last frame of a move, from its minimizer (diagonals) | %zu | %.2e | %.2e |\n",
        last_rel.size(), median(last_rel), max_of(last_rel));
    const size_t n = d.latency.size() + static_cast<size_t>(d.missed);
    const auto within = std::count_if(d.latency.begin(), d.latency.end(),
                                      [&](double ms) { return ms <= o.budget_ms; });
    std::printf(
        "\nmoves within %.0e of the diagonal in %.0f ms: %ld of %zu (%d never within it); "
        "solver steps per move %.1f; restarts during the drag: %d\n",
        o.tolerance, o.budget_ms, static_cast<long>(within), n, d.missed,
        n ? double(d.solves) / double(n) : 0.0, d.restarts);
    std::printf("each move, in order, ms:");
    for (const double ms : d.latency)
        std::printf(" %.0f", ms);
    std::printf("\n");
}

//! A move of the Jacobi peer: how far its shapes were from the move's minimizer, and when.
struct PeerMove
{
    double before = 0;        //!< the shape before the move, from the new minimizer
    double at_budget = 0;     //!< the last frame taken within budget_ms, from it
    std::optional<double> ms; //!< when a frame was within the tolerance
    double last = 0;          //!< the last frame taken, from it
    int steps_at_budget = 0;  //!< solver steps by budget_ms
    int steps = 0;            //!< solver steps by the end
};

//! \brief The Jacobi peer's move: the same energy, Jacobi steps played as the editor plays
//! them (one step a frame, each frame taken as it comes), the pins moved by `offset` with
//! the MovePins command (the M tool would take the direct method), until the shape is
//! within the tolerance or jacobi_cap_ms has passed.
PeerMove jacobi_move(EditorSession& s, const Vec3& offset, std::span<const Scalar> minimizer,
                     double tolerance, const DragOptions& o, const Interaction& drag)
{
    PeerMove p;
    p.before = p.at_budget = max_distance(s.document().mesh.positions, minimizer);
    const int steps = s.document().steps_from_base;
    const auto t = Clock::now();
    s.dispatch(cmd::MovePins{"pins", offset}, drag);
    s.update(); // the targets to the solver: a frame with the pins moved
    // Each pass has a frame taken: the first with the pins moved, then the steps' own.
    for (bool taken = true; taken; taken = s.take_frame())
    {
        const double ms = ms_since(t);
        p.last = max_distance(s.document().mesh.positions, minimizer);
        if (ms <= o.budget_ms)
        {
            p.at_budget = p.last;
            p.steps_at_budget = s.document().steps_from_base - steps;
        }
        if (p.last <= tolerance)
            p.ms = ms;
        if (p.ms || ms >= o.jacobi_cap_ms)
            break;
    }
    p.steps = s.document().steps_from_base - steps;
    return p;
}

void print_peer(const std::vector<PeerMove>& moves, double diagonal, const DragOptions& o)
{
    std::vector<double> before, at_budget, last, ms, steps, all_steps;
    for (const PeerMove& m : moves)
    {
        before.push_back(m.before / diagonal);
        at_budget.push_back(m.at_budget / diagonal);
        last.push_back(m.last / diagonal);
        steps.push_back(m.steps_at_budget);
        all_steps.push_back(m.steps);
        ms.push_back(m.ms ? *m.ms : o.jacobi_cap_ms);
    }
    std::printf("\n| Jacobi peer, the same energy (%zu moves) | median | max |\n|---|---|---|\n",
                moves.size());
    std::printf("| the shape before a move, from its minimizer (diagonals) | %.2e | %.2e |\n",
                median(before), max_of(before));
    std::printf("| %.0f ms after the move, from the minimizer (diagonals) | %.2e | %.2e |\n",
                o.budget_ms, median(at_budget), max_of(at_budget));
    std::printf("| steps shown by %.0f ms | %.0f | %.0f |\n", o.budget_ms, median(steps),
                max_of(steps));
    std::printf(
        "| at the end (within the tolerance or %.0f ms), from the minimizer | %.2e | %.2e |\n",
        o.jacobi_cap_ms, median(last), max_of(last));
    std::printf("| steps shown by the end | %.0f | %.0f |\n", median(all_steps), max_of(all_steps));
    const auto reached = std::count_if(moves.begin(), moves.end(),
                                       [](const PeerMove& m) { return m.ms.has_value(); });
    std::printf(
        "| time to within %.0e of the diagonal, ms (%ld of %zu reached it; the others "
        "count as %.0f) | %.0f | %.0f |\n",
        o.tolerance, static_cast<long>(reached), moves.size(), o.jacobi_cap_ms, median(ms),
        max_of(ms));
}

//! \brief The peer: the settings the drag took with Jacobi steps in place of the direct
//! method, played while the pins move on by `offset` per move, each move's minimizer
//! from `minimizer`.
std::vector<PeerMove> jacobi_peer(EditorSession& s, const Vec3& offset, Minimizer& minimizer,
                                  double tolerance, const DragOptions& o)
{
    SolverSettings jacobi = s.document().solver;
    jacobi.method = Method::Jacobi;
    jacobi.until_converged = false;
    jacobi.steps_per_run = 1000000; // played through the cap, as a run the artist started
    s.dispatch(cmd::SetSolverSettings{jacobi});
    s.settle_solver(); // its precomputation, untimed
    s.dispatch(cmd::Play{});
    const Interaction drag{"jacobi drag"}; // one undo step, as the M tool's gesture
    std::vector<PeerMove> moves;
    for (int e = 0; e < o.jacobi_moves; ++e)
    {
        std::vector<Scalar> targets = hard_targets(s.document());
        for (size_t k = 0; k < targets.size(); ++k)
            targets[k] += offset[k % 3];
        const std::vector<Scalar>& x = minimizer.solve(targets);
        moves.push_back(jacobi_move(s, offset, x, tolerance, o, drag));
    }
    s.end_interaction();
    s.dispatch(cmd::Pause{});
    return moves;
}

//! The median of `reps` runs of f, in ms.
double median_ms(const std::function<void()>& f, int reps = 3)
{
    std::vector<double> ms;
    for (int r = 0; r < reps; ++r)
    {
        const auto t = Clock::now();
        f();
        ms.push_back(ms_since(t));
    }
    return median(ms);
}

//! \brief Where a move's time goes: the calls the editor makes for one (SolverController's
//! restart_if_needed, LiveSolver's move_hard_targets and run_steps, EditorSession::update),
//! each timed apart on the same data, the solver's on the check's run (the same matrix).
void price_move(EditorSession& s, Minimizer& m)
{
    const Document& d = s.document();
    Session& session = m.session();
    std::vector<Scalar> x(session.positions().begin(), session.positions().end()), copy;
    std::vector<ConstraintSet> sets = d.sets; // the run's copy, which same_run compares with
    const auto changing = std::make_shared<const ChangingPart>(
        changing_part(m.mesh(), d.draw_data.vertex_face_offsets, d.draw_data.vertex_faces,
                      session.free_vertices()));
    DisplayGeometry g;
    const auto display = [&](std::uint64_t run) {
        update_display_geometry(x, d.mesh, d.draw_data.vertex_face_offsets,
                                d.draw_data.vertex_faces, run, changing, g);
    };
    const std::vector<std::pair<const char*, std::function<void()>>> parts = {
        {"interface: same_run, twice (the sets compared)",
         [&] {
             (void)same_run(d.sets, d.solver, sets, d.solver, false);
             (void)same_run(d.sets, d.solver, sets, d.solver, true);
         }},
        {"interface: constraint_problems (the enabled sets copied)",
         [&] { (void)constraint_problems(d.sets, d.solver); }},
        {"interface: build_recipe (the whole recipe, which a move read before pin_constraints)",
         [&] { (void)build_recipe(d.sets, d.solver, d.mesh, d.base_positions, 0); }},
        {"interface: the sets and settings copied (the run's ShapeRecipe)", [&] { sets = d.sets; }},
        {"interface: the positions copied (once; move_hard_targets copies 3 times)",
         [&] { copy.assign(x.begin(), x.end()); }},
        {"interface and solver: display geometry, whole mesh (a new display run)",
         [&] { display(new_display_run()); }},
        {"interface: upload of the whole mesh (update_geometry)",
         [&] {
             g.run = new_display_run(); // a frame of a run the renderer has not seen: whole
             s.renderer().update_geometry(g);
             (void)s.renderer().read_pixels(1, 1);
         }},
        {"solver: a direct step (right-hand side, back-substitution)", [&] { session.step(); }},
        {"solver: the residual (the stopping rule after each step)",
         [&] { (void)session.residual(session.positions()); }},
        {"solver: the energy (the plot's point)", [&] { (void)session.energy(); }}};
    std::printf("\n| part of a move, timed apart | median ms (3 runs) |\n|---|---|\n");
    display(new_display_run()); // g holds a whole frame for the upload
    for (const auto& [name, f] : parts)
        std::printf("| %s | %.2f |\n", name, median_ms(f));
}

//! What the M drag gave: its figures, the check's run (made after the first result, so
//! that the peak memory until then is the editor's), and the last move's offset.
struct Drag
{
    DragSeries series;
    std::optional<double> first_ms;
    SolverStatus first;
    std::unique_ptr<Minimizer> minimizer;
    double editor_peak = 0, minimizer_rss = 0;
    Vec3 offset{0, 0, 0};
};

//! The pins' first target (the vertex's base place before any move).
Vec3 first_target(const EditorSession& s, size_t p)
{
    const ConstraintSet& pins = set_named(s, "pins");
    const std::vector<Scalar>& base = s.document().base_positions;
    return pins.targets.empty() ? Vec3{base[p], base[p + 1], base[p + 2]} : pins.targets[0];
}

//! \brief One move of the M drag to `y`, timed and judged; the first makes the check's run.
//! False (said why) when the solver failed.
bool drag_move(EditorSession& s, glm::dvec3 at, double y, size_t p, double tolerance, Drag& drag)
{
    const Document& d = s.document();
    const std::vector<Scalar> before = d.mesh.positions;
    const Vec3 target_before = first_target(s, p);
    const int steps = d.steps_from_base, restarts = s.solver_status().restarts;
    const MoveFrames m = frames_after(s, [&] { s.mouse_move(at.x, y); });
    const SolverStatus status = s.solver_status();
    if (!status.error.empty())
    {
        std::printf("no drag: %s\n", status.error.c_str());
        return false;
    }
    const Vec3 target = first_target(s, p);
    for (size_t a = 0; a < 3; ++a)
        drag.offset[a] = target[a] - target_before[a];
    if (!drag.minimizer) // the first move: the editor's first result
    {
        drag.editor_peak = status_bytes("VmHWM:");
        const double rss = status_bytes("VmRSS:");
        drag.minimizer = std::make_unique<Minimizer>(d);
        drag.minimizer_rss = status_bytes("VmRSS:") - rss;
        drag.first = status;
        drag.first_ms = judge(m, before, drag.minimizer->solve(hard_targets(d)), tolerance).ms;
        return true;
    }
    const Judged j = judge(m, before, drag.minimizer->solve(hard_targets(d)), tolerance);
    DragSeries& series = drag.series;
    if (j.ms)
        series.latency.push_back(*j.ms);
    else
        ++series.missed;
    series.move.push_back(m.move_ms);
    series.update.push_back(m.update_ms);
    series.solver.push_back(status.step_ms);
    series.before.push_back(j.before);
    series.last.push_back(j.last);
    series.solves += d.steps_from_base - steps;
    series.restarts += status.restarts - restarts;
    return true;
}

//! \brief The M drag: a press on the first pin where it is drawn, then moves each lifting it
//! step_px further (the first takes the dome settings), then the release. Nullopt (said
//! why) when the press grabbed nothing or the solver failed.
std::optional<Drag> m_drag(EditorSession& s, int width, int height, double tolerance,
                           const DragOptions& o)
{
    const size_t p = 3 * static_cast<size_t>(set_named(s, "pins").vertices[0]);
    const std::vector<Scalar>& x = s.document().mesh.positions;
    const glm::dvec3 at = s.camera().project({x[p], x[p + 1], x[p + 2]}, width, height);
    s.mouse_press(MouseButton::Left, {}, at.x, at.y);
    if (!s.in_gesture())
    {
        std::printf("no drag: the press did not grab the pins\n");
        return std::nullopt;
    }
    Drag drag;
    double y = at.y;
    for (int e = 0; e <= o.moves; ++e)
        if (!drag_move(s, at, y -= o.step_px, p, tolerance, drag))
            return std::nullopt;
    s.mouse_release(MouseButton::Left, at.x, y);
    s.prepare_ui(); // the run's notes (a factor over the budget would be one)
    for (const std::string& note : s.state().run_notes)
        std::printf("run note: %s\n", note.c_str());
    return drag;
}

} // namespace

void drag_case(EditorSession& s, int width, int height, const DragOptions& o)
{
    if (o.moves < 1)
        return;
    std::printf(
        "\n--- a pin dragged with M in a region (the minimizer within %g of the "
        "diagonal in %.0f ms) ---\n\n",
        o.tolerance, o.budget_ms);
    if (!make_patch_and_pins(s, width, height, o))
    {
        std::printf("no drag: %s\n", s.state().message.c_str());
        return;
    }
    s.dispatch(cmd::SetTool{ToolKind::MovePins});
    if (o.conjugate_gradients)
    {
        // The settings the drag keeps: conjugate gradients with the thin plate (the dome).
        SolverSettings cg = s.document().solver;
        cg.method = Method::ConjugateGradient;
        cg.bending = Bending{};
        s.dispatch(cmd::SetSolverSettings{cg});
        std::printf(
            "method: conjugate gradients, the thin plate (no factor: a frame's "
            "iterations at a time)\n");
    }
    s.settle_solver(); // the sets' run as they stand, as an artist finds it
    const Document& d = s.document();
    const double diagonal = glm::length(d.box.hi - d.box.lo);
    const size_t region = set_named(s, "patch").vertices.size();
    std::printf("region 'patch': %zu vertices (%.0f %%), pins: %zu vertices; diagonal %.4g\n",
                region, 100.0 * double(region) / double(d.mesh.vertex_count()),
                set_named(s, "pins").vertices.size(), diagonal);
    const bool reset = reset_peak_memory(); // the earlier cases' peaks are theirs
    std::optional<Drag> drag = m_drag(s, width, height, o.tolerance * diagonal, o);
    if (!drag)
        return;
    print_drag(drag->series, drag->first_ms, drag->first, diagonal, o);
    if (const SparseCholesky* f = drag->minimizer->session().factorization())
        std::printf(
            "the factor (the check's, the same matrix): %.0f M nonzeros, %.2f GB by CHOLMOD's "
            "count; analysis %.1f s, factorization %.1f s\n",
            f->stats().factor_nonzeros / 1e6, gigabytes(f->stats().factor_bytes()),
            f->stats().analyse_seconds, f->stats().factor_seconds);
    if (!o.conjugate_gradients) // (its parts are the direct method's)
        price_move(s, *drag->minimizer);
    if (o.jacobi_moves > 0)
        print_peer(jacobi_peer(s, drag->offset, *drag->minimizer, o.tolerance * diagonal, o),
                   diagonal, o);
    std::printf(
        "\npeak resident memory%s: %.2f GB through the editor's first result (the "
        "document, the renderer, the editor's factor); %.2f GB at the end, with the "
        "check's own run (%.2f GB resident when made)\n",
        reset ? " since the drag case began" : " of the process", gigabytes(drag->editor_peak),
        gigabytes(status_bytes("VmHWM:")), gigabytes(drag->minimizer_rss));
}

} // namespace meshfair::bench
