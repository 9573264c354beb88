// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// The editor's live solving without GL (a RecordingRenderer answers picking and
// visibility): a session's exported recipe run through meshfair-cli's pipeline on the same
// mesh gives the editor's positions bit for bit, whether the steps ran on the caller's
// thread or on the solver's; undo of solver runs and set edits returns exact states. The
// cases run on a small noisy sphere; one runs the real meshfair-cli on the noisy bunny,
// which also holds the in-process pipeline to the executable.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>

#include <glm/gtc/quaternion.hpp>

#include "app/cli/smooth_file.h"
#include "app/editor/constraint_glyphs.h"
#include "app/editor/editor_session.h"
#include "app/editor/live_solver.h"
#include "app/editor/offscreen.h"
#include "app/editor/persistence.h"
#include "app/editor/script.h"
#include "app/render/palette.h"
#include "app/render/recording_renderer.h"
#include "core/energies/volume_constraint.h"
#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "core/recipe/locality_run.h"
#include "core/recipe/recipe.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "tests/app/editor/phase_gate.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;
namespace fs = std::filesystem;

namespace {

constexpr int kSessionWidth = 400, kSessionHeight = 300;

// The mesh most cases edit: a noisy unit sphere of 2562 vertices. Framed in the 400 x 300
// view it covers a disc of about 80 pixels' radius around (200, 150), where the rectangles
// and strokes below (drawn for the bunny the cases ran on before) land.
Mesh noisy_sphere()
{
    Mesh m = test::icosphere(4);
    test::perturb(m, 0.015, 7);
    return m;
}

Mesh noisy_bunny()
{
    Mesh m = io::read_mesh((test::assets_dir() / "bunny.obj").string());
    test::perturb(m, 0.002, 7);
    return m;
}

// A mesh written to a file, and a session on it, without GL.
struct Editing
{
    fs::path path;
    RecordingRenderer renderer;
    EditorSession session;
    Editing(const fs::path& dir, const Mesh& mesh)
        : path(write(dir, mesh)), session(load_document(path.string()), renderer)
    {
        session.state().offscreen = true;
        session.set_recovery_root({});
        session.set_view_rect(ViewRect::whole(kSessionWidth, kSessionHeight));
        session.camera().frame(session.document().box, session.aspect());
    }
    static fs::path write(const fs::path& dir, const Mesh& mesh)
    {
        const fs::path p = dir / "noisy.obj";
        io::write_mesh(mesh, p.string());
        return p;
    }
    void rectangle(double x0, double y0, double x1, double y1, Modifiers mods = {})
    {
        session.dispatch(cmd::SetTool{ToolKind::Rectangle});
        session.mouse_press(MouseButton::Left, mods, x0, y0);
        session.mouse_move(x1, y1);
        session.mouse_release(MouseButton::Left, x1, y1);
    }
};

// Grabs the first pin of set `set` where it is drawn (its position in `rest`) with the tool
// in hand and drags it up through `heights` pixels, released at the last.
void drag_first_pin_up(EditorSession& s, size_t set, const std::vector<Scalar>& rest,
                       std::initializer_list<double> heights)
{
    const size_t p = 3 * static_cast<size_t>(s.document().sets[set].vertices[0]);
    const glm::dvec3 at =
        s.camera().project({rest[p], rest[p + 1], rest[p + 2]}, kSessionWidth, kSessionHeight);
    s.mouse_press(MouseButton::Left, {}, at.x, at.y);
    for (const double h : heights)
        s.mouse_move(at.x, at.y - h);
    s.mouse_release(MouseButton::Left, at.x, at.y - *(heights.end() - 1));
}

// A run of `recipe` on `base` (the document's numbering), from the base shape, as the
// editor's SolverController starts one: the mesh, the order and the faces shared.
void restart_on(LiveSolver& solver, const Mesh& base, const Document& doc, const Recipe& recipe)
{
    solver.restart(std::make_shared<const Mesh>(base),
                   std::make_shared<const LocalityOrder>(doc.order), recipe, {},
                   std::make_shared<const VertexFaces>(
                       VertexFaces{doc.draw_data.vertex_face_offsets, doc.draw_data.vertex_faces}));
}

// A region "patch" and pins "pins" inside it moved by `offset`, each made of a
// rectangle's selection.
void make_region_and_moved_pins(Editing& b, const Vec3& offset)
{
    EditorSession& s = b.session;
    b.rectangle(120, 80, 300, 220);
    REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Region, "patch"}));
    b.rectangle(150, 100, 180, 130);
    REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Pin, "pins"}));
    s.dispatch(cmd::MovePins{"pins", offset});
}

// A region, pins inside it moved away, anchors, centroids (if asked) and normals on
// faces, each made of a rectangle's selection.
void make_every_kind_of_set(Editing& b, bool centroids)
{
    EditorSession& s = b.session;
    make_region_and_moved_pins(b, {0.0, 0.004, 0.0});
    b.rectangle(200, 150, 260, 200);
    REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "anchors"}));
    s.dispatch(cmd::SetElements{ElementKind::Faces});
    if (centroids)
    {
        b.rectangle(130, 160, 200, 215);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Centroid, "centroids"}));
    }
    b.rectangle(230, 90, 290, 140);
    REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Normal, "normals"}));
}

// Sets with each element's own data (target, weight; normal) in the order of the elements:
// two lists of sets that differ only in how each lists its elements compare equal.
std::vector<ConstraintSet> by_element(std::vector<ConstraintSet> sets)
{
    for (ConstraintSet& s : sets)
    {
        Index most = 0;
        for (const Index i : s.vertices)
            most = std::max(most, i);
        for (const Index f : s.faces)
            most = std::max(most, f);
        const std::vector<Index> identity = test::all_indices(most + 1);
        s = ordered_by(std::move(s), identity, identity);
    }
    return sets;
}

// What `meshfair-cli smooth MESH -o OUT --recipe RECIPE` writes, in process: the recipe
// file parsed and the CLI's own smooth_file (app/cli/smooth_file.h: the mesh read, the
// recipe checked in the file's numbering, one LocalityRun, the result written in the
// file's order), its output read back. The end-to-end case below holds it to the
// executable's bits.
std::vector<Scalar> cli_positions(const fs::path& mesh, const fs::path& recipe)
{
    const fs::path out = recipe.parent_path() / "in-process.obj";
    cli::smooth_file(mesh.string(), out.string(), read_recipe(recipe.string()), recipe.string(), "",
                     false);
    return io::read_mesh(out.string()).positions;
}

// The real meshfair-cli smooth on `mesh` with the recipe: the positions it writes.
std::vector<Scalar> cli_executable_positions(const fs::path& mesh, const fs::path& recipe)
{
    const fs::path out = recipe.parent_path() / "cli.obj";
    const test::CommandRun run = test::run_command(test::shell_quote(MESHFAIR_CLI) + " smooth " +
                                                   test::shell_quote(mesh.string()) + " -o " +
                                                   test::shell_quote(out.string()) + " --recipe " +
                                                   test::shell_quote(recipe.string()) + " --quiet");
    REQUIRE_MESSAGE(run.code == 0, run.err);
    return io::read_mesh(out.string()).positions;
}

// Steps on the caller's thread, then frames on the solver's (the settings' steps per frame
// each): the shape made of both is reproducible from the base.
void step_then_play(EditorSession& s, int steps, int frames)
{
    const int per_frame = s.document().solver.iterations_per_frame;
    s.dispatch(cmd::Step{steps});
    s.dispatch(cmd::Play{frames});
    while (s.playing())
        s.take_frame();
    CHECK(s.document().steps_from_base == steps + frames * per_frame);
    CHECK(s.document().reproducible);
    CHECK(s.document().mesh.positions != s.document().base_positions);
}

// What undo must restore, compared as a whole.
struct State
{
    SelectionMask v, f;
    std::vector<ConstraintSet> sets;
    SolverSettings solver;
    std::vector<Scalar> positions, base;
};
bool same(const State& a, const State& b)
{
    return a.v == b.v && a.f == b.f && a.sets == b.sets && a.solver == b.solver &&
           a.positions == b.positions && a.base == b.base;
}

// Exports the session's recipe into `dir` and runs it through meshfair-cli's pipeline on the
// mesh: true when it gives the editor's positions bit for bit.
bool cli_reproduces(EditorSession& s, const fs::path& mesh, const fs::path& dir)
{
    const fs::path recipe = dir / "recipe.json";
    REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));
    return cli_positions(mesh, recipe) == file_order_mesh(s.document()).positions;
}

// Plays a script file on the mesh file as `meshfair --offscreen MESH --script SCRIPT`
// does (app/editor/offscreen.cpp, render_screenshot, at its default size), with a
// RecordingRenderer for its GL one.
void play_offscreen(const fs::path& mesh, const fs::path& script)
{
    RecordingRenderer renderer;
    EditorSession session(load_document(mesh.string()), renderer);
    session.state().offscreen = true;
    session.set_recovery_root({});
    OffscreenHost host(session, 1280, 800, false);
    host.run_frame();
    session.camera().frame(session.document().box, session.aspect());
    play_script(read_script(script.string()), session, host);
    session.end_session();
}

// A dab of the smoothing brush on the unit sphere, centred toward (x, y, 1).
cmd::PaintDab relax_dab(Scalar x, Scalar y, int steps)
{
    const Scalar n = std::sqrt(x * x + y * y + 1);
    return cmd::PaintDab{
        "brush", PaintMode::Relax, Vec3{x / n, y / n, 1 / n}, 0.25, 0.5, FalloffCurve::Smooth,
        steps};
}

} // namespace

TEST_SUITE("Live solving")
{
    TEST_CASE("opening a mesh modifies nothing: the solver's first precomputation is silent")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        const std::vector<Scalar> loaded = s.document().mesh.positions;
        s.update();        // the first restart, on the solver's thread
        s.wait_for_heat(); // waits until it is done, and takes what it published
        CHECK(s.solver_status().ready);
        CHECK_FALSE(s.document().modified); // Ctrl+Q quits without asking
        CHECK(s.document().mesh.positions == loaded);
        CHECK(s.history().undo_count() == 0);
        s.dispatch(cmd::Step{1});
        CHECK(s.document().modified);
    }

    TEST_CASE(
        "with a region, the plot's energy of what moves leaves out the fixed rest, and the "
        "heat map colours only the free vertices")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.update(); // the plot is shown: its points carry the gradient
        b.rectangle(120, 80, 300, 220);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Region, "patch"}));
        s.dispatch(cmd::SetHeatMap{EnergyTerm::Total});
        s.dispatch(cmd::Step{30});
        s.wait_for_heat();
        const std::vector<EnergySample> e = s.energies();
        REQUIRE(e.size() >= 2);
        const EnergySample &first = e.front(), &last = e.back();
        CHECK(last.step == 30);
        // The fixed rest holds most of the energy; what moves falls by far more of its own.
        const double held = first.held.total();
        CHECK(held > 0.5 * first.energy.total());
        CHECK(last.held.total() == held);
        const double moving_ratio =
            (last.energy.total() - held) / (first.energy.total() - first.held.total());
        const double whole_ratio = last.energy.total() / first.energy.total();
        CHECK(whole_ratio < 1);
        CHECK(moving_ratio < whole_ratio - 0.1); // (0.77 against 0.92 here)
        // The held part is the energy of the sets' recipe over the fixed vertices' elements,
        // by the core's own reckoning (a session in the file's numbering).
        const Document& doc = s.document();
        const Recipe recipe = current_recipe(doc);
        const Topology topology = build_topology(doc.mesh, required_topology(recipe));
        Mesh start = doc.mesh;
        start.positions = doc.base_positions;
        const Session core(start, topology, recipe);
        CHECK(core.held_energy(doc.mesh.positions).total() == doctest::Approx(held).epsilon(1e-9));
        // The gradient, relative to the start, fell.
        REQUIRE(first.gradient > 0);
        REQUIRE(last.gradient >= 0);
        CHECK(last.gradient < 0.5 * first.gradient);
        // The heat map: the fixed vertices grey, the free ones on the ramp.
        const std::vector<float>& rgb = b.renderer.vertex_colors();
        REQUIRE(rgb.size() == 3 * doc.mesh.positions.size() / 3);
        const std::vector<char> is_free = core.free_flags();
        size_t grey_free = 0, coloured_fixed = 0, free_count = 0;
        for (size_t i = 0; i < is_free.size(); ++i)
        {
            const bool grey = rgb[3 * i] == palette::kHeatHidden[0] &&
                              rgb[3 * i + 1] == palette::kHeatHidden[1] &&
                              rgb[3 * i + 2] == palette::kHeatHidden[2];
            free_count += is_free[i] ? 1 : 0;
            grey_free += is_free[i] && grey ? 1 : 0;
            coloured_fixed += !is_free[i] && !grey ? 1 : 0;
        }
        CHECK(free_count > 100);
        CHECK(free_count < is_free.size() / 2);
        CHECK(grey_free == 0);
        CHECK(coloured_fixed == 0);
    }

    TEST_CASE(
        "Solve shows the minimizer, and a moved pin's shape is the minimizer without a "
        "refactorization")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        make_region_and_moved_pins(b, {0.0, 0.05, 0.0});
        SolverSettings settings = s.document().solver;
        settings.bending = Bending{1.0, 0.0};
        REQUIRE(s.dispatch(cmd::SetSolverSettings{settings}));
        REQUIRE(s.dispatch(cmd::Solve{}));
        CHECK(s.history().undo_label() == "solve");
        CHECK(s.document().solver.method == Method::Direct);
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        CHECK(s.document().steps_from_base >= 1);
        CHECK(s.document().reproducible);
        // The shape is the command line's: the exported recipe ("method": "direct", the
        // bending section, as many steps) gives it bit for bit.
        CHECK(cli_reproduces(s, b.path, dir));
        const std::vector<Scalar> solved = s.document().mesh.positions;
        const int restarts = s.solver_status().restarts;
        const Scalar diagonal = meshfair::bounding_box(solved).diagonal();
        const auto distance = [](const std::vector<Scalar>& a, const std::vector<Scalar>& c) {
            Scalar worst = 0;
            for (size_t k = 0; k < a.size(); ++k)
                worst = std::max(worst, std::abs(a[k] - c[k]));
            return worst;
        };

        // A pin moved: solved again on the solver's thread with the factorization kept (no
        // restart), and the shape is the minimizer for the new targets, as the command line
        // solves it from the base.
        REQUIRE(s.dispatch(cmd::MovePins{"pins", {0.0, 0.03, 0.02}}));
        s.settle_solver();
        CHECK(s.solver_status().restarts == restarts);
        const std::vector<Scalar> moved = s.document().mesh.positions;
        CHECK(distance(moved, solved) >= 0.03); // the pins moved by (0, 0.03, 0.02)
        const fs::path recipe = dir / "moved.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));
        CHECK(distance(cli_positions(b.path, recipe), file_order_mesh(s.document()).positions) <=
              1e-9 * diagonal);

        // A weight changed (the thin plate's slider): the run restarts on the analysis kept,
        // factoring only, and the shape is still the command line's.
        CHECK_FALSE(s.solver_status().analysis_kept);
        SolverSettings stiffer = s.document().solver;
        stiffer.bending->mu = 4.0;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{stiffer})); // (direct: solved at once)
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        CHECK(s.solver_status().restarts == restarts + 1);
        CHECK(s.solver_status().analysis_kept);
        CHECK(s.solver_status().analyse_ms == 0);
        CHECK(s.solver_status().factor_ms > 0);
        const fs::path stiffer_recipe = dir / "stiffer.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{stiffer_recipe.string()}));
        // (The command line solves from the base, the editor from the moved pins' shape: the
        // same minimizer, rounded apart.)
        CHECK(distance(cli_positions(b.path, stiffer_recipe),
                       file_order_mesh(s.document()).positions) <= 1e-9 * diagonal);
        // Two values at once, as a slider dragged fast gives them: the restart of the first
        // may be replaced before it is shown, and the second still keeps the analysis.
        stiffer.bending->mu = 5.0;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{stiffer}));
        stiffer.bending->mu = 6.0;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{stiffer}));
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        CHECK(s.solver_status().analysis_kept);
        REQUIRE(s.dispatch(cmd::Undo{}));
        REQUIRE(s.dispatch(cmd::Undo{}));
        REQUIRE(s.dispatch(cmd::Undo{})); // the weight
        s.settle_solver();

        // Undo of the move: the pins go back and the minimizer with them.
        REQUIRE(s.dispatch(cmd::Undo{}));
        s.settle_solver();
        CHECK(distance(s.document().mesh.positions, solved) <= 1e-9 * diagonal);
        // Solve again changes nothing: the shape already is the minimizer.
        CHECK_FALSE(s.dispatch(cmd::Solve{}));
        // Undo of Solve: back to Jacobi steps.
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().solver.method == Method::Jacobi);
    }

    TEST_CASE("Solve with 'keep volume': the minimizer under the volume, the command line's shape")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        // A region of most of the sphere, weakly anchored everywhere: the membrane would
        // shrink it; the volume holds it.
        b.rectangle(60, 40, 380, 280);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Region, "patch"}));
        REQUIRE(s.dispatch(cmd::RunSelection{SelectionCommand::All}));
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "anchors"}));
        SolverSettings settings = s.document().solver;
        settings.anchor_mu = 0.05;
        settings.keep_volume = true;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{settings}));
        REQUIRE(s.problems().empty());
        const Mesh base = file_order_mesh(s.document());
        REQUIRE(s.dispatch(cmd::Solve{}));
        CHECK(s.document().solver.method == Method::Direct);
        CHECK(s.document().solver.keep_volume);
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        CHECK(s.document().steps_from_base >= 1);
        // The exported recipe ("direct" with the volume) gives the shape bit for bit.
        CHECK(cli_reproduces(s, b.path, dir));
        const Recipe r = read_recipe((dir / "recipe.json").string());
        CHECK(r.method == Method::Direct);
        REQUIRE(r.volume.has_value());
        // The sphere's volume is the base's; without the volume the shape shrinks.
        const Topology t = build_topology(base);
        const std::vector<char> none(static_cast<size_t>(base.vertex_count()), 0);
        const VolumeConstraint volume(base, t, base.positions, none);
        REQUIRE(volume.component_count() == 1);
        const std::vector<Scalar> solved = file_order_mesh(s.document()).positions;
        CHECK(volume.volume(0, solved) ==
              doctest::Approx(volume.target_volumes()[0]).epsilon(1e-12));
        settings = s.document().solver;
        settings.keep_volume = false;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{settings}));
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        // The volume changes the topology the run needs, not the system's pattern: the
        // factorization's analysis is kept.
        CHECK(s.solver_status().analysis_kept);
        CHECK(volume.volume(0, file_order_mesh(s.document()).positions) <
              (1 - 1e-4) * volume.target_volumes()[0]);
    }

    TEST_CASE("implicit steps in the editor: each step a backward-Euler step of the time set")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        SolverSettings settings = s.document().solver;
        settings.method = Method::Implicit;
        settings.time = 0.5;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{settings}));
        REQUIRE(s.dispatch(cmd::Step{3}));
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        CHECK(s.document().steps_from_base == 3);
        CHECK(s.document().mesh.positions != s.document().base_positions);
        // The exported recipe ("method": "implicit", "time": 0.5) gives the same bits.
        CHECK(cli_reproduces(s, b.path, dir));
        const fs::path recipe = dir / "implicit.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));
        const Recipe exported = read_recipe(recipe.string());
        CHECK(exported.method == Method::Implicit);
        CHECK(exported.time == 0.5);
    }

    TEST_CASE("the exported recipe reproduces the editor's shape through meshfair-cli")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        make_every_kind_of_set(b, true);
        CHECK(s.problems().empty());
        SolverSettings settings = s.document().solver;
        settings.lambda = 0.4;
        settings.anchor_mu = 2;
        settings.centroid_mu = 0.5;
        settings.iterations_per_frame = 4;
        s.dispatch(cmd::SetSolverSettings{settings});
        step_then_play(s, 6, 5);

        const fs::path recipe = dir / "recipe.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));
        const Recipe r = read_recipe(recipe.string());
        CHECK(r.iterations == 26);
        REQUIRE(r.hard);
        CHECK_FALSE(r.hard->targets.empty());
        CHECK(cli_positions(b.path, recipe) == file_order_mesh(s.document()).positions);

        // Undo of the run, then of the steps: back to the loaded positions exactly.
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().steps_from_base == 6);
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().mesh.positions == s.document().base_positions);
        // Stepping again from there gives the same bits as the first time.
        s.dispatch(cmd::Step{6});
        CHECK(cli_reproduces(s, b.path, dir));
    }

    TEST_CASE("a run until it converges stops where meshfair-cli's tolerance stops")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(120, 80, 300, 220);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "anchors"}));
        SolverSettings settings = s.document().solver;
        settings.tolerance = 1e-3;
        settings.until_converged = true;
        settings.iterations_per_frame = 3;
        s.dispatch(cmd::SetSolverSettings{settings});
        s.dispatch(cmd::Play{});
        while (s.playing())
            s.take_frame();
        CHECK(s.solver_status().converged);
        const int steps = s.document().steps_from_base;
        CHECK(steps > 1);
        // The library's run of the exported recipe, allowed many more steps, stops at the
        // same step with the same positions.
        const fs::path recipe = dir / "recipe.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));
        Recipe r = read_recipe(recipe.string());
        r.iterations = 100 * steps;
        Mesh m = io::read_mesh(b.path.string());
        const SmoothResult result = smooth(m, build_topology(m, required_topology(r)), r);
        CHECK(result.stopped_by_tolerance);
        CHECK(result.iterations == steps);
        CHECK(result.gradients.back() <= 1e-3); // the gradient's rule, not the energy's
        // And meshfair-cli (the editor's vertex order, hence its bits) gives its positions.
        const fs::path longer = dir / "longer.json";
        io::write_file_atomically(longer.string(), recipe_to_json(r).dump());
        CHECK(cli_positions(b.path, longer) == file_order_mesh(s.document()).positions);
    }

    TEST_CASE("until converged where nothing holds the mesh: the run plays its steps, and says why")
    {
        // Plain smoothing of a whole sphere has no minimizer but a point: a run "until the
        // energy settles" would melt it. The run plays the steps per run instead.
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        SolverSettings settings = s.document().solver;
        settings.until_converged = true;
        settings.steps_per_run = 7;
        settings.iterations_per_frame = 2;
        s.dispatch(cmd::SetSolverSettings{settings});
        s.dispatch(cmd::Play{});
        while (s.playing())
            s.take_frame();
        CHECK(s.document().steps_from_base == 7);
        CHECK_FALSE(s.solver_status().converged);
        CHECK(s.solver_status().no_minimizer.find("is held by nothing") != std::string::npos);
        // Anchors hold it: a minimizer, and "until converged" is offered again.
        b.rectangle(120, 80, 300, 220);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "anchors"}));
        s.settle_solver();
        CHECK(s.solver_status().no_minimizer.empty());
    }

    TEST_CASE("positions taken from a playing solver come with the step count they are at")
    {
        // An interface slower than the solver: after each take the worker finishes the next
        // frame before the interface asks again, so status() counts a frame ahead of the
        // positions taken. take's own count must be theirs (the editor's recipe, and so
        // meshfair-cli, reproduce the shape from it).
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.02, 3);
        const Document doc = make_document(m, "sphere.obj");
        Recipe r;
        r.soft = SoftVertices{{true, {}}, 0.2, {}};
        LiveSolver solver;
        restart_on(solver, m, doc, r);
        solver.wait_idle();
        solver.set_iterations_per_frame(2);
        solver.set_playing(true, 6);
        std::vector<Scalar> x;
        DisplayGeometry g;
        int taken = 0;
        for (int frames = 0; frames < 6;)
        {
            if (!solver.wait_published())
                break;
            int steps = -1;
            REQUIRE(solver.take(x, g, steps));
            ++frames;
            // The next frame runs before the interface asks again: poll until the worker has
            // counted its steps (none after the sixth frame, the run's last). The deadline
            // only catches a worker that never runs; it measures nothing.
            const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
            for (SolverStatus now = solver.status();
                 frames < 6 && now.playing && now.steps <= steps; now = solver.status())
            {
                REQUIRE_MESSAGE(std::chrono::steady_clock::now() < deadline,
                                "the worker ran no frame in 120 s after the take");
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            if (frames < 6)
                CHECK(solver.status().steps == steps + 2); // a frame ahead of the positions
            // The same shape from the library: `steps` steps of the recipe.
            Mesh reference = m;
            Recipe n = r;
            n.iterations = steps;
            smooth(reference, build_topology(reference, required_topology(n)), n);
            CHECK(x == reference.positions);
            CHECK(steps == 2 * frames);
            taken = steps;
        }
        CHECK(taken == 12);
        CHECK(solver.status().steps == 12);
    }

    TEST_CASE("every frame's display geometry is that of its positions, recomputed in part")
    {
        // The solver's frames recompute only what a run's steps can move (its free vertices
        // and the faces around them); each must still equal the whole computation from the
        // positions taken, for every kind of recipe, and after the pins move.
        Mesh m = test::icosphere(4); // above the parallel threshold
        test::perturb(m, 0.02, 5);
        // In the locality numbering, as load_document keeps a file's mesh: the first half
        // of the vertices is a patch, its frames' changing part a range.
        const Document doc = make_document(reorder_mesh(m, locality_order(m)), "sphere.obj");
        const Mesh& base = doc.mesh; // in the document's numbering, as the editor runs
        const Index nv = base.vertex_count();
        Region half;
        for (Index v = 0; v < nv / 2; ++v)
            half.vertices.push_back(v);
        std::vector<std::pair<const char*, Recipe>> recipes;
        recipes.push_back({"plain", Recipe{}});
        Recipe region;
        region.region = half;
        recipes.push_back({"region", region});
        Recipe volume = region;
        volume.volume = KeepVolume{};
        recipes.push_back({"region, volume kept", volume});
        Recipe taubin = region;
        taubin.method = Method::Taubin;
        recipes.push_back({"region, Taubin", taubin});
        Recipe falloff = region;
        falloff.falloff = Falloff{};
        recipes.push_back({"region, falloff", falloff});
        // Pins: one beside free vertices, and one amid pins (no free neighbour: outside
        // the changing part when it moves).
        const Topology t = build_topology(base);
        Recipe pinned;
        pinned.region = half;
        pinned.hard = HardVertices{{nv / 3}, {}};
        for (const Index v : {nv - 1}) // far from the region, in the locality numbering
        {
            pinned.hard->vertices.push_back(v);
            for (const Index j : t.neighbors(v))
                pinned.hard->vertices.push_back(j);
        }
        pinned.soft = SoftVertices{{false, {5, 9}}, 0.3, {}};
        pinned.centroid = CentroidConstraints{{false, {0, 7}}, 1.0, {}, CentroidDenominator::Paper};
        pinned.normal = NormalConstraints{{false, {3, 11}}, 1.0, NormalSource::Initial, {}};
        recipes.push_back({"pins and constraints", pinned});
        for (const auto& named : recipes)
        {
            const char* name = named.first; // (clang 14 cannot capture a structured binding)
            const Recipe& recipe = named.second;
            CAPTURE(name);
            LiveSolver solver;
            restart_on(solver, base, doc, recipe);
            solver.wait_idle();
            std::vector<Scalar> x;
            DisplayGeometry g;
            const auto check_frame = [&] {
                int steps = -1;
                REQUIRE(solver.take(x, g, steps));
                DisplayGeometry whole;
                update_display_geometry(x, base, doc.draw_data.vertex_face_offsets,
                                        doc.draw_data.vertex_faces, 0, nullptr, whole);
                CHECK(g.positions == whole.positions);
                CHECK(g.normals == whole.normals);
                CHECK(g.face_areas == whole.face_areas);
                // A region's frames take the partial path: their part is not everything.
                if (recipe.region)
                    CHECK((g.changing != nullptr && g.changing->vertices.count() < nv));
            };
            solver.set_playing(true, 4);
            for (int frames = 0; frames < 4 && solver.wait_published(); ++frames)
                check_frame();
            solver.wait_idle();
            if (recipe.hard)
            {
                std::vector<Scalar> targets;
                for (const Index v : recipe.hard->vertices)
                    for (int a = 0; a < 3; ++a)
                        targets.push_back(base.positions[3 * v + a] + 0.05);
                solver.move_hard_targets(targets); // outside the free vertices
                check_frame();
                solver.step_now(2);
                check_frame();
            }
        }
    }

    TEST_CASE("pins dragged in the view plane move their targets without a precomputation")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(150, 100, 175, 125);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Pin, "pins"}));
        s.dispatch(cmd::Step{5});
        const int restarts = s.solver_status().restarts;
        const Vec3 before = [&] {
            const size_t i = 3 * static_cast<size_t>(s.document().sets[0].vertices[0]);
            return Vec3{s.document().mesh.positions[i], s.document().mesh.positions[i + 1],
                        s.document().mesh.positions[i + 2]};
        }();
        // Grab the first pin where it is drawn and drag it 30 pixels to the right.
        const glm::dvec3 at =
            s.camera().project({before[0], before[1], before[2]}, kSessionWidth, kSessionHeight);
        s.dispatch(cmd::SetTool{ToolKind::MovePins});
        s.mouse_press(MouseButton::Left, {}, at.x, at.y);
        s.mouse_move(at.x + 10, at.y);
        s.mouse_move(at.x + 30, at.y);
        s.mouse_release(MouseButton::Left, at.x + 30, at.y);
        s.update();
        const ConstraintSet& pins = s.document().sets[0];
        REQUIRE(pins.targets.size() == pins.vertices.size());
        // The grabbed point moved with the cursor, in the view plane (same depth).
        const glm::dvec3 moved =
            s.camera().project({pins.targets[0][0], pins.targets[0][1], pins.targets[0][2]},
                               kSessionWidth, kSessionHeight);
        CHECK(moved.x == doctest::Approx(at.x + 30).epsilon(1e-6));
        CHECK(moved.y == doctest::Approx(at.y).epsilon(1e-6));
        CHECK(moved.z == doctest::Approx(at.z).epsilon(1e-9));
        // The pins sit on their targets, with no new precomputation; one undo step.
        s.dispatch(cmd::Step{1});
        for (size_t k = 0; k < pins.vertices.size(); ++k)
            for (size_t a = 0; a < 3; ++a)
                CHECK(s.document().mesh.positions[3 * static_cast<size_t>(pins.vertices[k]) + a] ==
                      pins.targets[k][a]);
        CHECK(s.solver_status().restarts == restarts);
        CHECK_FALSE(s.document().reproducible); // the targets moved during the run
        CHECK(s.history().undo_label() == "step 1");
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.history().undo_label() == "move pins");
        // From the base with the moved targets the command line agrees.
        s.dispatch(cmd::Redo{});
        s.dispatch(cmd::ResetShape{});
        s.dispatch(cmd::Step{4});
        CHECK(s.document().reproducible);
        CHECK(cli_reproduces(s, b.path, dir));
    }

    TEST_CASE("a pin dragged with M in a region raises the thin plate's dome, undone in one step")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(120, 80, 300, 220);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Region, "patch"}));
        b.rectangle(200, 140, 215, 155);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Pin, "pins"}));
        REQUIRE(s.document().solver.method == Method::Jacobi);
        REQUIRE_FALSE(s.document().solver.bending);
        s.dispatch(cmd::SetTool{ToolKind::MovePins});
        s.settle_solver();
        const std::vector<Scalar> rest = s.document().mesh.positions;
        const size_t undo_before = s.history().undo_count();

        // Grab the first pin where it is drawn and drag it 40 pixels up.
        drag_first_pin_up(s, 1, rest, {20, 40});
        const ConstraintSet& pins = s.document().sets[1];
        const size_t p = 3 * static_cast<size_t>(pins.vertices[0]);
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());

        // The drag took the direct method with the thin plate, and said so, in its one
        // undo step.
        CHECK(s.document().solver.method == Method::Direct);
        REQUIRE(s.document().solver.bending);
        CHECK(s.document().solver.bending->mu == 1);
        CHECK(s.state().message.find("dome: thin plate, direct method") != std::string::npos);
        CHECK(s.history().undo_count() == undo_before + 1);
        CHECK(s.history().undo_label() == "move pins");
        // The shape is the minimizer of the sets, as the command line solves it.
        CHECK(cli_reproduces(s, b.path, dir));

        // What the drag raised: the minimizer with the moved pins less the one with the
        // pins where they were, for the thin plate and for the membrane (a horn, whose
        // lift dies off faster around the pins: less of the region rises).
        const Vec3 target = pins.targets[0];
        const Vec3 offset{target[0] - rest[p], target[1] - rest[p + 1], target[2] - rest[p + 2]};
        const auto lift = [&](bool plate) {
            SolverSettings settings = s.document().solver;
            settings.bending = plate ? std::optional<Bending>(Bending{}) : std::nullopt;
            s.dispatch(cmd::SetSolverSettings{settings});
            s.settle_solver();
            const std::vector<Scalar> raised = s.document().mesh.positions;
            REQUIRE(s.dispatch(cmd::MovePins{"pins", {-offset[0], -offset[1], -offset[2]}}));
            s.settle_solver();
            const std::vector<Scalar>& lowered = s.document().mesh.positions;
            Scalar sum = 0;
            for (size_t k = 0; k < raised.size(); k += 3)
                sum += std::hypot(raised[k] - lowered[k], raised[k + 1] - lowered[k + 1],
                                  raised[k + 2] - lowered[k + 2]);
            REQUIRE(s.dispatch(cmd::Undo{})); // the pins up again
            return sum;
        };
        const Scalar dome = lift(true), horn = lift(false);
        CHECK(dome > 1.3 * horn); // (1.45 here, with the region's 54 hidden vertices taken in)
        REQUIRE(s.dispatch(cmd::Undo{})); // the membrane
        CHECK(s.history().undo_label() == "move pins");

        // One undo gives back the pins and the settings.
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().solver.method == Method::Jacobi);
        CHECK_FALSE(s.document().solver.bending);
        CHECK(s.document().sets[1].targets.empty());
    }

    TEST_CASE("a pin drag without a factor: conjugate gradients frame by frame to the minimizer")
    {
        // The method "cg" (a system too large to factor): each frame after a move of the
        // pins runs a bounded number of conjugate-gradient iterations from the shape shown,
        // so the drag never waits for a whole solve, and the frames end on the minimizer
        // the direct method gives.
        const fs::path dir = test::temp_dir();
        Mesh sphere = test::icosphere(5); // 10,242 vertices: a region of thousands
        test::perturb(sphere, 0.008, 7);
        Editing b(dir, sphere);
        EditorSession& s = b.session;
        b.rectangle(120, 80, 300, 220);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Region, "patch"}));
        b.rectangle(200, 140, 215, 155);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Pin, "pins"}));
        SolverSettings cg = s.document().solver;
        cg.method = Method::ConjugateGradient;
        cg.bending = Bending{}; // the dome (the M tool keeps these settings)
        REQUIRE(s.dispatch(cmd::SetSolverSettings{cg}));
        s.dispatch(cmd::SetTool{ToolKind::MovePins});
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        const std::vector<Scalar> rest = s.document().mesh.positions;
        const int steps_before = s.solver_status().steps;

        drag_first_pin_up(s, 1, rest, {40});
        s.settle_solver();
        REQUIRE(s.solver_status().error.empty());
        CHECK(s.document().solver.method == Method::ConjugateGradient);
        // One move, several frames: the thin plate needs more iterations than a frame runs.
        const int frames = s.solver_status().steps - steps_before;
        CAPTURE(frames);
        CHECK(frames >= 3);
        CHECK(s.solver_status().converged);
        const std::vector<Scalar> by_frames = s.document().mesh.positions;

        // The direct method's minimizer of the same sets.
        SolverSettings direct = s.document().solver;
        direct.method = Method::Direct;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{direct}));
        s.settle_solver();
        const std::vector<Scalar>& minimizer = s.document().mesh.positions;
        Scalar apart = 0, lifted = 0;
        for (size_t k = 0; k < minimizer.size(); ++k)
        {
            apart = std::max(apart, std::abs(by_frames[k] - minimizer[k]));
            lifted = std::max(lifted, std::abs(minimizer[k] - rest[k]));
        }
        const Scalar diagonal = meshfair::bounding_box(std::span<const Scalar>(rest)).diagonal();
        CHECK(apart <= 1e-9 * diagonal);
        CHECK(lifted > 1e-2 * diagonal); // the drag raised something
    }

    TEST_CASE("restarts share the document's base: a copy per base, none per restart")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(120, 80, 300, 220);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Region, "patch"}));
        s.settle_solver();
        const int restarts = s.solver_status().restarts;
        // A slider dragged through values: a restart each, on the same base.
        for (const double lambda : {0.4, 0.3, 0.2})
        {
            SolverSettings settings = s.document().solver;
            settings.lambda = lambda;
            REQUIRE(s.dispatch(cmd::SetSolverSettings{settings}));
            s.settle_solver();
            CHECK(s.solver().run_shares_base());
        }
        CHECK(s.solver_status().restarts >= restarts + 3);
        CHECK(s.solver().base_copies() == 1);
        // A new base (Apply): one copy more, and the run is on it.
        s.dispatch(cmd::Step{3});
        REQUIRE(s.dispatch(cmd::ApplyShape{}));
        s.settle_solver();
        CHECK(s.solver().base_copies() == 2);
        CHECK(s.solver().run_shares_base());
        // Undone: the base before, made again, and the run's shape is the command line's.
        REQUIRE(s.dispatch(cmd::Undo{}));
        s.settle_solver();
        CHECK(s.solver().base_copies() == 3);
        CHECK(s.solver().run_shares_base());
        s.dispatch(cmd::ResetShape{});
        s.dispatch(cmd::Step{2});
        CHECK(s.document().reproducible);
        CHECK(cli_reproduces(s, b.path, dir));
    }

    TEST_CASE("what does not change the recipe restarts nothing, undoing a pin move puts pins back")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(150, 100, 175, 125);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Pin, "pins"}));
        s.dispatch(cmd::Step{1});
        const int restarts = s.solver_status().restarts;
        SolverSettings pace = s.document().solver;
        pace.iterations_per_frame = 7; // not part of the recipe
        s.dispatch(cmd::SetSolverSettings{pace});
        s.dispatch(cmd::RenameSet{"pins", "feet"});
        s.dispatch(cmd::SetColor{"feet", {0, 1, 0}});
        s.dispatch(cmd::ShowSet{"feet", false});
        s.dispatch(cmd::Step{1});
        CHECK(s.solver_status().restarts == restarts);
        // Moved pins: right-hand sides only; undone: the pins go back to their base places.
        s.dispatch(cmd::MovePins{"feet", {0.0, 0.01, 0.0}});
        s.dispatch(cmd::Step{1});
        CHECK(s.solver_status().restarts == restarts);
        REQUIRE(s.dispatch(cmd::Undo{})); // the step
        REQUIRE(s.dispatch(cmd::Undo{})); // the move
        CHECK(s.document().sets[0].targets.empty());
        s.dispatch(cmd::Step{1});
        const ConstraintSet& pins = s.document().sets[0];
        for (const Index v : pins.vertices)
            for (size_t a = 0; a < 3; ++a)
                CHECK(s.document().mesh.positions[3 * static_cast<size_t>(v) + a] ==
                      s.document().base_positions[3 * static_cast<size_t>(v) + a]);
    }

    TEST_CASE("a normal set's arrows dragged turn its direction like a trackball")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.dispatch(cmd::SetElements{ElementKind::Faces});
        b.rectangle(180, 120, 230, 170);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Normal, "up"}));
        s.dispatch(cmd::SetNormalDirection{"up", {0, 0, 2}}); // normalized
        REQUIRE(s.document().sets[0].normals.front() == Vec3{0, 0, 1});
        const Vec3 c = face_centroid(s.document().mesh, s.document().mesh.positions,
                                     s.document().sets[0].faces[0]);
        const glm::dvec3 at = s.camera().project({c[0], c[1], c[2]}, kSessionWidth, kSessionHeight);
        s.dispatch(cmd::SetTool{ToolKind::AimNormals});
        s.mouse_press(MouseButton::Left, {}, at.x, at.y);
        for (int k = 1; k <= 4; ++k)
            s.mouse_move(at.x + 25 * k, at.y); // 100 pixels to the right: one radian
        s.mouse_release(MouseButton::Left, at.x + 100, at.y);
        const Vec3 d = s.document().sets[0].normals.front();
        const glm::dvec3 up = s.camera().rotation * glm::dvec3(0, 1, 0);
        const glm::dvec3 turned(d[0], d[1], d[2]);
        CHECK(glm::length(turned) == doctest::Approx(1).epsilon(1e-12));
        CHECK(glm::dot(turned, up) == doctest::Approx(glm::dot(glm::dvec3(0, 0, 1), up)));
        CHECK(std::acos(std::clamp(turned.z, -1.0, 1.0)) == doctest::Approx(1.0).epsilon(1e-9));
        for (const Vec3& n : s.document().sets[0].normals)
            CHECK(n == d); // the one direction for every face of the set
        // The drag is one undo step.
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().sets[0].normals.front() == Vec3{0, 0, 1});
    }

    TEST_CASE(
        "the D tool grabs a normal set's arrow anywhere along it, and turns from the set's mean "
        "normal")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.dispatch(cmd::SetElements{ElementKind::Faces});
        b.rectangle(180, 120, 230, 170);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Normal, "faces"}));
        const ConstraintSet& set = s.document().sets[0];
        REQUIRE(set.normals.empty()); // each face's own normal, noisy
        const Vec3 mean = set_mean_normal(s.document().mesh, s.document().mesh.positions, set);
        const std::vector<NormalArrow> arrows = normal_arrows(s.document(), set);
        REQUIRE(arrows.size() > 1);
        // Pressed near an arrow's tip, far from its base, beyond the grab radius of any base.
        const auto screen = [&](const Vec3& p) {
            return s.camera().project({p[0], p[1], p[2]}, kSessionWidth, kSessionHeight);
        };
        const NormalArrow* far_arrow = nullptr;
        glm::dvec3 tip{0.0};
        for (const NormalArrow& a : arrows)
        {
            const glm::dvec3 t = screen(a.tip);
            bool clear = true;
            for (const NormalArrow& other : arrows)
                clear =
                    clear && glm::length(glm::dvec2(screen(other.base) - t)) > 2 * kGrabRadiusPx;
            if (clear)
            {
                far_arrow = &a;
                tip = t;
                break;
            }
        }
        REQUIRE(far_arrow != nullptr);
        s.dispatch(cmd::SetTool{ToolKind::AimNormals});
        s.mouse_press(MouseButton::Left, {}, tip.x, tip.y);
        s.mouse_move(tip.x + 50, tip.y); // half a radian
        s.mouse_release(MouseButton::Left, tip.x + 50, tip.y);
        REQUIRE(s.history().undo_label() == "normal direction");
        const Vec3 d = s.document().sets[0].normals.front();
        // The mean normal turned half a radian about the view's vertical axis.
        const glm::dvec3 up = s.camera().rotation * glm::dvec3(0, 1, 0);
        const glm::dvec3 expected =
            glm::angleAxis(0.5, glm::normalize(up)) * glm::dvec3(mean[0], mean[1], mean[2]);
        CHECK(glm::length(glm::dvec3(d[0], d[1], d[2]) - expected) < 1e-9);
        // A press on empty space beside the arrows grabs nothing: the same drag there turns
        // no normal (the view orbits instead).
        REQUIRE(s.dispatch(cmd::Undo{}));
        REQUIRE(s.document().sets[0].normals.empty());
        s.mouse_press(MouseButton::Left, {}, 5, 5);
        s.mouse_move(55, 5);
        s.mouse_release(MouseButton::Left, 55, 5);
        CHECK(s.document().sets[0].normals.empty());
    }

    TEST_CASE("a recipe changed during a run is reported as not reproducing the shape")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.dispatch(cmd::Step{3});
        SolverSettings settings = s.document().solver;
        settings.lambda = 0.3;
        s.dispatch(cmd::SetSolverSettings{settings});
        s.dispatch(cmd::Step{3});
        CHECK(s.document().steps_from_base == 6);
        CHECK_FALSE(s.document().reproducible);
        // Reset and run again: reproducible, and the command line agrees.
        s.dispatch(cmd::ResetShape{});
        s.dispatch(cmd::Step{6});
        CHECK(s.document().reproducible);
        CHECK(cli_reproduces(s, b.path, dir));
        // Apply makes the shape the new base: 0 steps from it.
        s.dispatch(cmd::ApplyShape{});
        CHECK(s.document().steps_from_base == 0);
        CHECK(s.document().base_positions == s.document().mesh.positions);
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().base_positions != s.document().mesh.positions);
    }

    TEST_CASE("overlaps are resolved by precedence with a note, what cannot run is refused")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(150, 100, 200, 150);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Pin, "feet"}));
        b.rectangle(180, 120, 230, 170);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "back"}));
        // A pin and an anchor sharing vertices: the pins win, said as a note, and it solves.
        CHECK(s.problems().empty());
        const std::vector<std::string> notes = constraint_notes(s.document().sets);
        REQUIRE(notes.size() == 1);
        CHECK(notes[0].find("of 'back' are also in 'feet': pinned, not anchored") !=
              std::string::npos);
        const Recipe r = current_recipe(s.document());
        REQUIRE(r.hard.has_value());
        REQUIRE(r.soft.has_value());
        for (const Index v : r.soft->vertices.indices)
            CHECK(std::find(r.hard->vertices.begin(), r.hard->vertices.end(), v) ==
                  r.hard->vertices.end());
        CHECK(r.soft->vertices.indices.size() < s.document().sets[1].vertices.size());
        const std::vector<Scalar> before = s.document().mesh.positions;
        REQUIRE(s.dispatch(cmd::Step{3}));
        CHECK(s.document().mesh.positions != before);
        // Joint mode without a normal set cannot run: refused, nothing steps or is exported.
        SolverSettings joint = s.document().solver;
        joint.joint = true;
        s.dispatch(cmd::SetSolverSettings{joint});
        REQUIRE(s.problems().size() == 1);
        CHECK(s.problems()[0] == "joint mode needs a normal set");
        const std::vector<Scalar> stepped = s.document().mesh.positions;
        CHECK_FALSE(s.dispatch(cmd::Step{3}));
        CHECK(s.document().mesh.positions == stepped);
        CHECK(s.state().message.find("cannot solve") == 0);
        CHECK_FALSE(s.dispatch(cmd::ExportRecipe{(dir / "r.json").string()}));
        CHECK_FALSE(fs::exists(dir / "r.json"));
        // An empty selection makes no set.
        s.dispatch(cmd::RunSelection{SelectionCommand::Clear});
        CHECK_FALSE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, {}}));
        CHECK(s.document().sets.size() == 2);
    }

    TEST_CASE("sets you can edit: add and remove the selection, a weight each, out of the solve")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(150, 100, 200, 150);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "soft"}));
        b.rectangle(220, 150, 260, 190);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "stiff"}));
        const size_t stiff = s.document().sets[1].vertices.size();
        // One weight per set: the recipe carries a weight per vertex.
        REQUIRE(s.dispatch(cmd::SetSetWeight{"stiff", 50}));
        Recipe r = current_recipe(s.document());
        REQUIRE(r.soft.has_value());
        REQUIRE(r.soft->weights.size() == r.soft->vertices.indices.size());
        CHECK(std::count(r.soft->weights.begin(), r.soft->weights.end(), 50.0) ==
              static_cast<std::ptrdiff_t>(stiff));
        // Equal weights again: one mu, no weights (the recipe of a single weight, bit for bit).
        REQUIRE(s.dispatch(cmd::SetSetWeight{"soft", 50}));
        r = current_recipe(s.document());
        CHECK(r.soft->weights.empty());
        CHECK(r.soft->mu == 50);
        // Add a selection to a set, then take part of it out again.
        b.rectangle(262, 150, 280, 190);
        REQUIRE(s.dispatch(cmd::AddToSet{"stiff"}));
        const size_t grown = s.document().sets[1].vertices.size();
        CHECK(grown > stiff);
        CHECK_FALSE(s.dispatch(cmd::AddToSet{"stiff"})); // nothing new
        REQUIRE(s.dispatch(cmd::RemoveFromSet{"stiff"}));
        CHECK(s.document().sets[1].vertices.size() == stiff);
        // Out of the solve: the recipe forgets it, the glyphs stay; undo brings it back.
        REQUIRE(s.dispatch(cmd::EnableSet{"soft", false}));
        r = current_recipe(s.document());
        CHECK(r.soft->vertices.indices.size() == stiff);
        CHECK(s.document().sets[0].visible);
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().sets[0].enabled);
        // An exported recipe with two weights comes back as two sets with their weights.
        REQUIRE(s.dispatch(cmd::SetSetWeight{"soft", 2}));
        REQUIRE(s.dispatch(cmd::ExportRecipe{(dir / "two.json").string()}));
        s.dispatch(cmd::DeleteSet{"soft"});
        s.dispatch(cmd::DeleteSet{"stiff"});
        REQUIRE(s.dispatch(cmd::ImportRecipe{(dir / "two.json").string()}));
        REQUIRE(s.document().sets.size() == 2);
        CHECK(s.document().sets[0].mu == 2.0);
        CHECK(s.document().sets[1].mu == 50.0);
        CHECK(s.document().sets[1].vertices.size() == stiff);
    }

    TEST_CASE("import restores the sets of an exported recipe")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        make_region_and_moved_pins(b, {0.001, 0.0, 0.0});
        s.dispatch(cmd::Step{4});
        const fs::path recipe = dir / "recipe.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));
        const Recipe exported = file_recipe(s.document());
        s.dispatch(cmd::DeleteSet{"pins"});
        s.dispatch(cmd::DeleteSet{"patch"});
        REQUIRE(s.dispatch(cmd::ImportRecipe{recipe.string()}));
        REQUIRE(s.document().sets.size() == 2);
        CHECK(s.document().sets[0].kind == ConstraintKind::Region);
        CHECK(s.document().sets[1].kind == ConstraintKind::Pin);
        Recipe again = file_recipe(s.document());
        again.iterations = exported.iterations;
        CHECK(recipe_to_json(again) == recipe_to_json(exported));
        CHECK_FALSE(s.dispatch(cmd::ImportRecipe{(dir / "missing.json").string()}));
        test::write_bytes(dir / "bad.json", R"({"hard": {"vertices": [99999999]}})");
        CHECK_FALSE(s.dispatch(cmd::ImportRecipe{(dir / "bad.json").string()}));
        CHECK(s.state().message.find("hard.vertices[0]") != std::string::npos);
    }

    TEST_CASE("undo of any mix of selection, set, setting and solver steps is exact")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        std::mt19937 rng(11);
        std::uniform_int_distribution<int> pick(0, 99);
        const auto state = [&] {
            const Document& d = s.document();
            return State{d.selected_vertices, d.selected_faces, d.sets, d.solver,
                         d.mesh.positions,    d.base_positions};
        };
        std::vector<State> states{state()};
        for (int k = 0; k < 40; ++k)
        {
            const std::size_t before = s.history().undo_count();
            const int what = pick(rng);
            if (what < 25)
                b.rectangle(pick(rng) * 4, pick(rng) * 3, pick(rng) * 4, pick(rng) * 3,
                            {.shift = pick(rng) < 50});
            else if (what < 45)
                s.dispatch(cmd::CreateSet{static_cast<ConstraintKind>(pick(rng) % 3), {}});
            else if (what < 55 && !s.document().sets.empty())
                s.dispatch(cmd::DeleteSet{
                    s.document()
                        .sets[static_cast<size_t>(pick(rng)) % s.document().sets.size()]
                        .name});
            else if (what < 65)
            {
                SolverSettings settings = s.document().solver;
                settings.lambda = 0.1 + 0.005 * pick(rng);
                s.dispatch(cmd::SetSolverSettings{settings});
            }
            else if (what < 85)
                s.dispatch(cmd::Step{1 + pick(rng) % 3});
            else if (what < 92)
                s.dispatch(cmd::ResetShape{});
            else
                s.dispatch(cmd::ApplyShape{});
            if (s.history().undo_count() > before)
                states.push_back(state());
        }
        REQUIRE(states.size() > 15);
        for (size_t k = states.size() - 1; k > 0; --k)
        {
            REQUIRE(s.dispatch(cmd::Undo{}));
            CHECK(same(state(), states[k - 1]));
        }
        for (size_t k = 1; k < states.size(); ++k)
        {
            REQUIRE(s.dispatch(cmd::Redo{}));
            CHECK(same(state(), states[k]));
        }
    }

    TEST_CASE("meshfair-cli itself reproduces the editor's shape from the exported recipe")
    {
        // End to end, on the noisy bunny as a file: the recipe exported, the real
        // executable run on the file, its output read back. It also holds the in-process
        // pipeline the other cases compare with (cli_positions) to the executable's bits.
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_bunny());
        EditorSession& s = b.session;
        make_every_kind_of_set(b, false);
        CHECK(s.problems().empty());
        SolverSettings settings = s.document().solver;
        settings.lambda = 0.4;
        settings.iterations_per_frame = 3;
        s.dispatch(cmd::SetSolverSettings{settings});
        step_then_play(s, 4, 3);

        const fs::path recipe = dir / "recipe.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));
        const std::vector<Scalar> cli = cli_executable_positions(b.path, recipe);
        CHECK(cli == file_order_mesh(s.document()).positions);
        CHECK(cli_positions(b.path, recipe) == cli);
    }
}

TEST_SUITE("Smoothing brush")
{
    // A stroke of the Paint tool across the sphere's front, as the mouse gives it.
    void stroke(EditorSession & s, const PaintSettings& paint)
    {
        s.dispatch(cmd::SetTool{ToolKind::Paint});
        REQUIRE(s.dispatch(cmd::SetPaintSettings{paint}));
        s.mouse_press(MouseButton::Left, {}, 170, 150);
        for (int k = 1; k <= 8; ++k)
            s.mouse_move(170 + 8 * k, 150 + 3 * k);
        s.mouse_release(MouseButton::Left, 234, 174);
        s.update();
    }

    TEST_CASE(
        "a stroke is one undo step, moves only what it covers, and meshfair-cli "
        "reproduces it from the exported recipe")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.update();
        const std::vector<Scalar> before = s.document().mesh.positions;
        PaintSettings paint;
        paint.strength = 0.6;
        paint.steps = 12;
        stroke(s, paint);
        const Document& d = s.document();
        REQUIRE(s.last_stroke().size() > 4);
        CHECK(s.history().undo_count() == 1);
        CHECK(s.history().undo_label() == "smooth stroke");
        REQUIRE(d.sets.size() == 1);
        const ConstraintSet& brush = d.sets[0];
        CHECK(brush.name == "brush");
        CHECK(brush.kind == ConstraintKind::Region);
        REQUIRE(brush.weights.size() == brush.vertices.size());
        CHECK(std::all_of(brush.weights.begin(), brush.weights.end(),
                          [](Scalar w) { return w > 0 && w <= 1; }));
        CHECK(d.steps_from_base == 12);
        CHECK(d.reproducible);
        // Vertices the stroke did not reach keep their bits; those it freed moved.
        std::vector<char> reached(before.size() / 3, 0);
        for (const Index v : brush.vertices)
            reached[static_cast<size_t>(v)] = 1;
        size_t moved = 0, kept = 0;
        for (size_t i = 0; i < reached.size(); ++i)
        {
            const bool same = std::equal(before.begin() + 3 * i, before.begin() + 3 * i + 3,
                                         d.mesh.positions.begin() + 3 * i);
            if (!reached[i])
                kept += same ? 1 : 0;
            else
                moved += same ? 0 : 1;
        }
        CHECK(kept == reached.size() - brush.vertices.size());
        CHECK(moved > brush.vertices.size() / 2);
        // The stroke's region with its weight map, exported, runs the same bits.
        CHECK(cli_reproduces(s, b.path, dir));
        const Recipe r = read_recipe((dir / "recipe.json").string());
        REQUIRE(r.soft);
        CHECK_FALSE(r.soft->weights.empty());

        // A brush region taken out of the solve is not painted with: the run would move
        // the whole mesh.
        REQUIRE(s.dispatch(cmd::EnableSet{"brush", false}));
        const std::vector<Scalar> stroked = s.document().mesh.positions;
        CHECK_FALSE(s.dispatch(cmd::PaintDab{"brush", PaintMode::Relax, Vec3{0, 0, 0}, 0.1, 0.5,
                                             FalloffCurve::Smooth, 3}));
        CHECK(s.state().message == "set 'brush' is out of the solve: take it in to smooth with it");
        CHECK(s.document().mesh.positions == stroked);
        REQUIRE(s.dispatch(cmd::Undo{})); // the set taken out

        // Undo: the shape and the sets as they were.
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().mesh.positions == before);
        CHECK(s.document().sets.empty());
    }

    TEST_CASE(
        "export then import keeps every set as made (names, colours, maps, shown or not) and "
        "the up axis, and a file edited since falls back to its sections, saying so")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_bunny());
        EditorSession& s = b.session;
        s.update();
        make_every_kind_of_set(b, true);
        // A painted region map, a renamed and recoloured set, a hidden one, -Z up.
        PaintSettings paint;
        paint.steps = 3;
        stroke(s, paint);
        REQUIRE(s.dispatch(cmd::RenameSet{"anchors", "ears"}));
        REQUIRE(s.dispatch(cmd::SetColor{"ears", {0.2f, 0.4f, 0.6f}}));
        REQUIRE(s.dispatch(cmd::ShowSet{"normals", false}));
        REQUIRE(s.dispatch(cmd::SetSetWeight{"centroids", 3}));
        REQUIRE(s.dispatch(cmd::SetUpAxis{UpAxis::NegZ}));
        const std::vector<ConstraintSet> made = s.document().sets;
        const SolverSettings settings = s.document().solver;
        REQUIRE(std::any_of(made.begin(), made.end(),
                            [](const ConstraintSet& c) { return !c.weights.empty(); }));
        const fs::path recipe = dir / "sets.json";
        REQUIRE(s.dispatch(cmd::ExportRecipe{recipe.string()}));

        // Another session on the same file, +Y up, imports it.
        fs::create_directories(dir / "again");
        Editing other(dir / "again", noisy_bunny());
        EditorSession& t = other.session;
        REQUIRE(t.camera().up_axis == UpAxis::Y);
        REQUIRE(t.dispatch(cmd::ImportRecipe{recipe.string()}));
        // The same sets, each element with its target, normal and weight (listed in the
        // file's order: runs in the file).
        CHECK(by_element(t.document().sets) == by_element(made));
        CHECK(t.document().solver.anchor_mu == settings.anchor_mu);
        CHECK(t.camera().up_axis == UpAxis::NegZ);
        CHECK(t.state().message.find("no longer make them") == std::string::npos);
        // The recipe the imported sets make is the exported one.
        Recipe again = file_recipe(t.document());
        Recipe exported = file_recipe(s.document());
        again.iterations = exported.iterations;
        CHECK(recipe_to_json(again) == recipe_to_json(exported));

        // The file is compact: index lists as runs, far smaller than plain lists.
        const std::string text = io::read_file(recipe.string());
        nlohmann::json plain = nlohmann::json::parse(text);
        size_t runs = 0;
        for (const nlohmann::json& set : plain["editor"]["sets"])
            for (const nlohmann::json& item : set["vertices"])
                runs += item.is_array() ? 1 : 0;
        CHECK(runs > 0);

        // Edited by hand: a region vertex taken out of the sections. The sets come from the
        // sections, and the status line says why.
        nlohmann::json edited = plain;
        nlohmann::json& region = edited["region"]["vertices"];
        region.erase(region.begin());
        test::write_bytes(dir / "edited.json", edited.dump());
        REQUIRE(t.dispatch(cmd::ImportRecipe{(dir / "edited.json").string()}));
        CHECK(t.state().message.find("no longer make them") != std::string::npos);
        CHECK(by_element(t.document().sets) != by_element(made));
        // A damaged editor object is refused, naming it.
        nlohmann::json damaged = plain;
        damaged["editor"]["sets"][0]["vertices"] = nlohmann::json::array({-4});
        test::write_bytes(dir / "damaged.json", damaged.dump());
        CHECK_FALSE(t.dispatch(cmd::ImportRecipe{(dir / "damaged.json").string()}));
        CHECK(t.state().message.find("editor.sets[0]") != std::string::npos);
    }

    TEST_CASE(
        "a stroke's recorded dabs, played as a script by the editor, give its shape "
        "bit for bit")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.update();
        PaintSettings paint;
        paint.strength = 0.4;
        paint.curve = FalloffCurve::Sphere;
        paint.steps = 7;
        stroke(s, paint);
        // Two strokes: the second starts from the first's shape.
        paint.strength = 0.9;
        stroke(s, paint);
        CHECK(s.history().undo_count() == 2);
        CHECK_FALSE(s.document().reproducible); // two runs: Apply first for one recipe
        const std::string action = stroke_action(s.last_stroke());
        REQUIRE(action.find("\"paint\"") != std::string::npos);

        // The first stroke's dabs are the same as the second's path: replay both.
        REQUIRE(s.dispatch(cmd::Undo{}));
        REQUIRE(s.dispatch(cmd::Undo{}));
        std::vector<cmd::PaintDab> first;
        paint.strength = 0.4;
        stroke(s, paint);
        first = s.last_stroke();
        paint.strength = 0.9;
        stroke(s, paint);
        const fs::path script = dir / "replay.json", out = dir / "replayed.obj";
        test::write_bytes(script, "{\"actions\": [" + stroke_action(first) + ", " + action +
                                      ", {\"save_mesh\": " + nlohmann::json(out.string()).dump() +
                                      "}]}");
        REQUIRE_NOTHROW(play_offscreen(b.path, script));
        CHECK(io::read_mesh(out.string()).positions == file_order_mesh(s.document()).positions);
    }

    TEST_CASE(
        "a stroke's dab returns before its run is prepared (the interface runs no step), a "
        "newer dab supersedes a run not yet done, and the stroke ends in the last dab's run")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.settle_solver(); // the opening's run prepared
        const std::vector<Scalar> before = s.document().mesh.positions;
        const size_t steps = s.history().undo_count();
        const SolverStatus at_start = s.solver_status();
        test::PhaseGate gate;
        s.observe_preparation([&gate](const PreparationProgress::Snapshot& p) { gate.arrive(p); });

        // The first dab's run held in its preparation: the dab has returned all the same,
        // with its map painted and the shape not yet changed.
        const cmd::PaintDab first = relax_dab(-0.2, 0, 12), second = relax_dab(0.2, 0.1, 12);
        gate.hold(PreparationProgress::Phase::Assembling);
        REQUIRE(s.dispatch(first, Interaction{"stroke"}));
        gate.wait_held();
        CHECK(s.solver_status().preparing);
        REQUIRE(s.set_named("brush"));
        CHECK_FALSE(s.document().sets[0].weights.empty());
        s.update();
        CHECK(s.document().mesh.positions == before);
        // The second dab while the first's run is under way: it supersedes that run.
        REQUIRE(s.dispatch(second, Interaction{"stroke"}));
        CHECK(s.document().mesh.positions == before);
        gate.release();
        s.end_interaction(); // waits for the last dab's run, then records the stroke
        const std::vector<Scalar> stroked = s.document().mesh.positions;
        CHECK(stroked != before);
        CHECK(s.history().undo_count() == steps + 1);
        CHECK(s.history().undo_label() == "smooth stroke");
        CHECK(s.document().steps_from_base == 12);
        const SolverStatus st = s.solver_status();
        CHECK(st.steps_on_caller == at_start.steps_on_caller); // all steps on the worker
        // The first dab's run was never made the current one: one restart, the second's.
        CHECK(st.restarts == at_start.restarts + 1);
        CHECK_FALSE(st.preparing);
        // The last dab's run alone, from the base: meshfair-cli's path on the exported
        // recipe gives the same bits.
        CHECK(cli_reproduces(s, b.path, dir));
        // ... and the first dab's run alone ends elsewhere: that shape was not kept.
        fs::create_directories(dir / "first");
        Editing one(dir / "first", noisy_sphere());
        REQUIRE(one.session.dispatch(first, Interaction{"stroke"}));
        one.session.end_interaction();
        CHECK(one.session.document().mesh.positions != before);
        CHECK(one.session.document().mesh.positions != stroked);

        // Undo: the stroke's start, the sets as they were; redo: the stroke's shape.
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().mesh.positions == before);
        CHECK(s.document().sets.empty());
        REQUIRE(s.dispatch(cmd::Redo{}));
        CHECK(s.document().mesh.positions == stroked);
    }

    TEST_CASE(
        "a stroke of many dabs, faster than their runs, is one undo step ending bit for bit in "
        "the shape of its last dab's run alone")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        s.settle_solver();
        const std::vector<Scalar> before = s.document().mesh.positions;
        const int on_caller = s.solver_status().steps_on_caller;
        const int restarts = s.solver_status().restarts;
        const int dabs = 30;
        for (int k = 0; k < dabs; ++k)
        {
            REQUIRE(s.dispatch(relax_dab(-0.4 + 0.8 * k / (dabs - 1), 0.1 * (k % 3), 9),
                               Interaction{"stroke"}));
            if (k % 4 == 0)
                s.update(); // a frame now and then shows the newest run done
        }
        s.end_interaction();
        const std::vector<Scalar> stroked = s.document().mesh.positions;
        CHECK(s.history().undo_count() == 1);
        CHECK(s.document().steps_from_base == 9);
        CHECK(s.document().reproducible);
        CHECK(s.solver_status().steps_on_caller == on_caller);
        // At most one restart a dab: the runs superseded were dropped, not queued.
        CHECK(s.solver_status().restarts - restarts <= dabs);
        // The same map's run alone, by meshfair-cli's path and by the editor's own Step on
        // the imported recipe (from the base, on the caller's thread: counted there).
        CHECK(cli_reproduces(s, b.path, dir));
        fs::create_directories(dir / "again");
        Editing other(dir / "again", noisy_sphere());
        EditorSession& t = other.session;
        REQUIRE(t.dispatch(cmd::ImportRecipe{(dir / "recipe.json").string()}));
        const int t_on_caller = t.solver_status().steps_on_caller;
        REQUIRE(t.dispatch(cmd::Step{9}));
        CHECK(t.solver_status().steps_on_caller == t_on_caller + 9);
        CHECK(t.document().mesh.positions == stroked);
        // One undo step: back to the start exactly.
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().mesh.positions == before);
        CHECK(s.document().sets.empty());
        CHECK_FALSE(s.dispatch(cmd::Undo{}));
    }

    TEST_CASE("painting an anchor set's weights with the mouse is one undo step a stroke")
    {
        const fs::path dir = test::temp_dir();
        Editing b(dir, noisy_sphere());
        EditorSession& s = b.session;
        b.rectangle(120, 80, 300, 220);
        REQUIRE(s.dispatch(cmd::CreateSet{ConstraintKind::Anchor, "anchors"}));
        const size_t steps = s.history().undo_count();
        PaintSettings paint;
        paint.mode = PaintMode::Subtract;
        paint.strength = 0.5;
        paint.set = "anchors";
        stroke(s, paint);
        CHECK(s.history().undo_count() == steps + 1);
        CHECK(s.history().undo_label() == "paint weights");
        CHECK(s.document().mesh.positions == s.document().base_positions); // nothing ran
        const ConstraintSet& anchors = s.document().sets[0];
        REQUIRE(anchors.weights.size() == anchors.vertices.size());
        const auto lowered = std::count_if(anchors.weights.begin(), anchors.weights.end(),
                                           [](Scalar w) { return w < 1; });
        CHECK(lowered > 0);
        CHECK(static_cast<size_t>(lowered) < anchors.vertices.size());
        // However often the dabs overlap, a stroke lowers a weight by its strength at most.
        CHECK(std::all_of(anchors.weights.begin(), anchors.weights.end(),
                          [](Scalar w) { return w >= 0.5 && w <= 1; }));
        CHECK(*std::min_element(anchors.weights.begin(), anchors.weights.end()) < 0.55);
        // The recipe holds each anchor with the kind's weight times its map.
        SolverSettings settings = s.document().solver;
        settings.anchor_mu = 3;
        REQUIRE(s.dispatch(cmd::SetSolverSettings{settings}));
        const Recipe r = build_recipe(s.document().sets, s.document().solver, s.document().mesh,
                                      s.document().base_positions, 1);
        REQUIRE(r.soft);
        REQUIRE(r.soft->weights.size() == anchors.vertices.size());
        for (size_t k = 0; k < anchors.vertices.size(); ++k)
            CHECK(r.soft->weights[k] == 3 * anchors.weights[k]);
        // Smoothing the map, then undoing it, returns the painted map exactly.
        const std::vector<Scalar> painted = s.document().sets[0].weights;
        paint.mode = PaintMode::Smooth;
        stroke(s, paint);
        CHECK(s.document().sets[0].weights != painted);
        REQUIRE(s.dispatch(cmd::Undo{}));
        CHECK(s.document().sets[0].weights == painted);
        // Subtract on a set that is not there is refused, naming it.
        paint.set = "nothing";
        paint.mode = PaintMode::Subtract;
        CHECK_FALSE(s.dispatch(cmd::PaintDab{
            "nothing", PaintMode::Subtract, {0, 0, 0}, 0.1, 0.5, FalloffCurve::Smooth, 1}));
        CHECK(s.state().message == "no set named 'nothing' to paint");
    }
}
