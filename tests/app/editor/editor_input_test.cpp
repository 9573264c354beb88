// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// The editor as a person drives it, without GL: raw input through the input router and the
// interface (Dear ImGui laid out, never drawn) to the commands, with a RecordingRenderer.
#include <doctest/doctest.h>

#include <map>

#include <algorithm>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <set>

#include "app/editor/constraint_glyphs.h"
#include "app/editor/editor_frame.h"
#include "app/editor/editor_session.h"
#include "app/editor/interface_context.h"
#include "app/editor/key_map.h"
#include "app/editor/script.h"
#include "app/editor/user_files.h"
#include "app/render/image.h"
#include "app/render/recording_renderer.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "tests/app/editor/phase_gate.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

std::size_t count(const SelectionMask& m)
{
    return static_cast<std::size_t>(std::count(m.begin(), m.end(), 1));
}

// An editor on a mesh file with its interface, no window and no GL.
struct Editor
{
    RecordingRenderer renderer;
    EditorSession session;
    InterfaceContext layer{false};
    EditorFrame frame{session, &layer};

    explicit Editor(const fs::path& mesh) : session(load_document(mesh.string()), renderer)
    {
        session.state().offscreen = true;
        session.set_recovery_root({});
        run();
        session.camera().frame(session.document().box, session.aspect());
        run();
    }
    const Document& doc() const { return session.document(); }
    void run(int frames = 1)
    {
        for (int k = 0; k < frames; ++k)
        {
            frame.run({kWidth, kHeight, kWidth, kHeight}, 1.0 / 60);
            frame.draw(); // the renderer gets what changed, as in a window
        }
    }
    // Pushes events, then runs frames until the router has handed them all out.
    void input(const std::vector<InputEvent>& events)
    {
        for (const InputEvent& e : events)
            frame.input().push(e);
        while (frame.input().pending())
            run();
        run();
    }
    void drag(std::vector<ScreenPoint> points, Modifiers mods = {})
    {
        input(drag_events(points, MouseButton::Left, mods));
    }
    void click(double x, double y) { drag({{x, y, 0}, {x, y, 0}}); }
    // A region of the view's square [r0, r1]^2 (fractions of the view), then pins of
    // [p0, p1]^2, each with the rectangle tool and its key.
    void region_and_pins(double r0, double r1, double p0, double p1)
    {
        key("r");
        drag({view_point(r0, r0), view_point(r1, r1)});
        key("shift+r");
        drag({view_point(p0, p0), view_point(p1, p1)});
        key("shift+p");
    }
    void key(const char* chord) { input(key_events(*parse_key_chord(chord))); }
    void type(const std::string& text)
    {
        std::vector<InputEvent> events;
        for (const char c : text)
        {
            InputEvent e;
            e.type = InputEvent::Type::Char;
            e.key = c;
            events.push_back(e);
        }
        input(events); // all queued at once, as fast typing queues them
    }
    // Where a widget is; one scrolled out of the side panel is scrolled to with the wheel,
    // as a person does.
    WidgetRect widget(const std::string& label)
    {
        for (int attempt = 0; attempt < 40 && !frame.ui().widget(label); ++attempt)
        {
            InputEvent wheel = input_event(InputEvent::Type::Scroll, {kWidth - 170.0, 400, 0});
            wheel.amount = attempt < 20 ? -3 : 3; // down, then up
            input({input_event(InputEvent::Type::MouseMove, {kWidth - 170.0, 400, 0}), wheel});
        }
        const std::optional<WidgetRect> w = frame.ui().widget(label);
        REQUIRE_MESSAGE(w.has_value(), label);
        return *w;
    }
    void click_widget(const std::string& label)
    {
        const WidgetRect w = widget(label);
        click(w.center_x(), w.center_y());
    }
    // The middle of the 3D view, in framebuffer pixels.
    ScreenPoint view_point(double fx, double fy) const
    {
        const ViewRect& v = session.view_rect();
        return {v.x + fx * v.width, v.y + fy * v.height, 0};
    }
};

fs::path bunny_copy()
{
    const fs::path dir = test::temp_dir();
    const fs::path p = dir / "bunny.obj";
    fs::copy_file(test::assets_dir() / "bunny.obj", p);
    return p;
}

} // namespace

TEST_SUITE("Editor input")
{
    TEST_CASE("the key map: every chord gives its row's command, and no chord is bound twice")
    {
        std::set<std::tuple<int, bool, bool, bool>> seen;
        std::size_t chords = 0;
        for (const KeyBinding& b : key_bindings())
            for (const KeyAction& k : b.keys)
            {
                ++chords;
                CHECK_MESSAGE(seen.insert({k.chord.key, k.chord.mods.shift, k.chord.mods.ctrl,
                                           k.chord.mods.alt})
                                  .second,
                              b.input);
                const std::optional<Command> c = command_for_key(k.chord);
                REQUIRE(c.has_value());
                CHECK(c->index() == k.command.index());
            }
        CHECK(chords > 50);
        // Modifiers must match exactly: Ctrl+Shift+A is no binding, Shift+R a set.
        CHECK_FALSE(command_for_key(*parse_key_chord("ctrl+shift+a")).has_value());
        CHECK(
            std::holds_alternative<cmd::CreateSet>(*command_for_key(*parse_key_chord("shift+r"))));
        CHECK(std::holds_alternative<cmd::SetTool>(*command_for_key(*parse_key_chord("r"))));
        CHECK(std::holds_alternative<cmd::Solve>(*command_for_key(*parse_key_chord("enter"))));
        CHECK_FALSE(parse_key_chord("hyper+q").has_value());
        // Function keys F1 to F12; a long run of digits names none (and does not throw).
        CHECK(parse_key_chord("f12").has_value());
        CHECK_FALSE(parse_key_chord("f13").has_value());
        CHECK_FALSE(parse_key_chord("f0").has_value());
        CHECK_FALSE(
            parse_key_chord("f0000000000000000000000000000000000000000300000000001").has_value());
    }

    TEST_CASE("a click on a panel never reaches the view: the selection stays, the button acts")
    {
        Editor e(bunny_copy());
        e.key("r"); // the rectangle tool, through the key map
        REQUIRE(e.session.tool() == ToolKind::Rectangle);
        e.drag({e.view_point(0.3, 0.3), e.view_point(0.45, 0.4), e.view_point(0.6, 0.6)});
        const std::size_t selected = count(e.doc().selected_vertices);
        REQUIRE(selected > 100);
        REQUIRE(e.session.history().undo_count() == 1);
        // An empty part of the side panel, below its last section.
        const WidgetRect grow = e.widget("Grow");
        e.click(grow.x1 + 60, grow.center_y());
        CHECK(count(e.doc().selected_vertices) == selected);
        CHECK(e.session.history().undo_count() == 1);
        // A button of the panel with the tool active: it acts on the selection.
        e.click_widget("Grow");
        CHECK(count(e.doc().selected_vertices) > selected);
        CHECK(e.session.history().undo_count() == 2);
        CHECK(e.session.history().undo_label() == "select grow");
        // And the menus: Select > invert; the renderer shows what is selected.
        const std::size_t grown = count(e.doc().selected_vertices);
        e.click_widget("Select");
        e.click_widget("Select/invert");
        CHECK(count(e.doc().selected_vertices) ==
              static_cast<std::size_t>(e.doc().mesh.vertex_count()) - grown);
        CHECK(e.session.history().undo_label() == "select invert");
        CHECK(e.renderer.selected_vertices() == e.doc().selected_vertices);
    }

    TEST_CASE("keys typed into a field never trigger a binding, Ctrl+A then typing replaces")
    {
        const fs::path mesh = bunny_copy();
        Editor e(mesh);
        e.key("ctrl+a");
        e.key("shift+p"); // a pin set of everything
        REQUIRE(e.doc().sets.size() == 1);
        e.click_widget("sets/pin 1/rename");
        e.key("ctrl+a");
        e.type("rrr wide"); // 'r' would pick the rectangle tool, space would play
        e.key("enter");
        CHECK(e.doc().sets[0].name == "rrr wide");
        CHECK(e.session.tool() == ToolKind::Navigate);
        CHECK_FALSE(e.session.playing());
        CHECK(e.doc().solver.method == Method::Jacobi); // Enter ended the field, not Solve

        // Save as: the dialog's name field holds "bunny.obj"; Ctrl+A selects it and the
        // typed name replaces it, every character of a fast burst kept.
        e.key("ctrl+shift+s");
        e.key("ctrl+a");
        e.type("crown-of-the-head.ply");
        e.key("enter");
        const fs::path saved = mesh.parent_path() / "crown-of-the-head.ply";
        CHECK(fs::exists(saved));
        CHECK(e.doc().path == saved.string());
        CHECK(e.session.state().message == "saved " + saved.string());
        // Ctrl+S now saves to the new name.
        fs::remove(saved);
        e.key("ctrl+s");
        CHECK(fs::exists(saved));
        // Typing at once, without Ctrl+A: the name shown is selected, the typing replaces it.
        e.key("ctrl+shift+s");
        e.type("at-once.obj");
        e.key("enter");
        CHECK(fs::exists(mesh.parent_path() / "at-once.obj"));
        CHECK(e.doc().path == (mesh.parent_path() / "at-once.obj").string());
    }

    TEST_CASE("M and D over the view: the pins follow the cursor, the normals turn, one step each")
    {
        Editor e(bunny_copy());
        e.key("r");
        e.drag({e.view_point(0.35, 0.35), e.view_point(0.45, 0.45)});
        e.key("shift+p");
        e.key("v"); // faces
        e.drag({e.view_point(0.5, 0.5), e.view_point(0.6, 0.6)});
        e.key("shift+n");
        REQUIRE(e.doc().sets.size() == 2);
        const std::size_t steps = e.session.history().undo_count();
        // Hovering with each tool draws its reach and acts on nothing.
        for (const char* tool : {"m", "d"})
        {
            e.key(tool);
            e.input({input_event(InputEvent::Type::MouseMove, e.view_point(0.2, 0.2)),
                     input_event(InputEvent::Type::MouseMove, e.view_point(0.7, 0.3))});
            CHECK(e.session.state().overlay.shape == ToolOverlay::Shape::Circle);
        }
        CHECK(e.session.history().undo_count() == steps);

        // A drag from a pin's glyph moves the set's targets with the cursor.
        e.key("m");
        const ConstraintSet& pins = e.doc().sets[0];
        const size_t i = 3 * static_cast<size_t>(pins.vertices[0]);
        const std::vector<Scalar>& x = e.doc().mesh.positions;
        const glm::dvec3 w = e.session.camera().project(
            {x[i], x[i + 1], x[i + 2]}, e.session.view_rect().width, e.session.view_rect().height);
        const ScreenPoint from{w.x + e.session.view_rect().x, w.y + e.session.view_rect().y, 0};
        const std::uint64_t members = e.doc().versions.set_members;
        e.drag({from, {from.x + 10, from.y, 0}, {from.x + 30, from.y - 20, 0}});
        // Moving pins changes no set's elements: notes, holes and the border ring stay.
        CHECK(e.doc().versions.set_members == members);
        REQUIRE(e.doc().sets[0].targets.size() == pins.vertices.size());
        // Targets away from the base; the solver puts the pins there once its thread has
        // prepared the dome's recipe (the interface does not wait for it).
        const std::vector<Scalar>& base_shape = e.doc().base_positions;
        const Vec3 target = e.doc().sets[0].targets[0];
        CHECK(std::abs(target[0] - base_shape[i]) + std::abs(target[1] - base_shape[i + 1]) +
                  std::abs(target[2] - base_shape[i + 2]) >
              0);
        e.session.settle_solver();
        e.run();
        CHECK(x[i] == target[0]);
        CHECK(x[i + 1] == target[1]);
        CHECK(x[i + 2] == target[2]);
        CHECK(e.session.history().undo_count() == steps + 1);
        CHECK(e.session.history().undo_label() == "move pins");

        // A drag from a normal arrow's base turns the set's direction.
        e.key("d");
        const ConstraintSet& normals = e.doc().sets[1];
        const Vec3 c = face_centroid(e.doc().mesh, x, normals.faces[0]);
        const glm::dvec3 cw = e.session.camera().project(
            {c[0], c[1], c[2]}, e.session.view_rect().width, e.session.view_rect().height);
        const ScreenPoint base{cw.x + e.session.view_rect().x, cw.y + e.session.view_rect().y, 0};
        e.drag({base, {base.x + 40, base.y, 0}, {base.x + 80, base.y + 10, 0}});
        REQUIRE(e.doc().sets[1].normals.size() == normals.faces.size());
        CHECK(e.session.history().undo_count() == steps + 2);
        CHECK(e.session.history().undo_label() == "normal direction");
        e.key("ctrl+z");
        CHECK(e.doc().sets[1].normals.empty());

        // The arrow a press at the base would take is highlighted, base to tip, and follows a
        // zoom at the cursor without the cursor moving (the frame's camera, not the last
        // move's).
        e.input({input_event(InputEvent::Type::MouseMove, base)});
        const std::vector<ScreenPoint> lit = e.session.state().grab_hover;
        REQUIRE(lit.size() == 2);
        CHECK(std::hypot(lit[0].x - base.x, lit[0].y - base.y) < kGrabRadiusPx);
        InputEvent wheel = input_event(InputEvent::Type::Scroll, base);
        wheel.amount = 3;
        e.input({wheel});
        const std::vector<ScreenPoint> zoomed = e.session.state().grab_hover;
        REQUIRE(zoomed.size() == 2);
        CHECK(std::hypot(zoomed[1].x - zoomed[0].x, zoomed[1].y - zoomed[0].y) >
              1.2 * std::hypot(lit[1].x - lit[0].x, lit[1].y - lit[0].y));
        // Another tool highlights nothing.
        e.key("n");
        CHECK(e.session.state().grab_hover.empty());
    }

    TEST_CASE(
        "a long preparation shows where it is, and Esc, the Cancel over the view or the menu stops "
        "it")
    {
        Editor e(bunny_copy());
        e.region_and_pins(0.3, 0.7, 0.48, 0.53);
        REQUIRE(e.doc().sets.size() == 2);
        const std::string pins = e.doc().sets[1].name;
        const std::vector<Scalar> before = e.doc().mesh.positions;
        // The solver's thread held where the ordering begins, as a large mesh's would stay
        // there for seconds, until the test lets it go on.
        test::PhaseGate gate;
        e.session.observe_preparation(
            [&gate](const PreparationProgress::Snapshot& p) { gate.arrive(p); });

        // Enter solves: the box over the view and the panel show the phase; Esc cancels.
        gate.hold(PreparationProgress::Phase::Ordering);
        e.key("enter");
        REQUIRE(e.doc().solver.method == Method::Direct);
        const std::size_t steps = e.session.history().undo_count();
        e.run(); // (the restart, at the frame after the key's)
        gate.wait_held();
        e.run();
        const SolverStatus& st = e.session.state().solver;
        CHECK(st.preparing);
        CHECK(st.preparation.phase == PreparationProgress::Phase::Ordering);
        CHECK(st.preparation.unknowns > 100);
        CHECK(st.preparation.expected_seconds > 0);
        e.widget("cancel preparation"); // the box's Cancel
        // Pins moved meanwhile: the interface does not wait for the solver's thread.
        REQUIRE(e.session.dispatch(cmd::MovePins{pins, {0.0, 0.01, 0.0}}));
        e.key("escape");
        CHECK(e.session.state().message.rfind("preparation cancelled", 0) == 0);
        gate.release();
        e.session.settle_solver();
        e.run();
        CHECK_FALSE(st.preparing);
        CHECK(st.cancelled);
        CHECK_FALSE(st.ready);
        CHECK(st.error.empty());
        CHECK_FALSE(e.frame.ui().widget("cancel preparation").has_value());
        // Nothing was solved: the shape is as it was but for the pins moved, and the
        // cancel is no undo step.
        const std::vector<Scalar>& x = e.doc().mesh.positions;
        std::vector<char> pinned(before.size() / 3, 0);
        for (const Index v : e.doc().sets[1].vertices)
            pinned[static_cast<size_t>(v)] = 1;
        size_t same = 0;
        for (size_t v = 0; v < pinned.size(); ++v)
            same += !pinned[v] && std::equal(x.begin() + 3 * v, x.begin() + 3 * v + 3,
                                             before.begin() + 3 * v)
                        ? 1
                        : 0;
        CHECK(same == pinned.size() - e.doc().sets[1].vertices.size());
        CHECK(e.session.history().undo_count() == steps + 1); // the pins moved
        // Esc again: nothing to cancel.
        e.key("escape");
        CHECK(e.session.state().message == "nothing to cancel: the solver is not preparing");

        // Solve prepares again (the sets did not change); the menu's Cancel stops it.
        gate.hold(PreparationProgress::Phase::Ordering);
        e.key("enter");
        e.run();
        gate.wait_held();
        e.run();
        REQUIRE(st.preparing);
        e.click_widget("Solve");
        e.click_widget("Solve/Cancel preparation");
        gate.release();
        e.session.settle_solver();
        e.run();
        CHECK(st.cancelled);
        CHECK_FALSE(st.ready);

        // Solve prepares again; the Cancel over the view stops it.
        gate.hold(PreparationProgress::Phase::Ordering);
        e.click_widget("Solve");
        e.click_widget("Solve/Solve: the minimizer");
        e.run();
        gate.wait_held();
        e.run();
        REQUIRE(st.preparing);
        e.click_widget("cancel preparation");
        gate.release();
        e.session.settle_solver();
        e.run();
        CHECK(st.cancelled);

        // And the panel's Solve, let through: the minimizer of the sets with the pins
        // where they were moved to.
        e.click_widget("solver/Solve");
        e.session.settle_solver();
        e.run();
        CHECK_FALSE(st.cancelled);
        REQUIRE(st.ready);
        CHECK(st.error.empty());
        CHECK(gate.phases_seen() >= 4); // assembling, ordering, factoring, done
        const std::vector<Scalar>& solved = e.doc().mesh.positions;
        const size_t p = 3 * static_cast<size_t>(e.doc().sets[1].vertices[0]);
        const Vec3 target = e.doc().sets[1].targets[0];
        CHECK(solved[p + 1] == target[1]);
        CHECK(target[1] == doctest::Approx(e.doc().base_positions[p + 1] + 0.01));
        size_t moved = 0;
        for (size_t v = 0; v < pinned.size(); ++v)
            moved += !pinned[v] && !std::equal(solved.begin() + 3 * v, solved.begin() + 3 * v + 3,
                                               before.begin() + 3 * v)
                         ? 1
                         : 0;
        CHECK(moved > 100);
    }

    TEST_CASE("Play runs its steps and stops, each run and each change during one is a step")
    {
        Editor e(bunny_copy());
        e.key("r");
        e.drag({e.view_point(0.3, 0.3), e.view_point(0.5, 0.5)});
        e.key("shift+r");
        // The region's restart ends the "nothing holds the mesh" lines above Play: the
        // panel is clicked as it is after it, as a person sees it.
        e.session.settle_solver();
        e.run();
        e.click_widget("Play");
        while (e.session.playing())
            e.session.take_frame();
        e.run();
        CHECK(e.doc().steps_from_base == 20); // the default steps per run
        CHECK(e.session.history().undo_label() == "solve 20 steps");
        const std::vector<Scalar> after_first = e.doc().mesh.positions;

        // A setting changed during a run: the run so far is a step, then the change.
        SolverSettings s = e.doc().solver;
        s.steps_per_run = 400;
        e.session.dispatch(cmd::SetSolverSettings{s});
        e.key("space");
        REQUIRE(e.session.playing());
        e.session.take_frame();
        e.session.take_frame();
        s.lambda = 0.3;
        e.session.dispatch(cmd::SetSolverSettings{s});
        const std::vector<Scalar> at_change = e.doc().mesh.positions;
        const int steps_at_change = e.doc().steps_from_base;
        e.session.take_frame();
        e.key("space");
        REQUIRE_FALSE(e.session.playing());
        CHECK(e.doc().steps_from_base > steps_at_change);
        // Undo: the segment after the change, the change, the segment before it.
        e.key("ctrl+z");
        CHECK(e.doc().mesh.positions == at_change);
        e.key("ctrl+z");
        CHECK(e.doc().solver.lambda == 0.5);
        e.key("ctrl+z");
        CHECK(e.doc().mesh.positions == after_first);

        // Display only: hiding a set, the heat map, shading, are no undo steps.
        const std::size_t steps = e.session.history().undo_count();
        e.click_widget("sets/region 1/show");
        CHECK_FALSE(e.doc().sets[0].visible);
        e.key("s");
        e.session.dispatch(cmd::SetHeatMap{EnergyTerm::Total});
        CHECK(e.session.history().undo_count() == steps);
    }

    TEST_CASE("quitting asks only when there are unsaved changes")
    {
        {
            Editor e(bunny_copy());
            e.key("ctrl+q");
            CHECK(e.session.state().quit);
        }
        Editor f(bunny_copy());
        f.session.dispatch(cmd::AddNoise{0.1, 3});
        f.key("ctrl+q");
        CHECK_FALSE(f.session.state().quit);
        f.run();
        f.click_widget("Discard and quit");
        CHECK(f.session.state().quit);
    }
}

TEST_SUITE("Editor display")
{
    TEST_CASE("the region's ring takes its set's colour, each kind its own colour")
    {
        Editor e(bunny_copy());
        e.region_and_pins(0.3, 0.6, 0.4, 0.45);
        const std::array<float, 3> green{0.1f, 0.9f, 0.2f};
        e.session.dispatch(cmd::SetColor{"region 1", green});
        e.run();
        const std::vector<GlyphGroup>& glyphs = e.renderer.glyphs();
        REQUIRE(glyphs.size() == 3); // the pins, the ring's edges and its vertices
        CHECK(glyphs[1].color == green);
        CHECK(glyphs[2].color == green);
        std::set<std::array<float, 3>> colors;
        for (int k = 0; k < kConstraintKinds; ++k)
            colors.insert(default_color(static_cast<ConstraintKind>(k)));
        CHECK(colors.size() == static_cast<size_t>(kConstraintKinds));
    }

    TEST_CASE("the up axis: +Z from the menu, the front view along +y, remembered for the file")
    {
        const fs::path dir = test::temp_dir();
        const fs::path mesh = bunny_copy();
        setenv("XDG_CONFIG_HOME", (dir / "config").c_str(), 1);
        {
            Editor e(mesh);
            e.session.state().offscreen = false; // a person's session remembers
            e.click_widget("View");
            e.click_widget("View/Up axis +Z");
            CHECK(e.session.camera().up_axis == UpAxis::Z);
            CHECK(glm::length(e.session.camera().forward() - glm::dvec3(0, 1, 0)) < 1e-12);
            e.session.dispatch(cmd::OpenMesh{(test::assets_dir() / "bunny.obj").string()});
            e.session.dispatch(cmd::OpenMesh{mesh.string()});
            CHECK(e.session.camera().up_axis == UpAxis::Z);
        }
        CHECK(load_up_axis(up_axes_path(), mesh.string()) == UpAxis::Z);
        unsetenv("XDG_CONFIG_HOME");
    }
}

TEST_SUITE("Editor sets")
{
    TEST_CASE(
        "a region's holes: a pit of any depth it surrounds, not the rest of the mesh, not an "
        "end of a band, not another component")
    {
        // A 20 x 20 grid of vertices beside a second, untouched one.
        Mesh grid = test::open_grid(19, 19);
        const Mesh other = test::open_grid(3, 3);
        const Index offset = grid.vertex_count();
        for (Index v = 0; v < other.vertex_count(); ++v)
            grid.add_vertex(other.positions[3 * v] + 30, other.positions[3 * v + 1], 0);
        for (Index f = 0; f < other.face_count(); ++f)
        {
            std::vector<Index> face;
            for (const Index v : other.face(f))
                face.push_back(v + offset);
            grid.add_face(face);
        }
        const Topology topology = build_topology(grid, TopologyParts::All);
        const auto at = [](int i, int j) { return static_cast<Index>(j * 20 + i); };
        // A square block of rows and columns 2..17 without a 5 x 5 pit inside it, deeper than
        // one ring closes.
        ConstraintSet block;
        std::vector<Index> pit;
        for (int j = 2; j <= 17; ++j)
            for (int i = 2; i <= 17; ++i)
                (i >= 7 && i <= 11 && j >= 7 && j <= 11 ? pit : block.vertices).push_back(at(i, j));
        CHECK(region_holes(block, grid, topology) == pit);
        ConstraintSet closed = block;
        CHECK(close_region_holes(closed, grid, topology) == 25);
        CHECK(closed.vertices.size() == 256);
        CHECK(std::is_sorted(closed.vertices.begin(), closed.vertices.end()));
        // A band across the middle leaves out both ends (each larger than a quarter of it).
        ConstraintSet band;
        for (int j = 9; j <= 10; ++j)
            for (int i = 0; i < 20; ++i)
                band.vertices.push_back(at(i, j));
        CHECK(region_holes(band, grid, topology).empty());
        // Everything but a patch: the patch is the rest of that component, kept out (but for
        // its four corners, which one ring closes).
        ConstraintSet most;
        for (int j = 0; j < 20; ++j)
            for (int i = 0; i < 20; ++i)
                if (!(i >= 7 && i <= 11 && j >= 7 && j <= 11))
                    most.vertices.push_back(at(i, j));
        CHECK(region_holes(most, grid, topology) ==
              std::vector<Index>{at(7, 7), at(11, 7), at(7, 11), at(11, 11)});
        // A region of faces takes the faces around its pit.
        ConstraintSet faces;
        for (Index f = 0; f < 19 * 19; ++f)
        {
            const int i = static_cast<int>(f % 19), j = static_cast<int>(f / 19);
            if (i >= 2 && i <= 16 && j >= 2 && j <= 16 && !(i >= 6 && i <= 11 && j >= 6 && j <= 11))
                faces.faces.push_back(f);
        }
        CHECK(region_holes(faces, grid, topology).size() == 25);
        CHECK(close_region_holes(faces, grid, topology) == 25);
        CHECK(faces.faces.size() == 15 * 15);
    }

    TEST_CASE("the border ring is one unbroken line where a region meets the fixed rest")
    {
        // A diamond-ish region on a triangulated grid: ring vertices joined only through
        // faces, never an edge, at its slanted sides.
        Mesh grid = test::open_grid(12, 12);
        Mesh triangles;
        triangles.positions = grid.positions;
        for (Index f = 0; f < grid.face_count(); ++f)
        {
            const std::span<const Index> q = grid.face(f);
            triangles.add_face(std::vector<Index>{q[0], q[1], q[2]});
            triangles.add_face(std::vector<Index>{q[0], q[2], q[3]});
        }
        Document d = make_document(triangles, "diamond.obj");
        ConstraintSet region;
        region.kind = ConstraintKind::Region;
        for (int j = 0; j <= 12; ++j)
            for (int i = 0; i <= 12; ++i)
                if (std::abs(i - 6) + std::abs(j - 6) <= 4)
                    region.vertices.push_back(static_cast<Index>(j * 13 + i));
        d.sets.push_back(region);
        const RegionBorder border = region_border(d);
        REQUIRE(!border.crossings.empty());
        REQUIRE(border.crossings.size() % 4 == 0);
        // Each crossing edge (an end inside, an end outside) is the end of exactly two
        // segments: the line closes on itself without a gap.
        std::map<std::pair<Index, Index>, int> ends;
        for (size_t k = 0; k < border.crossings.size(); k += 2)
        {
            const Index a = border.crossings[k], b = border.crossings[k + 1];
            ++ends[{std::min(a, b), std::max(a, b)}];
        }
        for (const auto& [edge, count] : ends)
            CHECK(count == 2);
        // And every edge that crosses is on it.
        size_t crossing_edges = 0;
        std::vector<char> in(static_cast<size_t>(d.mesh.vertex_count()), 0);
        for (const Index v : region.vertices)
            in[static_cast<size_t>(v)] = 1;
        for (Index e = 0; e < d.topology.edge_count(); ++e)
            crossing_edges += in[static_cast<size_t>(d.topology.edge_vertices[2 * e])] !=
                              in[static_cast<size_t>(d.topology.edge_vertices[2 * e + 1])];
        CHECK(ends.size() == crossing_edges);
    }

    TEST_CASE("a region made from a selection closes its holes, says how many, in one undo step")
    {
        const fs::path dir = test::temp_dir();
        io::write_mesh(test::open_grid(6, 6), (dir / "grid.obj").string());
        Editor e(dir / "grid.obj");
        e.session.dispatch(cmd::RunSelection{SelectionCommand::All});
        e.session.dispatch(cmd::ApplySelection{ElementKind::Vertices, SelectOp::Subtract, {24}});
        const size_t steps = e.session.history().undo_count();
        e.key("shift+r"); // the key's region, as the panel's button makes it
        REQUIRE(e.doc().sets.size() == 1);
        CHECK(e.doc().sets[0].vertices.size() == 49);
        CHECK(e.session.state().message.find("48 vertices selected and 1 enclosed vertices") !=
              std::string::npos);
        CHECK(e.session.history().undo_count() == steps + 1);
        e.key("ctrl+z");
        CHECK(e.doc().sets.empty());
        // Asked not to (a script's "close_holes": false), it keeps the selection as it is.
        REQUIRE(e.session.dispatch(cmd::CreateSet{ConstraintKind::Region, "r", false}));
        CHECK(e.doc().sets[0].vertices.size() == 48);
    }

    TEST_CASE("a region that leaves out what it encloses says so, and closes its holes")
    {
        const fs::path dir = test::temp_dir();
        io::write_mesh(test::open_grid(6, 6), (dir / "grid.obj").string());
        Editor e(dir / "grid.obj");
        e.session.dispatch(cmd::RunSelection{SelectionCommand::All});
        // Vertex 3 + 3 * 7 = 24 sits inside the grid, as a vertex hidden in a pit does.
        e.session.dispatch(cmd::ApplySelection{ElementKind::Vertices, SelectOp::Subtract, {24}});
        // (Made without closing its holes: an older file's, or a script's "close_holes": false.)
        REQUIRE(e.session.dispatch(cmd::CreateSet{ConstraintKind::Region, {}, false}));
        e.run();
        REQUIRE(e.session.state().region_holes.size() == 1);
        CHECK(e.session.state().region_holes[0].second == 1);
        CHECK(std::any_of(e.session.state().notes.begin(), e.session.state().notes.end(),
                          [](const std::string& n) {
                              return n.find("leaves out 1 vertices it encloses") !=
                                     std::string::npos;
                          }));
        e.click_widget("sets/region 1/close holes");
        CHECK(e.doc().sets[0].vertices.size() == 49);
        CHECK(e.session.state().region_holes.empty());
        e.key("ctrl+z");
        CHECK(e.doc().sets[0].vertices.size() == 48);
    }
}

TEST_SUITE("Editor scripts")
{
    // A script's host without GL: the same frames as the window's, through the Editor above.
    struct TestHost final : ScriptHost
    {
        Editor& e;
        explicit TestHost(Editor& editor) : e(editor) {}
        void run_frame() override { e.run(); }
        EditorFrame& frame_driver() override { return e.frame; }
        void screenshot(const std::string& path) override
        {
            write_png(e.renderer.read_pixels(kWidth, kHeight), path);
        }
    };

    TEST_CASE("a script's keys, drags and widget clicks take a person's path")
    {
        const fs::path mesh = bunny_copy();
        Editor e(mesh);
        TestHost host(e);
        const Script script = parse_script(R"({"actions": [
            {"key": "r"}, {"drag": [[300, 250], [420, 330]]},
            {"click_widget": "Grow"}, {"key": "shift+r"},
            {"click_widget": "sets/region 1/rename"}, {"key": "ctrl+a"}, {"type": "cheek"},
            {"key": "enter"},
            {"solver": {"steps_per_run": 7}}, {"click_widget": "Play"}, {"frames": 3},
            {"key": "ctrl+s"}]})",
                                           "person.json");
        play_script(script, e.session, host);
        while (e.session.playing())
            e.session.take_frame();
        REQUIRE(e.doc().sets.size() == 1);
        CHECK(e.doc().sets[0].name == "cheek");
        CHECK(e.session.tool() == ToolKind::Rectangle);
        CHECK(e.doc().steps_from_base == 7);
        CHECK(e.session.history().undo_label() == "solve 7 steps");
        // A widget that is not on screen names what is.
        const Script missing = parse_script(R"([{"click_widget": "Launch"}])", "m.json");
        CHECK_THROWS_WITH_AS(play_script(missing, e.session, host),
                             doctest::Contains("'m.json': actions[0]: no widget 'Launch'"),
                             InvalidInputError);
    }

    TEST_CASE("a run the recipe does not fit ends at once: the script stops with the reason")
    {
        const fs::path mesh = bunny_copy();
        Editor e(mesh);
        TestHost host(e);
        // fair-region on the whole mesh: nothing holds the thin plate (the direct method
        // refuses it). Play ends instead of waiting for frames that never come.
        const Script script =
            parse_script(R"([{"preset": "fair-region"}, {"play": 3}])", "refused.json");
        CHECK_THROWS_WITH_AS(play_script(script, e.session, host),
                             doctest::Contains("'refused.json': actions[1]: cannot solve: "),
                             InvalidInputError);
        CHECK(!e.session.playing());
        CHECK(e.doc().steps_from_base == 0);
        CHECK(e.session.state().message_is_error);
        CAPTURE(e.session.state().message);
        CHECK(e.session.state().message.find("is held by nothing") != std::string::npos);
        CHECK(e.session.history().undo_label() == "preset"); // no empty run recorded
    }

    TEST_CASE(
        "a preset runs its own steps, the strength takes the iterations from the noise "
        "and a count puts them back")
    {
        const fs::path mesh = bunny_copy();
        Editor e(mesh);
        TestHost host(e);
        play_script(parse_script(R"([{"noise": 0.3, "seed": 2}, {"preset": "denoise-organic"},
                                     {"solver": {"strength": 2}}, {"click_widget": "Play"}])",
                                 "organic.json"),
                    e.session, host);
        while (e.session.playing())
            e.session.take_frame();
        const SolverSettings& s = e.doc().solver;
        REQUIRE(s.adaptive_smoothing);
        CHECK(s.adaptive_smoothing->strength == 2);
        CHECK(s.adaptive_smoothing->per_noise == 50); // the preset's rate
        CHECK(s.steps_per_run == 12);                 // the preset's own iterations
        CHECK(e.doc().steps_from_base == 12);
        // The run says what it found, at the strength given.
        const auto& notes = e.session.state().run_notes;
        const auto found = std::find_if(notes.begin(), notes.end(), [](const std::string& n) {
            return n.rfind("normal smoothing: noise of ", 0) == 0;
        });
        REQUIRE(found != notes.end());
        CHECK(found->find("(strength 2)") != std::string::npos);
        // A count replaces the iterations from the noise.
        play_script(parse_script(R"([{"solver": {"normal_smoothing_iterations": 5}}])", "n.json"),
                    e.session, host);
        CHECK(!e.doc().solver.adaptive_smoothing);
        CHECK(e.doc().solver.normal_smoothing_iterations == 5);
    }
}
