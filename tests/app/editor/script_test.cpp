// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Scripted sessions through the meshfair executable: tool strokes, undo and redo, and
// screenshots compared with golden images; scripts that are refused, and why.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "app/editor/editor_session.h"
#include "app/editor/offscreen.h"
#include "app/editor/script.h"
#include "app/render/gl_renderer.h"
#include "app/render/image.h"
#include "core/errors.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/topology/vertex_order.h"
#include "tests/app/render/render_support.h"
#include "tests/helpers.h"

using namespace meshfair;
namespace fs = std::filesystem;

namespace {

// Plays `script` (JSON text) on the bunny offscreen; returns the run and the screenshot.
test::CommandRun play(const std::string& script, const fs::path& png,
                      const std::string& options = "--size 480x360",
                      const fs::path& mesh = test::assets_dir() / "bunny.obj")
{
    const fs::path path = png.parent_path() / (png.stem().string() + ".json");
    test::write_bytes(path, script);
    return test::run_command(
        "env -u DISPLAY GALLIUM_DRIVER=llvmpipe " + test::shell_quote(MESHFAIR_EDITOR) +
        " --offscreen " + test::shell_quote(mesh.string()) + " " + options + " --script " +
        test::shell_quote(path.string()) + " --screenshot " + test::shell_quote(png.string()));
}

// A stroke across the bunny's flank; a zoom onto its haunch and a lasso there (480 x 360).
const char* kBrushStroke =
    R"({"tool": "brush"}, {"brush_radius": 14},
       {"drag": [[190, 170], [230, 185], [270, 200], [300, 230], [310, 260]]})";
const char* kLassoFaces =
    R"({"scroll": 6, "at": [280, 240]}, {"tool": "lasso"}, {"elements": "faces"},
       {"drag": [[200, 170], [300, 140], [370, 200], [340, 290], [250, 300], [230, 240]]})";
// The same lasso without the zoom (the camera is not part of the history).
const char* kLassoInPlace =
    R"({"tool": "lasso"}, {"elements": "faces"},
       {"drag": [[200, 170], [300, 140], [370, 200], [340, 290], [250, 300], [230, 240]]})";

// A script of tests/app/editor/scripts/ with @OUT@ replaced by `out`.
std::string script_file(const std::string& name, const fs::path& out)
{
    std::string text = io::read_file((fs::path(MESHFAIR_TEST_SCRIPTS) / name).string());
    for (size_t at; (at = text.find("@OUT@")) != std::string::npos;)
        text.replace(at, 5, out.string());
    return text;
}

} // namespace

TEST_SUITE("Scripted sessions")
{
    TEST_CASE("the glyphs of every constraint kind, and a region's border ring")
    {
        const fs::path dir = test::temp_dir();
        const test::CommandRun run = play(script_file("constraint_glyphs.json", dir),
                                          dir / "glyphs.png", "--size 560x420 --mode flat");
        REQUIRE_MESSAGE(run.code == 0, run.err);
        test::check_golden("script_constraint_glyphs",
                           app::read_png((dir / "glyphs.png").string()));
    }

    TEST_CASE("a noisy bunny's flank before and after smoothing it as a region")
    {
        const fs::path dir = test::temp_dir();
        const test::CommandRun run = play(script_file("region_smoothing.json", dir),
                                          dir / "end.png", "--size 560x420 --mode flat");
        REQUIRE_MESSAGE(run.code == 0, run.err);
        test::check_golden("script_region_before",
                           app::read_png((dir / "region_before.png").string()));
        test::check_golden("script_region_after",
                           app::read_png((dir / "region_after.png").string()));
    }

    TEST_CASE("crash recovery: a session killed mid-run is restored as it was autosaved")
    {
        const fs::path dir = test::temp_dir();
        const fs::path state = dir / "state";
        const fs::path script = dir / "first.json";
        test::write_bytes(script, script_file("crash_first_run.json", dir));
        const std::string editor = "env -u DISPLAY GALLIUM_DRIVER=llvmpipe XDG_STATE_HOME=" +
                                   test::shell_quote(state.string()) + " " +
                                   test::shell_quote(MESHFAIR_EDITOR) + " --offscreen " +
                                   test::shell_quote((test::assets_dir() / "bunny.obj").string()) +
                                   " --size 560x420";
        // The first run autosaves, then plays "forever" until it is killed: once its trace
        // says the run has begun (after the autosave, which wrote the recovery files), and
        // the recovery's state.json is there.
        const fs::path trace = dir / "first.trace";
        const test::CommandRun killed = test::run_command(
            editor + " --trace --script " + test::shell_quote(script.string()) + " --screenshot " +
            test::shell_quote((dir / "never.png").string()) + " >" +
            test::shell_quote(trace.string()) + " & pid=$!; for i in $(seq 1200); do grep -qs " +
            "'^command play: ok' " + test::shell_quote(trace.string()) + " && ls " +
            test::shell_quote(state.string()) +
            "/meshfair/recovery/*/state.json >/dev/null 2>&1 && break; sleep 0.05; done; "
            "kill -9 $pid; wait $pid; echo \"exit $?\"");
        REQUIRE_MESSAGE(killed.out.find("exit 137") != std::string::npos, killed.out << killed.err);
        // Killed mid-run: the run had begun, after the autosave.
        const std::string traced = io::read_file(trace.string());
        REQUIRE_MESSAGE(traced.find("command play: ok") != std::string::npos, traced);
        CHECK(traced.find("command autosave") < traced.find("command play: ok"));
        CHECK_FALSE(fs::exists(dir / "never.png"));

        // The second run recovers, saves the mesh and exports the recipe.
        const fs::path recovered = dir / "recovered.obj", again = dir / "again.json";
        test::write_bytes(dir / "second.json",
                          R"([{"recover": true}, {"save_mesh": ")" + recovered.string() +
                              R"("}, {"export_recipe": ")" + again.string() + R"("}])");
        const test::CommandRun second = test::run_command(
            editor + " --script " + test::shell_quote((dir / "second.json").string()) +
            " --screenshot " + test::shell_quote((dir / "second.png").string()));
        REQUIRE_MESSAGE(second.code == 0, second.err);
        // The same sets and steps as at the autosave, and the shape the command line gives
        // for them: the state was restored exactly.
        CHECK(io::read_file(again.string()) == io::read_file((dir / "recipe.json").string()));
        const fs::path cli = dir / "cli.obj";
        const test::CommandRun smooth =
            test::run_command(test::shell_quote(MESHFAIR_CLI) + " smooth " +
                              test::shell_quote((test::assets_dir() / "bunny.obj").string()) +
                              " -o " + test::shell_quote(cli.string()) + " --recipe " +
                              test::shell_quote((dir / "recipe.json").string()) + " --quiet");
        REQUIRE(smooth.code == 0);
        CHECK(io::read_mesh(recovered.string()).positions == io::read_mesh(cli.string()).positions);
        // A clean exit removes the files: nothing is offered a third time.
        const test::CommandRun third = test::run_command(
            editor + " --script " + test::shell_quote((dir / "second.json").string()) +
            " --screenshot " + test::shell_quote((dir / "third.png").string()));
        CHECK(third.code == 2);
        CHECK(third.err.find("no recovery files") != std::string::npos);
    }

    TEST_CASE("the heat map: each vertex coloured by its share of the energy")
    {
        const fs::path dir = test::temp_dir();
        const test::CommandRun run =
            play(script_file("heat_map.json", dir), dir / "heat.png", "--size 560x420 --mode flat");
        REQUIRE_MESSAGE(run.code == 0, run.err);
        test::check_golden("script_heat_map", app::read_png((dir / "heat.png").string()));
    }

    TEST_CASE("the energy plot and the panels after live solving, rendered in process")
    {
        // In process, so that the renderer's name shown is "llvmpipe" without the LLVM
        // version of the machine (as for the other interface goldens).
        test::offscreen_context(1280, 800);
        app::GlRenderer renderer;
        app::EditorSession session(app::load_document((test::assets_dir() / "bunny.obj").string()),
                                   renderer);
        session.state().offscreen = true;
        session.state().renderer_name = "llvmpipe";
        app::OffscreenHost host(session, 1280, 800, true);
        host.run_frame();
        session.camera().frame(session.document().box, session.aspect());
        const app::Script script = app::parse_script(
            R"([{"noise": 0.3, "seed": 5}, {"tool": "rectangle"}, {"elements": "faces"},
                {"drag": [[430, 250], [700, 520]]}, {"create_set": "region", "name": "flank"},
                {"drag": [[520, 330], [560, 370]]}, {"create_set": "centroid"},
                {"select": "clear"},
                {"solver": {"iterations_per_frame": 5, "centroid_mu": 4}}, {"play": 12}])",
            "energy.json");
        app::play_script(script, session, host);
        CHECK(session.document().steps_from_base == 60);
        const std::vector<app::EnergySample> e = session.energies();
        REQUIRE(e.size() == 13);
        CHECK(e.back().energy.total() < e.front().energy.total());
        // The plot's points come from the steps' sweeps (each the energy of the positions
        // a step starts from), and the run's end adds the shape shown: step counts rising,
        // energies falling, and the last point the energy of the positions at step 60.
        for (size_t k = 1; k < e.size(); ++k)
        {
            CHECK(e[k].step > e[k - 1].step);
            CHECK(e[k].energy.total() <= e[k - 1].energy.total());
        }
        CHECK(e.back().step == 60);
        const fs::path dir = test::temp_dir();
        REQUIRE(session.dispatch(app::cmd::ExportRecipe{(dir / "plot.json").string()}));
        const app::Document& doc = session.document();
        Mesh base = doc.mesh; // the start of the run, in the file's numbering: the targets
        base.positions = doc.base_positions;
        base = reorder_mesh(base, inverse_order(doc.order));
        const Recipe recipe = read_recipe((dir / "plot.json").string());
        const Topology topology = build_topology(base, required_topology(recipe));
        const Session check(base, topology, recipe);
        const Scalar now = check.energy(file_order_mesh(doc).positions).total();
        CHECK(std::abs(e.back().energy.total() - now) <= 1e-12 * now);
        test::check_golden("ui_energy_plot", host.frame());
    }

    TEST_CASE("a brush stroke's vertices, then a lasso's faces, as golden images")
    {
        const fs::path dir = test::temp_dir();
        const fs::path brush = dir / "brush.png", lasso = dir / "lasso.png";
        const test::CommandRun a =
            play(std::string("[") + kBrushStroke + "]", brush, "--size 480x360 --mode flat");
        REQUIRE_MESSAGE(a.code == 0, a.err);
        test::check_golden("script_brush_selection", app::read_png(brush.string()));
        const test::CommandRun b =
            play(std::string("[") + kLassoFaces + "]", lasso, "--size 480x360 --mode flat,wire");
        REQUIRE_MESSAGE(b.code == 0, b.err);
        test::check_golden("script_lasso_faces", app::read_png(lasso.string()));
    }

    TEST_CASE("undo returns the frame of the untouched mesh, redo the frame after the stroke")
    {
        const fs::path dir = test::temp_dir();
        REQUIRE(play("[]", dir / "plain.png").code == 0);
        REQUIRE(play(std::string("[") + kBrushStroke + "]", dir / "stroke.png").code == 0);
        REQUIRE(play(std::string("[") + kBrushStroke + "," + kLassoInPlace + R"(, {"undo": 2}])",
                     dir / "undone.png")
                    .code == 0);
        REQUIRE(play(std::string("[") + kBrushStroke + "," + kLassoInPlace +
                         R"(, {"undo": 2}, {"redo": 1}])",
                     dir / "redone.png")
                    .code == 0);
        const std::string plain = io::read_file((dir / "plain.png").string());
        const std::string stroke = io::read_file((dir / "stroke.png").string());
        CHECK(plain != stroke); // the stroke shows
        CHECK(io::read_file((dir / "undone.png").string()) == plain);
        CHECK(io::read_file((dir / "redone.png").string()) == stroke);
    }

    TEST_CASE("a screenshot and a saved mesh in the middle of a script")
    {
        const fs::path dir = test::temp_dir();
        const fs::path mid = dir / "mid.png", saved = dir / "saved.off";
        const std::string script = std::string("[") + kBrushStroke + R"(, {"screenshot": ")" +
                                   mid.string() + R"("}, {"select": "clear"}, {"save_mesh": ")" +
                                   saved.string() + R"("}])";
        REQUIRE(play(script, dir / "end.png").code == 0);
        REQUIRE(play(std::string("[") + kBrushStroke + "]", dir / "stroke.png").code == 0);
        CHECK(io::read_file(mid.string()) == io::read_file((dir / "stroke.png").string()));
        const Mesh bunny = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        const Mesh copy = io::read_mesh(saved.string());
        CHECK(copy.positions == bunny.positions);
        CHECK(copy.face_count() == bunny.face_count());
    }

    TEST_CASE("the editor's save keeps the file's texture coordinates, colours and groups")
    {
        // A quad grid with a texture seam, vertex colours, normals, a group and a material.
        const fs::path dir = test::temp_dir();
        std::string obj = "mtllib grid.mtl\n";
        const Mesh grid = test::open_grid(6, 4);
        for (Index v = 0; v < grid.vertex_count(); ++v)
            obj += "v " + std::to_string(grid.position(v)[0]) + " " +
                   std::to_string(grid.position(v)[1]) + " " + std::to_string(0.2 * (v % 3)) +
                   " 0.25 0.5 " + std::to_string(v / 40.0) + "\n";
        for (Index f = 0; f < grid.face_count(); ++f)
            for (int k = 0; k < 4; ++k)
                obj += "vt " + std::to_string(f / 24.0) + " " + std::to_string(k / 4.0) + "\n";
        obj += "vn 0 0 1\ng sheet\nusemtl cloth\n";
        for (Index f = 0; f < grid.face_count(); ++f)
        {
            obj += "f";
            for (int k = 0; k < 4; ++k)
                obj += " " + std::to_string(grid.face(f)[static_cast<size_t>(k)] + 1) + "/" +
                       std::to_string(4 * f + k + 1) + "/1";
            obj += "\n";
        }
        const fs::path in = dir / "sheet.obj", saved = dir / "saved.obj", ply = dir / "saved.ply";
        test::write_bytes(in, obj);
        const test::CommandRun run = play(R"([{"step": 5}, {"save_mesh": ")" + saved.string() +
                                              R"("}, {"save_mesh": ")" + ply.string() + R"("}])",
                                          dir / "sheet.png", "--size 320x240", in);
        REQUIRE(run.code == 0);
        io::MeshAttributes before, after, as_ply;
        const Mesh original = io::read_mesh(in.string(), nullptr, &before);
        const Mesh copy = io::read_mesh(saved.string(), nullptr, &after);
        const Mesh ply_copy = io::read_mesh(ply.string(), nullptr, &as_ply);
        CHECK(copy.positions != original.positions); // smoothed
        CHECK(copy.face_vertices == original.face_vertices);
        CHECK(after.texcoords == before.texcoords);
        CHECK(after.vertex == before.vertex);
        CHECK(after.statements == before.statements);
        io::MeshAttributes renewed = before;
        io::recompute_normals(copy, renewed);
        CHECK(after.normals == renewed.normals); // of the saved shape
        CHECK(as_ply.vertex.find("red") != nullptr);
        // What PLY cannot hold is said where the editor reports (its status line).
        CHECK(run.err.find("PLY cannot hold the OBJ groups, objects, smoothing groups and "
                           "materials 'mtllib grid.mtl', 'g sheet', 'usemtl cloth'") !=
              std::string::npos);
    }

    TEST_CASE("scripts are refused with the file and the action named, before anything runs")
    {
        using app::parse_script;
        const auto message = [](const std::string& text) {
            try
            {
                parse_script(text, "s.json");
            }
            catch (const InvalidInputError& e)
            {
                return std::string(e.what());
            }
            return std::string("accepted");
        };
        CHECK(message(R"({"actions": [{"tool": "brush"}, {"tool": "spray"}]})") ==
              "'s.json': actions[1].tool: 'spray' is not navigate, click, brush, rectangle, "
              "lasso, move_pins, aim_normals or paint");
        CHECK(message(R"([{"paint": {"radius": 0.1, "dabs": [[0, 0]]}}])") ==
              "'s.json': actions[0].paint.dabs[0]: must be [x, y, z]");
        CHECK(message(R"([{"paint": {"radius": 0.1, "mode": "spray", "dabs": [[0, 0, 0]]}}])") ==
              "'s.json': actions[0].paint.mode: must be \"relax\", \"add\", \"subtract\" or "
              "\"smooth\"");
        CHECK(message(R"([{"paint": {"dabs": [[0, 0, 0]]}}])") ==
              "'s.json': actions[0].paint: needs 'radius' and 'dabs': a list of centres [x, y, z]");
        CHECK(message(R"([{"paint_settings": {"strength": 2}}])") ==
              "'s.json': actions[0].paint_settings.strength: must be in [0, 1] (got 2)");
        CHECK(message(R"([{"paint_settings": {"size": 2}}])") ==
              "'s.json': actions[0].paint_settings.size: is not a key of 'paint_settings'");
        CHECK(message("[{\"drag\": [[1, 2]]}]") ==
              "'s.json': actions[0].drag: must be a list of at least 2 points [x, y]");
        CHECK(message("[{\"click\": [1, 2], \"undo\": 1}]") ==
              "'s.json': actions[0]: has two actions ('click' and 'undo')");
        CHECK(message("[{\"undo\": 0}]") ==
              "'s.json': actions[0].undo: must be an integer in [1, 100000] (got 0)");
        CHECK(message(R"([{"solver": {"iterations_per_frame": 2.5}}])") ==
              "'s.json': actions[0].solver.iterations_per_frame: must be an integer (got 2.5)");
        CHECK(message(R"([{"paint_settings": {"steps": 3.0}}])") ==
              "'s.json': actions[0].paint_settings.steps: must be an integer (got 3.0)");
        CHECK(message("[{\"select\": \"grow\", \"modifiers\": [\"shift\"]}]") ==
              "'s.json': actions[0].modifiers: only drag, click or click_widget takes 'modifiers'");
        CHECK(message("[{\"drag\": [[0, 0], [1, 1]], \"modifiers\": [\"hyper\"]}]") ==
              "'s.json': actions[0].modifiers: 'hyper' is not shift, ctrl or alt");
        CHECK(message("[{\"scroll\": 2}]") ==
              "'s.json': actions[0].scroll: needs 'at': the "
              "cursor [x, y]");
        CHECK(message("[{\"click\": [1e300, 2]}]")
                  .find("actions[0].click[0]: must be in [-1000000, 1000000] (got 1e+300)") !=
              std::string::npos);
        CHECK(message("{\"steps\": []}") == "'s.json': steps: unknown key (allowed here: actions)");
        CHECK(message("[3]") == "'s.json': actions[0]: an action must be a JSON object");
        CHECK(message("[{}]") == "'s.json': actions[0]: names no action");
        CHECK(message("[\n{\"tool\": \"brush\"},\n{\"tool\" \"x\"}]") ==
              "'s.json':3:11: not valid JSON: syntax error while parsing object separator - "
              "unexpected string literal; expected ':'");
        CHECK(message(R"([{"solver": {"bilateral": {"sigma_r": 0}}}])") ==
              "'s.json': actions[0].solver.bilateral.sigma_r: must be > 0 (got 0)");
        CHECK(message(R"([{"solver": {"method": "newton"}}])") ==
              "'s.json': actions[0].solver.method: must be \"jacobi\", \"taubin\", \"direct\", "
              "\"cg\" or \"implicit\"");
        CHECK(message(R"([{"solver": {"method": "taubin", "keep_volume": true, "bilateral": {},
                          "falloff": {"radius": 4, "curve": "sphere"}}}])") == "accepted");
        CHECK(message(R"([{"view": "front"}, {"projection": "orthographic"}, {"scroll": 1,
                          "at": [3, 4]}, {"select": "connected"}, {"elements": "faces"},
                          {"through": true}, {"brush_radius": 3}])") == "accepted");
    }

    TEST_CASE("the executable: exit code 2 for a bad script, 3 for an output it cannot write")
    {
        const fs::path dir = test::temp_dir();
        const test::CommandRun bad = play("[{\"tool\": \"spray\"}]", dir / "bad.png");
        CHECK(bad.code == 2);
        CHECK(bad.err.find("bad.json': actions[0].tool") != std::string::npos);
        CHECK_FALSE(fs::exists(dir / "bad.png"));
        const test::CommandRun unwritable =
            play(R"([{"save_mesh": "/nonexistent/dir/x.obj"}])", dir / "unwritable.png");
        CHECK(unwritable.code == 3);
        CHECK(unwritable.err.find("actions[0]") != std::string::npos);
        const test::CommandRun window = test::run_command(
            "env -u DISPLAY " + test::shell_quote(MESHFAIR_EDITOR) + " --script x.json");
        CHECK(window.code == 2);
        CHECK(window.err.find("--script needs --offscreen") != std::string::npos);
    }
}
