// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// The meshfair executable as a script or a newcomer runs it: offscreen frames, the
// fallback without a display, saved views, exit codes and messages, files kept whole.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/editor/offscreen.h"
#include "app/render/image.h"
#include "core/io/io.h"
#include "tests/helpers.h"

using namespace meshfair;
namespace fs = std::filesystem;

namespace {

using Run = test::CommandRun;

// Runs meshfair with `args` (already quoted), without a display unless `env` says more.
Run editor(const std::string& args, const std::string& env = "env -u DISPLAY")
{
    return test::run_command(env + " GALLIUM_DRIVER=llvmpipe " +
                             test::shell_quote(MESHFAIR_EDITOR) + " " + args);
}

std::string bunny_argument()
{
    return test::shell_quote((test::assets_dir() / "bunny.obj").string());
}

} // namespace

TEST_SUITE("meshfair")
{
    TEST_CASE("an offscreen frame is written, the same bytes every time")
    {
        const fs::path dir = test::temp_dir();
        const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string();
        const std::string common =
            "--offscreen " + bunny_argument() + " --size 320x200 --mode flat,wire";
        REQUIRE(editor(common + " --screenshot " + test::shell_quote(a)).code == 0);
        REQUIRE(editor(common + " --screenshot " + test::shell_quote(b)).code == 0);
        CHECK(io::read_file(a) == io::read_file(b));
        const app::Image image = app::read_png(a);
        CHECK(image.width == 320);
        CHECK(image.height == 200);
    }

    TEST_CASE("a saved view gives the same frame when loaded")
    {
        const fs::path dir = test::temp_dir();
        const std::string view = (dir / "view.json").string();
        const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string();
        REQUIRE(editor("--offscreen " + bunny_argument() + " --size 300x300 --screenshot " +
                       test::shell_quote(a) + " --save-view " + test::shell_quote(view))
                    .code == 0);
        REQUIRE(editor("--offscreen " + bunny_argument() + " --size 300x300 --screenshot " +
                       test::shell_quote(b) + " --view " + test::shell_quote(view))
                    .code == 0);
        CHECK(io::read_file(a) == io::read_file(b));
    }

    TEST_CASE("--beside draws a second mesh to the right, seen by the first one's camera")
    {
        // The noisy bunny beside the bunny: the left half must be the noisy bunny's own
        // frame and the right half the bunny's frame from the noisy one's camera, pixel for
        // pixel.
        const fs::path dir = test::temp_dir();
        const std::string noisy = (dir / "noisy.obj").string(), view = (dir / "v.json").string();
        const std::string pair = (dir / "pair.png").string(), left = (dir / "l.png").string(),
                          right = (dir / "r.png").string();
        REQUIRE(test::run_command(test::shell_quote(MESHFAIR_CLI) + " noise " + bunny_argument() +
                                  " -o " + test::shell_quote(noisy) + " --sigma 0.5 --seed 3")
                    .code == 0);
        const std::string size = " --size 240x180 --offscreen ";
        REQUIRE(editor(test::shell_quote(noisy) + size + "--screenshot " + test::shell_quote(pair) +
                       " --beside " + bunny_argument())
                    .code == 0);
        REQUIRE(editor(test::shell_quote(noisy) + size + "--screenshot " + test::shell_quote(left) +
                       " --save-view " + test::shell_quote(view))
                    .code == 0);
        REQUIRE(editor(bunny_argument() + size + "--screenshot " + test::shell_quote(right) +
                       " --view " + test::shell_quote(view))
                    .code == 0);
        const app::Image both = app::read_png(pair), a = app::read_png(left),
                         b = app::read_png(right);
        REQUIRE(both.width == 480);
        REQUIRE(both.height == 180);
        CHECK(both.rgba == app::side_by_side(a, b).rgba);
        CHECK(a.rgba != b.rgba); // the two meshes differ on screen

        // A bad second mesh is refused before anything is drawn or written.
        const fs::path bad = dir / "bad.obj";
        test::write_bytes(bad, "v 0 0 0\nf 1 2 3\n");
        test::write_bytes(pair, "the previous picture");
        const Run r =
            editor(test::shell_quote(noisy) + size + "--screenshot " + test::shell_quote(pair) +
                   " --beside " + test::shell_quote(bad.string()));
        CHECK(r.code == 2);
        CHECK(r.err == "meshfair: " + bad.string() +
                           ":2:7: vertex index 3 is past the last vertex (the file defines 1)\n");
        CHECK(io::read_file(pair) == "the previous picture");
        CHECK(editor(bunny_argument() + " --beside " + bunny_argument()).code == 2);
    }

    TEST_CASE("without a display the editor says so and renders the screenshot instead")
    {
        const fs::path dir = test::temp_dir();
        const std::string shot = (dir / "shot.png").string();
        const Run r =
            editor(bunny_argument() + " --size 200x160 --screenshot " + test::shell_quote(shot));
        CHECK(r.code == 0);
        CHECK(r.err.find("meshfair: no display") == 0);
        CHECK(r.err.find("rendering offscreen to " + shot + " instead") != std::string::npos);
        CHECK(app::read_png(shot).width == 200);
    }

    TEST_CASE("bad input is refused with exit code 2, naming the file and the place")
    {
        const fs::path dir = test::temp_dir();
        const std::string shot = (dir / "shot.png").string();
        const fs::path bad_mesh = dir / "bad.obj";
        test::write_bytes(bad_mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
        test::write_bytes(shot, "the previous screenshot");
        Run r = editor("--offscreen " + test::shell_quote(bad_mesh.string()) + " --screenshot " +
                       test::shell_quote(shot));
        CHECK(r.code == 2);
        CHECK(r.err == "meshfair: " + bad_mesh.string() +
                           ":4:7: vertex index 9 is past the last vertex (the file defines 3)\n");
        CHECK(io::read_file(shot) == "the previous screenshot"); // nothing half-written

        const fs::path bad_view = dir / "view.json";
        test::write_bytes(bad_view, "{\"distance\": 0}");
        r = editor("--offscreen " + bunny_argument() + " --view " +
                   test::shell_quote(bad_view.string()) + " --screenshot " +
                   test::shell_quote(shot));
        CHECK(r.code == 2);
        CHECK(r.err ==
              "meshfair: '" + bad_view.string() + "': view field 'distance' must be positive\n");

        r = editor("--offscreen " + bunny_argument() + " --mode sketchy --screenshot " +
                   test::shell_quote(shot));
        CHECK(r.code == 2);
        CHECK(r.err.find("unknown mode 'sketchy'") != std::string::npos);
        r = editor("--offscreen " + bunny_argument() + " --size 12x4000 --screenshot " +
                   test::shell_quote(shot));
        CHECK(r.code == 2);
        CHECK(r.err.find("'12x4000' is not WxH") != std::string::npos);
        r = editor("--offscreen " + bunny_argument());
        CHECK(r.code == 2);
        CHECK(r.err == "meshfair: --offscreen needs --screenshot OUT.png\n");
        r = editor("--offscreen " + test::shell_quote((dir / "missing.obj").string()) +
                   " --screenshot " + test::shell_quote(shot));
        CHECK(r.code == 2);
        CHECK(r.err.find("missing.obj': cannot open") != std::string::npos);
        CHECK(io::read_file(shot) == "the previous screenshot");
    }

    TEST_CASE("a screenshot that cannot be written exits with code 3")
    {
        const fs::path dir = test::temp_dir();
        const Run r = editor("--offscreen " + bunny_argument() + " --size 64x64 --screenshot " +
                             test::shell_quote((dir / "no" / "such" / "dir.png").string()));
        CHECK(r.code == 3);
        CHECK(r.err.find("dir.png': cannot create a temporary file beside it") !=
              std::string::npos);
    }
}
