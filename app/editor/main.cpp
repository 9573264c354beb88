// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair: the editor. A window (GLFW, OpenGL 3.3 core, Dear ImGui) by default; with
// --offscreen, or where there is no display, one frame rendered through OSMesa to a PNG.
// Exit codes as meshfair-cli's: 0 ok, 2 bad usage or input, 3 could not write an output,
// 1 internal error (no usable OpenGL included).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "app/editor/offscreen.h"
#include "app/editor/window.h"
#include "app/render/render_error.h"
#include "core/errors.h"
#include "core/parallel/parallel.h"

namespace {

using namespace meshfair;
using namespace meshfair::app;

constexpr int kExitInput = 2;
constexpr int kExitWrite = 3;
constexpr int kExitInternal = 1;

// "--mode" words: a shading (flat, smooth) and what to draw over it.
void apply_mode(const std::string& word, DisplayOptions& d)
{
    if (word == "flat")
        d.shading = Shading::Flat;
    else if (word == "smooth")
        d.shading = Shading::Smooth;
    else if (word == "wire")
        d.wireframe = true;
    else if (word == "points")
        d.vertex_points = true;
    else if (word == "boundary")
        d.boundary_edges = true;
    else if (word == "no-boundary")
        d.boundary_edges = false;
    else if (word == "no-back-tint")
        d.back_face_tint = false;
    else
        throw CLI::ValidationError("--mode", "unknown mode '" + word +
                                                 "' (flat, smooth, wire, points, boundary, "
                                                 "no-boundary, no-back-tint)");
}

void parse_size(const std::string& text, int& width, int& height)
{
    int w = 0, h = 0;
    char x = 0, rest = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X') ||
        w < 16 || h < 16 || w > 8192 || h > 8192)
        throw CLI::ValidationError("--size", "'" + text + "' is not WxH with 16 <= W, H <= 8192");
    width = w;
    height = h;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"meshfair: select, constrain and smooth polygon meshes"};
    std::string mesh = MESHFAIR_DEFAULT_MESH;
    bool offscreen = false, ui = false;
    std::string view, screenshot, save_view, script, beside, size = "1280x800";
    std::vector<std::string> modes;
    int threads = 0;
    bool trace = false;
    std::string widget_map;
    app.add_option("MESH", mesh, "Mesh to open (OBJ, OFF, PLY, STL; default: the bundled bunny)");
    app.add_flag("--offscreen", offscreen,
                 "Render one frame through OSMesa (no display needed) and exit");
    app.add_option("--view", view, "Camera to start from (JSON written by --save-view)");
    app.add_option("--screenshot", screenshot,
                   "PNG to write: the offscreen frame, or where F12 writes in the window");
    app.add_option("--save-view", save_view, "Write the offscreen frame's camera as JSON");
    app.add_option("--script", script,
                   "Offscreen: play a scripted session (JSON, docs/editor.md) before the frame");
    app.add_option("--beside", beside,
                   "Offscreen: draw this mesh too, to the right of MESH, seen by the same camera "
                   "(a before / after picture twice as wide)");
    app.add_option("--size", size, "Frame size WxH (default 1280x800; with --beside, each half)");
    app.add_option("--mode", modes,
                   "Display: flat|smooth, and any of wire, points, boundary, no-boundary, "
                   "no-back-tint (comma-separated or repeated)")
        ->delimiter(',');
    app.add_flag("--ui", ui, "Offscreen: draw the editor's panels too");
    app.add_flag("--trace", trace,
                 "Print each command the keys, menus, panels and tools give, and its outcome "
                 "(offscreen: those of the script)");
    app.add_option("--widget-map", widget_map,
                   "Window: keep FILE listing where each widget of the interface is (label, "
                   "x0, y0, x1, y1 in window pixels, tab-separated, after the lines '#frame N' "
                   "(the frame, once on the screen) and '#input EVENTS HELD QUEUED MOVES X Y': "
                   "the key, button and wheel events handled, 1 while a key or button is down, "
                   "1 while events wait, the cursor moves handled and where the last one put "
                   "the cursor), for driving it from outside");
    app.add_option("--threads", threads, "Threads for normals and loading (default: every core)")
        ->check(CLI::Range(1, 1024));
    DisplayOptions display;
    int width = 1280, height = 800;
    try
    {
        app.parse(argc, argv);
        for (const std::string& m : modes)
            apply_mode(m, display);
        parse_size(size, width, height);
    }
    catch (const CLI::ParseError& e)
    {
        return app.exit(e) == 0 ? 0 : kExitInput;
    }
    if (threads > 0)
        set_thread_count(threads);

    try
    {
        if (!script.empty() && !offscreen)
        {
            std::cerr << "meshfair: --script needs --offscreen\n";
            return kExitInput;
        }
        if (!beside.empty() && !offscreen)
        {
            std::cerr << "meshfair: --beside needs --offscreen\n";
            return kExitInput;
        }
        if (!offscreen)
        {
            try
            {
                run_window({mesh, view, screenshot, width, height, display, trace, widget_map});
                return 0;
            }
            catch (const NoDisplayError& e)
            {
                if (screenshot.empty())
                    screenshot = "meshfair-screenshot.png";
                std::cerr << "meshfair: no display (" << e.what() << "); rendering offscreen to "
                          << screenshot << " instead\n";
            }
        }
        if (screenshot.empty())
        {
            std::cerr << "meshfair: --offscreen needs --screenshot OUT.png\n";
            return kExitInput;
        }
        render_screenshot(
            {mesh, view, screenshot, save_view, script, beside, width, height, display, ui, trace});
        return 0;
    }
    catch (const WriteError& e)
    {
        std::cerr << "meshfair: " << e.what() << "\n";
        return kExitWrite;
    }
    catch (const InvalidInputError& e)
    {
        std::cerr << "meshfair: " << e.what() << "\n";
        return kExitInput;
    }
    catch (const std::exception& e)
    {
        std::cerr << "meshfair: " << e.what() << "\n";
        return kExitInternal;
    }
}
