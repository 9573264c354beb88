// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-editor-bench: how interactive the editor's selection tools are on a large
// mesh. It drives an EditorSession with GlRenderer on OSMesa, as the window does, over a
// subdivided bunny, and times each part of a frame separately: the tool's work for one
// mouse event, the upload of the selection to the renderer, the software rasterization
// (llvmpipe here; a GPU draws the same buffers far faster), and the undo record; then a
// pin dragged with the M tool, each move timed until the editor shows the minimizer
// (editor_drag.h); and strokes of the smoothing brush over a 50k-vertex scan, each dab
// timed on the interface's thread (editor_paint.h). See docs/performance.md ("Editor").
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "app/bench/bench_common.h"
#include "app/bench/editor_drag.h"
#include "app/bench/editor_paint.h"
#include "app/bench/memory_bandwidth.h"
#include "app/bench/mesh_generator.h"
#include "app/editor/editor_session.h"
#include "app/editor/editor_ui.h"
#include "app/editor/interface_context.h"
#include "app/editor/live_solver.h"
#include "app/render/gl_renderer.h"
#include "app/render/osmesa_context.h"
#include "core/io/io.h"
#include "core/parallel/parallel.h"
#include "core/recipe/locality_run.h"
#include "core/recipe/recipe_json.h"

namespace {

using namespace meshfair;
using namespace meshfair::app;
using Clock = std::chrono::steady_clock;
using bench::ms_since;

struct Series
{
    std::string name;
    std::vector<double> ms;
    double median() const { return bench::median(ms); }
    double max() const { return ms.empty() ? 0 : *std::max_element(ms.begin(), ms.end()); }
};

void print(const Series& s)
{
    std::printf("| %s | %zu | %.2f | %.2f |\n", s.name.c_str(), s.ms.size(), s.median(), s.max());
}

//! The CPU time of the process so far (all its threads), in milliseconds.
double process_cpu_ms()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

double timed(const std::function<void()>& f)
{
    const auto t = Clock::now();
    f();
    return ms_since(t);
}

//! A torus of nu x nv vertices (R = 1, r = 0.4): quads, or each quad split into two
//! triangles (three edges a vertex, as a scan).
Mesh torus(int nu, int nv, bool quads)
{
    Mesh m;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
        {
            const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
            m.add_vertex((1 + 0.4 * std::cos(v)) * std::cos(u),
                         (1 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v));
        }
    const auto at = [&](int i, int j) { return static_cast<Index>((j % nv) * nu + (i % nu)); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
        {
            const Index a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (quads)
                m.add_face(std::array<Index, 4>{a, b, c, d});
            else
            {
                m.add_face(std::array<Index, 3>{a, b, c});
                m.add_face(std::array<Index, 3>{a, c, d});
            }
        }
    return m;
}

//! The view's frames while the camera orbits (2 pixels between frames): the draw call and
//! its wait, for plain shading, with the wireframe and flat-shaded, interleaved so that a
//! busy moment of the machine falls on all three alike. Prints a row per mode and the
//! ratio of the wireframe's median to plain shading's.
void view_frames(const std::string& name, EditorSession& session, GlRenderer& renderer, int frames,
                 int width, int height)
{
    const DisplayOptions base = session.state().display;
    DisplayOptions wire = base, flat = base;
    wire.wireframe = true;
    flat.shading = Shading::Flat;
    const std::pair<const char*, DisplayOptions> modes[3] = {
        {"shading", base}, {"shading + wireframe", wire}, {"flat shading", flat}};
    // Wall clock, and the CPU time of the whole process (the caller's and llvmpipe's
    // threads): on a shared machine the second tells the frame's own work from the wait
    // for a core.
    std::vector<double> ms[3], cpu[3];
    for (int f = -1; f < frames; ++f) // frame -1: each mode's programs made, not timed
        for (int m = 0; m < 3; ++m)
        {
            session.camera().orbit(OrbitStyle::Turntable, 0, 0, 2, 0, width, height);
            session.state().display = modes[m].second;
            const double cpu_start = process_cpu_ms();
            const double t = timed([&] {
                session.draw();
                (void)renderer.read_pixels(1, 1); // waits for the frame
            });
            if (f >= 0)
            {
                ms[m].push_back(t);
                cpu[m].push_back(process_cpu_ms() - cpu_start);
            }
        }
    session.state().display = base;
    for (int m = 0; m < 3; ++m)
        std::printf("| %s | %s | %d | %.1f | %.1f | %.1f |\n", name.c_str(), modes[m].first, frames,
                    bench::median(ms[m]), *std::min_element(ms[m].begin(), ms[m].end()),
                    bench::median(cpu[m]));
    std::printf("| %s | wireframe / shading | | %.2fx | | %.2fx |\n", name.c_str(),
                bench::median(ms[1]) / bench::median(ms[0]),
                bench::median(cpu[1]) / bench::median(cpu[0]));
}

//! view_frames on a mesh of its own (a renderer and a session of its own, framed as the
//! bench's).
void view_frames_of(const std::string& name, Mesh mesh, int frames, int width, int height)
{
    GlRenderer renderer;
    EditorSession session(make_document(std::move(mesh), name), renderer);
    session.state().offscreen = true;
    session.set_view_rect(ViewRect::whole(width, height));
    session.camera().frame(session.document().box, session.aspect());
    view_frames(name, session, renderer, frames, width, height);
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"meshfair-editor-bench: the selection tools' frame times on a large mesh"};
    std::string mesh_path = MESHFAIR_DEFAULT_MESH;
    long long min_vertices = 1000000;
    int width = 1280, height = 800, events = 60, reps = 3, threads = 0, frames = 30;
    app.add_option("--mesh", mesh_path, "triangle mesh to subdivide")->check(CLI::ExistingFile);
    app.add_option("--vertices", min_vertices, "at least this many vertices");
    app.add_option("--events", events, "mouse moves per stroke")->check(CLI::Range(2, 10000));
    app.add_option("--reps", reps, "strokes and rectangles of each kind")
        ->check(CLI::Range(1, 100));
    app.add_option("--frames", frames, "live-solving frames timed per recipe")
        ->check(CLI::Range(1, 100000));
    app.add_option("--threads", threads, "threads (default: all cores)")
        ->check(CLI::Range(0, 1024));
    bench::DragOptions drag;
    bool drag_only = false, frames_only = false;
    int view_frame_count = 10;
    app.add_option("--drag-moves", drag.moves,
                   "pin drag: mouse moves timed after the first (0: no drag)")
        ->check(CLI::Range(0, 10000));
    app.add_option("--drag-px", drag.step_px, "pin drag: pixels each move lifts the pins")
        ->check(CLI::Range(0.5, 100.0));
    app.add_option(
           "--drag-region", drag.region,
           "pin drag: the region's rectangle through the surface, as a fraction of the view")
        ->check(CLI::Range(0.05, 1.0));
    app.add_option("--jacobi-moves", drag.jacobi_moves, "pin drag: moves of the Jacobi peer")
        ->check(CLI::Range(0, 1000));
    app.add_option("--jacobi-cap-ms", drag.jacobi_cap_ms,
                   "pin drag: the Jacobi peer's time per move")
        ->check(CLI::Range(100.0, 600000.0));
    app.add_flag("--drag-cg", drag.conjugate_gradients,
                 "pin drag: by conjugate gradients (no factor), not the direct method");
    app.add_flag("--drag-only", drag_only,
                 "only the pin drag (not the selection and live solving)");
    app.add_option("--view-frames", view_frame_count,
                   "view frames timed per display mode while the camera orbits (0: none)")
        ->check(CLI::Range(0, 10000));
    app.add_flag("--frames-only", frames_only,
                 "only the view's frames (shading, wireframe, flat) at the bench's size and "
                 "on the bunny and 60k tori");
    bench::PaintOptions paint;
    bool paint_only = false;
    app.add_option("--paint-dabs", paint.dabs,
                   "smoothing brush strokes on a 50k-vertex scan: dabs a stroke (0: none)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--paint-strokes", paint.strokes, "smoothing brush strokes per recipe")
        ->check(CLI::Range(1, 100));
    app.add_flag("--paint-only", paint_only, "only the smoothing brush strokes on the scan");
    CLI11_PARSE(app, argc, argv);
    if (threads > 0)
        set_thread_count(threads);

    if (paint_only)
    {
        // A scan's size where a stroke must keep up with the mouse: 50,000 vertices.
        OsmesaContext context(width, height);
        bench::paint_case(torus(250, 200, false), width, height, paint);
        return 0;
    }
    const Mesh base = io::read_mesh(mesh_path);
    const int k = bench::subdivision_factor_for(base, min_vertices);
    auto t = Clock::now();
    // In the locality numbering, as load_document keeps every document.
    Mesh subdivided = bench::subdivide_triangles(base, k);
    LocalityOrder order = locality_order(subdivided);
    Document document = make_document(reorder_mesh(subdivided, order), "subdivided");
    document.order = std::move(order);
    subdivided = Mesh{};
    const double document_ms = ms_since(t);
    const Index n = document.mesh.vertex_count();
    std::printf(
        "mesh: %s subdivided %d-fold: %lld vertices, %lld faces; %d threads; "
        "%dx%d view\n",
        mesh_path.c_str(), k, static_cast<long long>(n),
        static_cast<long long>(document.mesh.face_count()), thread_count(), width, height);
    std::printf("document (topology, draw data): %.0f ms\n\n", document_ms);

    OsmesaContext context(width, height);
    GlRenderer renderer;
    t = Clock::now();
    EditorSession session(std::move(document), renderer);
    std::printf("renderer set_mesh: %.0f ms (%s)\n\n", ms_since(t),
                context.renderer_name().c_str());
    session.state().offscreen = true;
    session.set_view_rect(ViewRect::whole(width, height));
    session.camera().frame(session.document().box, session.aspect());
    session.draw();
    if (view_frame_count > 0 && !drag_only)
    {
        // The draw call alone (rasterization and its wait), the camera orbiting: at the
        // bench's size, on the bunny as it is and on 60,000-vertex tori of triangles (three
        // edges a vertex) and of quads (the fan's diagonals hidden from the wireframe).
        std::printf("view frames while orbiting (%s):\n\n", context.renderer_name().c_str());
        std::printf(
            "| mesh | display | frames | median ms | min ms | median CPU ms (all threads) "
            "|\n|---|---|---|---|---|---|\n");
        view_frames(std::to_string(n) + " vertices", session, renderer, view_frame_count, width,
                    height);
        view_frames_of("the mesh as read (" + std::to_string(base.vertex_count()) + " vertices)",
                       base, view_frame_count, width, height);
        view_frames_of("torus, 60,000 vertices, triangles", torus(300, 200, false),
                       view_frame_count, width, height);
        view_frames_of("torus, 60,000 vertices, quads", torus(300, 200, true), view_frame_count,
                       width, height);
        std::printf("\n");
        session.draw();
        if (frames_only)
            return 0;
    }
    if (drag_only)
    {
        bench::drag_case(session, width, height, drag);
        return 0;
    }

    const char* kinds[2] = {"vertices", "faces"};
    std::vector<Series> press_moved, press_same, rect_release;
    for (const char* kind_name : kinds)
    {
        press_moved.push_back(
            {std::string("brush press, ") + kind_name + ", after a camera move", {}});
        press_same.push_back({std::string("brush press, ") + kind_name + ", same view", {}});
        rect_release.push_back({std::string("rectangle release, ") + kind_name, {}});
    }
    Series rect_through{"rectangle release, vertices, through the surface", {}};
    Series move{"brush move (dabs, selection flags)", {}};
    Series upload{"selection upload (set_selection)", {}};
    Series rect_press{"rectangle press, same view", {}};
    Series record{"undo record at release (compare, keep the masks)", {}};
    Series undo{"undo", {}};
    Series raster{"draw (llvmpipe rasterization)", {}};
    Series kept{"draw, nothing changed since (the view kept and copied)", {}};
    Series kept_frame{
        "interface frame, nothing changed in the view (panels laid out and "
        "drawn, the view copied)",
        {}};
    InterfaceContext layer;
    EditorUi interface;
    Series ids{"ID buffer render + read back (Renderer::visibility)", {}};
    std::size_t brushed = 0, rectangled = 0, through = 0;
    const auto count = [](const SelectionMask& m) {
        return static_cast<std::size_t>(std::count(m.begin(), m.end(), 1));
    };
    const double y = 0.5 * height;
    // A brush stroke of radius 40 px across the middle of the view, in zigzag.
    const auto stroke = [&](Series& pressed) {
        session.dispatch(cmd::SetTool{ToolKind::Brush});
        session.dispatch(cmd::SetBrushRadius{40});
        pressed.ms.push_back(
            timed([&] { session.mouse_press(MouseButton::Left, {}, 0.2 * width, y); }));
        for (int e = 1; e <= events; ++e)
        {
            const double x = (0.2 + 0.6 * e / events) * width;
            move.ms.push_back(timed([&] { session.mouse_move(x, y + 40 * ((e % 8) - 4)); }));
            upload.ms.push_back(timed([&] { session.sync_renderer(); }));
        }
        record.ms.push_back(
            timed([&] { session.mouse_release(MouseButton::Left, 0.8 * width, y); }));
    };
    // A rectangle over the left half of the view.
    const auto rectangle = [&](Series& released) {
        session.dispatch(cmd::SetTool{ToolKind::Rectangle});
        rect_press.ms.push_back(timed([&] { session.mouse_press(MouseButton::Left, {}, 0, 0); }));
        session.mouse_move(0.5 * width, height - 1);
        released.ms.push_back(
            timed([&] { session.mouse_release(MouseButton::Left, 0.5 * width, height - 1); }));
        upload.ms.push_back(timed([&] { session.sync_renderer(); }));
    };

    for (int rep = 0; rep < reps; ++rep)
    {
        ids.ms.push_back(
            timed([&] { (void)renderer.visibility(session.camera(), session.view_rect()); }));
        for (int kind = 0; kind < 2; ++kind)
        {
            session.dispatch(
                cmd::SetElements{kind == 0 ? ElementKind::Vertices : ElementKind::Faces});
            session.dispatch(cmd::SetThrough{false});
            // A small orbit first: the first press renders the ID buffer, the next reuse it.
            session.camera().orbit(OrbitStyle::Turntable, 0, 0, 2, 0, width, height);
            stroke(press_moved[kind]);
            stroke(press_same[kind]);
            brushed = std::max(brushed, count(session.document().selected_vertices));
            raster.ms.push_back(timed([&] {
                session.draw();
                (void)renderer.read_pixels(1, 1); // waits for the frame
            }));
            // A frame of the interface alone (a panel hovered, a slider of it dragged).
            kept.ms.push_back(timed([&] {
                session.draw();
                (void)renderer.read_pixels(1, 1);
            }));
            // The whole frame such an event costs: the interface built and drawn over it.
            kept_frame.ms.push_back(timed([&] {
                interface.prepare_offscreen(layer, session.document(), session.state(),
                                            session.camera(), width, height);
                session.draw();
                layer.draw();
                (void)renderer.read_pixels(1, 1);
            }));
            rectangle(rect_release[kind]);
            rectangled = std::max(rectangled, count(kind == 0 ? session.document().selected_vertices
                                                              : session.document().selected_faces));
            undo.ms.push_back(timed([&] { session.dispatch(cmd::Undo{}); }));
            session.dispatch(cmd::Redo{});
        }
        session.dispatch(cmd::SetElements{ElementKind::Vertices});
        session.dispatch(cmd::SetThrough{true});
        rectangle(rect_through);
        through = std::max(through, count(session.document().selected_vertices));
    }
    std::printf(
        "selected at most: %zu vertices by a stroke, %zu elements by a front-facing "
        "rectangle, %zu vertices (%.0f %%) by a rectangle through the surface\n\n",
        brushed, rectangled, through, 100.0 * double(through) / double(n));
    std::printf("| part | samples | median ms | max ms |\n|---|---|---|---|\n");
    for (int kind = 0; kind < 2; ++kind)
    {
        print(press_moved[kind]);
        print(press_same[kind]);
    }
    for (const Series* s :
         {&move, &upload, &record, &rect_press, &rect_release[0], &rect_release[1], &rect_through,
          &undo, &raster, &kept, &kept_frame, &ids})
        print(*s);
    const double frame = move.median() + upload.median();
    std::printf(
        "\nbrush frame without rasterization (move + upload, medians): %.2f ms = %.0f %% "
        "of a 16.7 ms frame\n",
        frame, 100 * frame / 16.7);

    // --- The smoothing brush: a stroke of the Paint tool as the mouse gives it. The press
    // renders the ID buffer once (the visible vertices); each dab paints the map and asks
    // the solver's thread for the stroke's run (its steps of the whole recipe from where the
    // stroke began, the solver restarted for the new map), which the release waits for.
    double dab_ms = 0;
    const int dab_steps = session.tool_settings().paint.steps;
    {
        session.dispatch(cmd::SetTool{ToolKind::Paint});
        session.dispatch(cmd::SetBrushRadius{40});
        Series press{"smoothing brush: the press (visible vertices, first dab)", {}};
        Series dab{"smoothing brush: a mouse move with one dab (its run of " +
                       std::to_string(dab_steps) + " steps on the solver's thread)",
                   {}};
        for (int rep = 0; rep < reps; ++rep)
        {
            session.camera().orbit(OrbitStyle::Turntable, 0, 0, 2, 0, width, height);
            press.ms.push_back(
                timed([&] { session.mouse_press(MouseButton::Left, {}, 0.45 * width, y); }));
            for (int e = 1; e <= 4; ++e)
            {
                const std::size_t before = session.last_stroke().size();
                const double ms = timed([&] { session.mouse_move((0.45 + 0.01 * e) * width, y); });
                if (session.last_stroke().size() == before + 1)
                    dab.ms.push_back(ms);
            }
            session.mouse_release(MouseButton::Left, 0.49 * width, y);
            session.dispatch(cmd::Undo{});
        }
        std::printf("\n| part | samples | median ms | max ms |\n|---|---|---|---|\n");
        print(press);
        print(dab);
        dab_ms = dab.median();
    }

    // --- Live solving: a frame of one step, as the solver's thread and the interface run
    // it, each part timed apart, for plain smoothing and for the combined recipe. The
    // parts are those of LiveSolver::run_steps (step, energy for the plot, the positions
    // published) and of EditorSession::update (the renderer's normals and upload).
    std::printf("\nlive solving, one step per frame (%d frames):\n\n", frames);
    std::printf("| recipe | part | median ms | max ms |\n|---|---|---|---|\n");
    const Document& doc = session.document();
    Mesh internal_mesh; // the document's base shape, in its numbering
    internal_mesh.positions = doc.base_positions;
    internal_mesh.face_offsets = doc.mesh.face_offsets;
    internal_mesh.face_vertices = doc.mesh.face_vertices;
    Recipe combined;
    {
        // Half the mesh moves; anchors, centroids and normals on parts of it.
        const Index nv = doc.mesh.vertex_count(), nf = doc.mesh.face_count();
        combined.region = Region{};
        for (Index v = 0; v < nv / 2; ++v)
            combined.region->vertices.push_back(v);
        combined.soft = SoftVertices{};
        for (Index v = 0; v < nv / 2; v += 7)
            combined.soft->vertices.indices.push_back(v);
        combined.centroid = CentroidConstraints{};
        combined.normal = NormalConstraints{};
        for (Index f = 0; f < nf; f += 3)
            combined.centroid->faces.indices.push_back(f);
        for (Index f = 1; f < nf; f += 3)
            combined.normal->faces.indices.push_back(f);
    }
    // The modes beside the paper's terms, each as an artist turns it on: anchors fading
    // from the region's border (the combined recipe with a falloff), the volume kept
    // (plain smoothing with the constraint), and the presets as their files say them
    // (denoise: bilateral normal smoothing, reweighted, in the precomputation, then
    // integrated by the normal term, volume kept; relax: Taubin's two steps).
    Recipe with_falloff = combined;
    with_falloff.falloff = Falloff{};
    Recipe with_volume;
    with_volume.volume = KeepVolume{};
    const std::string recipes_dir = MESHFAIR_RECIPES_DIR;
    const std::vector<std::pair<const char*, Recipe>> recipes = {
        {"plain", Recipe{}},
        {"combined", combined},
        {"combined, falloff from the border", with_falloff},
        {"plain, volume kept", with_volume},
        {"denoise.json (bilateral normals, volume)", read_recipe(recipes_dir + "/denoise.json")},
        {"relax.json (Taubin, centroids, volume)", read_recipe(recipes_dir + "/relax.json")}};
    // Per recipe, for the ratios to the plain step printed at the end.
    struct Priced
    {
        std::string name;
        double precompute, step, frame;
    };
    std::vector<Priced> priced;
    // The published positions and the display geometry outlive the runs, as LiveSolver's
    // buffers do: a run's first frame recomputes everything into memory already touched.
    std::vector<Scalar> published(doc.mesh.positions.size());
    DisplayGeometry g;
    for (const auto& [name, recipe] : recipes)
    {
        t = Clock::now();
        LocalityRun run(internal_mesh, doc.order, recipe);
        const double precompute = ms_since(t);
        // As LiveSolver::restart: a display run whose frames recompute and upload only the
        // part the steps move.
        t = Clock::now();
        const auto changing = std::make_shared<const ChangingPart>(
            changing_part(run.mesh(), doc.draw_data.vertex_face_offsets, doc.draw_data.vertex_faces,
                          run.session().free_vertices()));
        const double changing_ms = ms_since(t);
        const std::uint64_t display_run = new_display_run();
        // The solver's thread: a step (its sweep gives the plot's energy), the positions
        // published, and the display geometry. The interface's thread: the upload. The run's
        // first frame computes and uploads everything; the others only the changing part.
        Series step{"solver step, with the plot's energy from its sweep", {}},
            energy{"energy in a pass of its own (only when a run stops)", {}},
            back{"positions published (copy)", {}},
            display{
                "display geometry of the changing part (floats, face area vectors, vertex "
                "normals)",
                {}},
            worker{"solver's thread, per frame (sum)", {}},
            gpu{"interface's thread: upload of the changing part (update_geometry)", {}},
            required{"iteration + normal update + upload", {}},
            peer{"peer: STREAM triad over three position-sized arrays", {}};
        double first_display = 0, first_upload = 0;
        // The peer, timed in the same frames: the machine's memory speed of the moment, so
        // that the frame's parts can be read as ratios when the machine is shared.
        bench::TriadBandwidth triad(published.size());
        for (int f = 0; f <= frames; ++f)
        {
            TermEnergies plotted; // LiveSolver::run_steps: the energy the step starts from
            const double a = timed([&] { run.session().step(plotted); });
            const double b = timed([&] { (void)run.energy(); });
            const double c = timed([&] {
                const std::span<const Scalar> x = run.session().positions();
                std::copy(x.begin(), x.end(), published.begin());
            });
            const double d = timed([&] {
                update_display_geometry(published, doc.mesh, doc.draw_data.vertex_face_offsets,
                                        doc.draw_data.vertex_faces, display_run, changing, g);
            });
            const double u = timed([&] {
                renderer.update_geometry(g);
                (void)renderer.read_pixels(1, 1); // the upload has reached the GPU side
            });
            if (f == 0)
            {
                first_display = d;
                first_upload = u;
                continue;
            }
            const double bytes = 24.0 * double(published.size());
            peer.ms.push_back(1e3 * bytes / triad.measure(1));
            step.ms.push_back(a);
            energy.ms.push_back(b);
            back.ms.push_back(c);
            display.ms.push_back(d);
            worker.ms.push_back(a + c + d);
            gpu.ms.push_back(u);
            required.ms.push_back(a + d + u);
        }
        std::printf(
            "| %s | the changing part (once per run): %d and %d vertex and face ranges, "
            "%.0f %% of the vertices | %.2f | |\n",
            name, static_cast<int>(changing->vertices.begin.size()),
            static_cast<int>(changing->faces.begin.size()),
            100.0 * changing->vertices.count() / doc.mesh.vertex_count(), changing_ms);
        std::printf("| %s | a run's first frame: display geometry of the whole mesh | %.2f | |\n",
                    name, first_display);
        std::printf("| %s | a run's first frame: upload of the whole mesh | %.2f | |\n", name,
                    first_upload);
        std::printf("| %s | precomputation (once per recipe) | %.0f | |\n", name, precompute);
        for (const Series* x : {&step, &energy, &back, &display, &worker, &gpu, &required, &peer})
            std::printf("| %s | %s | %.2f | %.2f |\n", name, x->name.c_str(), x->median(),
                        x->max());
        std::printf("| %s | iteration + normal update + upload / peer | %.1fx | |\n", name,
                    required.median() / peer.median());
        priced.push_back({name, precompute, step.median(), required.median()});
    }

    // Every mode priced against the plain step of the same run (medians).
    const Priced& plain = priced.front();
    std::printf("\nthe modes priced against the plain step (%.2f ms; its frame %.2f ms):\n\n",
                plain.step, plain.frame);
    std::printf(
        "| mode | step / plain step | frame / plain frame | precomputation / plain step "
        "|\n|---|---|---|---|\n");
    for (const Priced& m : priced)
        std::printf("| %s | %.2fx | %.2fx | %.0fx |\n", m.name.c_str(), m.step / plain.step,
                    m.frame / plain.frame, m.precompute / plain.step);
    std::printf(
        "| smoothing brush, a dab on the interface's thread (its map; its run of %d steps is "
        "the solver's) | %.2fx | | |\n",
        dab_steps, dab_ms / plain.step);

    if (paint.dabs > 0)
        bench::paint_case(torus(250, 200, false), width, height, paint);

    // --- Last, as it leaves its sets in the document (the smoothing brush runs them).
    if (drag.moves > 0)
        bench::drag_case(session, width, height, drag);
    return 0;
}
