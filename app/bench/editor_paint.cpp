// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/editor_paint.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "app/bench/bench_common.h"
#include "app/editor/editor_session.h"
#include "app/render/gl_renderer.h"
#include "core/recipe/locality_run.h"

namespace meshfair::bench {

namespace {

using namespace meshfair::app;
using Clock = std::chrono::steady_clock;

//! The CPU time of the calling thread so far, in milliseconds: a dab's own work, where the
//! wall clock also counts the waits for a core on a shared machine.
double thread_cpu_ms()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

struct StrokeTimes
{
    std::vector<double> press;   // the press: the ID buffer rendered, the first dab
    std::vector<double> dab;     // a mouse move giving one dab
    std::vector<double> dab_cpu; // its CPU time on the interface's thread
    std::vector<double> frame;   // the frame's update and renderer sync after it
    std::vector<double> release; // the release, until the final shape is the document's
    std::vector<double> stroke;  // press to final shape
    size_t dabs = 0;             // dabs of the last stroke
};

//! One stroke left to right across the top of the torus (in the front view), a dab per
//! mouse move, then undone.
void stroke(EditorSession& s, int width, int height, const PaintOptions& o, StrokeTimes& t)
{
    const glm::dvec3 from = s.camera().project({-0.5, 1.0, 0.4}, width, height);
    const double spacing = std::max(1.0, o.radius_px / 4); // PaintTool's: one dab a move
    const auto start = Clock::now();
    auto at = Clock::now();
    s.mouse_press(MouseButton::Left, {}, from.x, from.y);
    t.press.push_back(ms_since(at));
    for (int k = 1; k < o.dabs; ++k)
    {
        const size_t before = s.last_stroke().size();
        at = Clock::now();
        const double cpu = thread_cpu_ms();
        s.mouse_move(from.x + spacing * k, from.y);
        const double ms = ms_since(at);
        if (s.last_stroke().size() == before + 1)
        {
            t.dab.push_back(ms);
            t.dab_cpu.push_back(thread_cpu_ms() - cpu);
        }
        at = Clock::now();
        s.update();
        s.sync_renderer();
        t.frame.push_back(ms_since(at));
    }
    at = Clock::now();
    s.mouse_release(MouseButton::Left, from.x + spacing * (o.dabs - 1), from.y);
    // (After the release the shape is the stroke's: a frame's update takes what is left.)
    s.update();
    t.release.push_back(ms_since(at));
    t.stroke.push_back(ms_since(start));
    t.dabs = s.last_stroke().size();
    s.dispatch(cmd::Undo{});
    s.settle_solver();
}

} // namespace

void paint_case(const Mesh& mesh, int width, int height, const PaintOptions& o)
{
    LocalityOrder order = locality_order(mesh);
    Document document = make_document(reorder_mesh(mesh, order), "scan");
    document.order = std::move(order);
    GlRenderer renderer;
    EditorSession s(std::move(document), renderer);
    s.state().offscreen = true;
    s.set_view_rect(ViewRect::whole(width, height));
    s.dispatch(cmd::AddNoise{o.noise, 1});
    s.dispatch(cmd::SetView{StandardView::Front});
    s.dispatch(cmd::FrameAll{});
    s.dispatch(cmd::SetTool{ToolKind::Paint});
    s.dispatch(cmd::SetBrushRadius{o.radius_px});
    s.settle_solver();
    s.draw();
    const int steps = s.tool_settings().paint.steps;
    std::printf(
        "\nsmoothing brush strokes: %lld vertices (a noisy torus of triangles), %d dabs a "
        "stroke of %d steps each, radius %.0f px, %d strokes per recipe:\n\n",
        static_cast<long long>(s.document().mesh.vertex_count()), o.dabs, steps, o.radius_px,
        o.strokes);
    std::printf(
        "| recipe | dabs | press, median ms | dab on the interface's thread, median / max ms | "
        "its CPU time, median / max ms | frame's update, median / max ms | release to final "
        "shape, median / max ms | whole stroke, median ms |\n|---|---|---|---|---|---|---|---|\n");
    const std::pair<const char*, const char*> recipes[] = {{"plain region", ""},
                                                           {"denoise-organic", "denoise-organic"}};
    for (const auto& [name, preset] : recipes)
    {
        if (*preset != 0)
        {
            s.dispatch(cmd::ApplyPreset{preset});
            s.settle_solver();
        }
        StrokeTimes t;
        for (int k = 0; k < o.strokes; ++k)
            stroke(s, width, height, o, t);
        std::printf(
            "| %s | %zu | %.1f | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.1f / %.1f | %.0f |\n",
            name, t.dabs, median(t.press), median(t.dab), max_of(t.dab), median(t.dab_cpu),
            max_of(t.dab_cpu), median(t.frame), max_of(t.frame), median(t.release),
            max_of(t.release), median(t.stroke));
        std::fflush(stdout);
    }
}

} // namespace meshfair::bench
