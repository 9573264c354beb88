// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-bench: MeshFair's solver and reader against OpenMesh and tinyobjloader, in one
// process, on k-fold subdivisions of the bundled bunny in three vertex orders, with the
// machine's memory bandwidth measured in the same run. See docs/performance.md.
#include <fcntl.h>
#include <omp.h>
#include <spawn.h>
#include <sys/wait.h>
#include <tiny_obj_loader.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/bench/bench_common.h"
#include "app/bench/core_clock.h"
#include "app/bench/memory_bandwidth.h"
#include "app/bench/mesh_generator.h"
#include "app/bench/openmesh_peer.h"
#include "core/io/io.h"
#include "core/parallel/parallel.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/topology/topology.h"
#include "core/topology/vertex_order.h"

extern char** environ;

namespace {

using namespace meshfair;
using Clock = std::chrono::steady_clock;
using bench::default_cli;
using bench::human_count;
using bench::seconds_since;

//! One measured figure: its samples (one per repetition) and how to print them.
struct Figure
{
    std::string name;           //!< "plain step", "load + topology", ...
    Index vertices = 0;         //!< mesh size
    std::string order;          //!< vertex order of the mesh
    std::string implementation; //!< meshfair, openmesh, tinyobjloader, machine
    std::string unit;           //!< "s", "B/s", "B/vertex"
    std::vector<double> samples;

    double median() const { return bench::median(samples); }
    double min() const { return *std::min_element(samples.begin(), samples.end()); }
    double max() const { return *std::max_element(samples.begin(), samples.end()); }
};

struct Options
{
    std::vector<long> sizes{1'000'000, 4'000'000};
    int reps = 5;
    int steps = 10;
    int threads = 0;
    std::string mesh = MESHFAIR_DEFAULT_MESH;
    std::string cache = "bench-meshes";
    std::string out = "bench-results.tsv";
    std::string cli;
    bool skip_load = false;
    bool profile = false;
};

std::string format_value(double v, const std::string& unit)
{
    char buffer[64];
    if (unit == "s")
        std::snprintf(buffer, sizeof buffer, "%10.3f ms", v * 1e3);
    else if (unit == "B/s")
        std::snprintf(buffer, sizeof buffer, "%9.2f GB/s", v / 1e9);
    else if (unit == "Hz")
        std::snprintf(buffer, sizeof buffer, "%10.2f GHz", v / 1e9);
    else if (unit == "B/vertex")
        std::snprintf(buffer, sizeof buffer, "%10.1f B/v", v);
    else
        std::snprintf(buffer, sizeof buffer, "%10.3f %s", v, unit.c_str());
    return buffer;
}

//! The vertices on a boundary edge (n_e = 1), which OpenMesh's smoother never moves.
std::vector<Index> boundary_vertices(const Topology& topology)
{
    std::vector<char> on(static_cast<size_t>(topology.vertex_count), 0);
    for (Index e = 0; e < topology.edge_count(); ++e)
        if (topology.edge_kind(e) == EdgeKind::Boundary)
            on[topology.edge_vertices[2 * e]] = on[topology.edge_vertices[2 * e + 1]] = 1;
    std::vector<Index> out;
    for (Index i = 0; i < topology.vertex_count; ++i)
        if (on[i])
            out.push_back(i);
    return out;
}

Recipe plain_recipe(const Topology& topology)
{
    Recipe r;
    r.lambda = 0.5;
    const std::vector<Index> boundary = boundary_vertices(topology);
    if (!boundary.empty())
        r.hard = HardVertices{boundary, {}};
    return r;
}

//! Soft vertex, centroid and normal terms on every element (and, with `region`, only the
//! region's vertices free).
Recipe combined_recipe(std::optional<Region> region)
{
    Recipe r;
    r.lambda = 0.5;
    r.soft = SoftVertices{IndexSet{true, {}}, 0.05, {}};
    r.centroid = CentroidConstraints{IndexSet{true, {}}, 1.0, {}, CentroidDenominator::Paper};
    r.normal = NormalConstraints{IndexSet{true, {}}, 1.0, NormalSource::Initial, {}};
    r.region = std::move(region);
    return r;
}

//! A connected patch of about `fraction` of the vertices: the first vertices of a
//! breadth-first visit from vertex 0, as a brush stroke grown from a click would select.
Region patch_region(const Mesh& mesh, double fraction)
{
    std::vector<Index> order = breadth_first_order(mesh);
    order.resize(static_cast<size_t>(fraction * mesh.vertex_count()));
    std::sort(order.begin(), order.end());
    return Region{std::move(order), {}};
}

//! Bytes a plain step must move at least, counted like STREAM (reads + writes, no
//! write-allocate): the old positions and the adjacency (CSR offsets and neighbours) read
//! once, the new positions written once.
double plain_step_bytes(const Topology& t)
{
    return 24.0 * t.vertex_count * 2 + 4.0 * (t.vertex_count + 1) +
           4.0 * static_cast<double>(t.vertex_neighbors.size());
}

//! The combined step adds the initial positions (24 B/vertex: the soft targets, and the
//! centroid targets computed from them), the face corners (offsets and indices), each
//! vertex's corners (CSR), and per face the normal (24 B).
double combined_step_bytes(const Mesh& m, const Topology& t)
{
    return plain_step_bytes(t) + 24.0 * t.vertex_count + 4.0 * (m.face_count() + 1) +
           4.0 * m.corner_count() + 4.0 * (t.vertex_count + 1) + 4.0 * m.corner_count() +
           24.0 * m.face_count();
}

double max_relative_difference(const std::vector<Scalar>& a, const std::vector<Scalar>& b)
{
    Scalar diff = 0, scale = 0;
    for (size_t k = 0; k < a.size(); ++k)
    {
        diff = std::max(diff, std::abs(a[k] - b[k]));
        scale = std::max(scale, std::abs(a[k]));
    }
    return scale > 0 ? diff / scale : diff;
}

//! The report of `cli smooth FILE -o OUT --report OUT.report.json [EXTRA...]`, as the CLI
//! writes it; discarded (is_discarded()) when the CLI fails.
nlohmann::json cli_smooth_report(const std::string& cli, const std::string& file,
                                 const std::string& out, std::vector<std::string> extra,
                                 int threads)
{
    const std::string report = out + ".report.json";
    std::vector<std::string> args = {cli, "smooth", file, "-o", out, "--report", report, "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    if (threads > 0)
        args.insert(args.end(), {"--threads", std::to_string(threads)});
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, cli.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    int status = 0;
    if (spawned != 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0)
        return nlohmann::json(nlohmann::json::value_t::discarded);
    return nlohmann::json::parse(io::read_file(report), nullptr, false);
}

//! Peak resident set of `cli smooth FILE --recipe R -o OUT`, in bytes, as the CLI reports
//! it (its own high-water mark: a forked child's ru_maxrss would include this process's
//! memory); negative when it fails.
double cli_peak_rss(const std::string& cli, const std::string& file, const std::string& recipe,
                    const std::string& out, int threads)
{
    const nlohmann::json json = cli_smooth_report(cli, file, out, {"--recipe", recipe}, threads);
    if (json.is_discarded() || !json.contains("peak_memory_bytes"))
        return -1;
    return json["peak_memory_bytes"].get<double>();
}

//! The report's seconds.solve of `cli smooth FILE -o OUT --iterations N` (plain
//! smoothing, the CLI's default recipe); negative when it fails.
double cli_solve_seconds(const std::string& cli, const std::string& file, const std::string& out,
                         int iterations, int threads)
{
    const nlohmann::json json =
        cli_smooth_report(cli, file, out, {"--iterations", std::to_string(iterations)}, threads);
    if (json.is_discarded() || !json.contains("seconds"))
        return -1;
    return json["seconds"]["solve"].get<double>();
}

//! \brief What the bench solves on, as meshfair-cli does: the mesh renumbered for
//! locality, its topology, and the plain and combined sessions, their recipes written in
//! the file's numbering. Sessions point into `work`: not copyable.
struct SolverSetup
{
    explicit SolverSetup(const Mesh& mesh)
        : topology(build_topology(mesh)),
          locality(locality_order(mesh)),
          work(reorder_mesh(mesh, locality)),
          work_topology(build_topology(work)),
          plain(work, work_topology, internal(plain_recipe(topology))),
          combined(work, work_topology, internal(combined_recipe(std::nullopt)))
    {
    }
    SolverSetup(const SolverSetup&) = delete;
    SolverSetup& operator=(const SolverSetup&) = delete;

    //! A recipe in the file's numbering, in the solver's.
    Recipe internal(const Recipe& r) const
    {
        return renumber_recipe(r, locality.vertex_index, locality.face_index);
    }

    Topology topology; //!< of the mesh in the file's numbering
    LocalityOrder locality;
    Mesh work;
    Topology work_topology;
    Session plain;
    Session combined;
};

// The profiled functions stay whole and apart: GCC would merge two of them (the same
// body) without noipa; clang merges neither and does not know that attribute.
#if defined(__clang__)
#define MESHFAIR_PROFILED [[gnu::noinline]]
#else
#define MESHFAIR_PROFILED [[gnu::noipa]]
#endif

class Bench
{
public:
    explicit Bench(Options options) : o_(std::move(options)), triad_(1u << 24) {}

    int run()
    {
        std::filesystem::create_directories(o_.cache);
        const Mesh base = io::read_mesh(o_.mesh);
        std::printf(
            "meshfair-bench: %d thread(s), %d repetitions, %d steps per timing, "
            "base mesh %s (%s vertices)\n",
            omp_get_max_threads(), o_.reps, o_.steps, o_.mesh.c_str(),
            human_count(base.vertex_count()).c_str());
        for (const long size : o_.sizes)
            run_size(base, size);
        write_tsv();
        std::printf("\nresults: %s\n", o_.out.c_str());
        if (!failures_.empty())
        {
            for (const std::string& f : failures_)
                std::fprintf(stderr, "meshfair-bench: FAILED: %s\n", f.c_str());
            return 1;
        }
        return 0;
    }

    //! \brief For a profiler (app/bench/profile.sh runs this under callgrind): the plain
    //! and combined steps of MeshFair and OpenMesh's smoother on the first size's mesh in
    //! its natural order, `--steps` steps each, inside the functions named
    //! profiled_*_steps so the profiler can count each one alone. No timing.
    int profile()
    {
        const Mesh base = io::read_mesh(o_.mesh);
        const long size = o_.sizes.empty() ? 1'000'000 : o_.sizes.front();
        const Mesh mesh =
            bench::subdivide_triangles(base, bench::subdivision_factor_for(base, size));
        SolverSetup setup(mesh);
        bench::OpenMeshPeer peer(mesh);
        setup.plain.set_positions(setup.work.positions);
        setup.combined.set_positions(setup.work.positions);
        profiled_meshfair_plain_steps(setup.plain, o_.steps);
        profiled_meshfair_combined_steps(setup.combined, o_.steps);
        profiled_openmesh_plain_steps(peer, o_.steps);
        std::printf("profiled: %d vertices, %d steps each\n", mesh.vertex_count(), o_.steps);
        return 0;
    }

private:
    MESHFAIR_PROFILED static void profiled_meshfair_plain_steps(Session& session, int steps)
    {
        for (int s = 0; s < steps; ++s)
            session.step();
    }
    MESHFAIR_PROFILED static void profiled_meshfair_combined_steps(Session& session, int steps)
    {
        for (int s = 0; s < steps; ++s)
            session.step();
    }
    MESHFAIR_PROFILED static void profiled_openmesh_plain_steps(bench::OpenMeshPeer& peer,
                                                                int steps)
    {
        peer.smooth(steps);
    }

    Figure& figure(const std::string& name, Index vertices, const std::string& order,
                   const std::string& implementation, const std::string& unit)
    {
        for (Figure& f : figures_)
            if (f.name == name && f.vertices == vertices && f.order == order &&
                f.implementation == implementation)
                return f;
        figures_.push_back(Figure{name, vertices, order, implementation, unit, {}});
        return figures_.back();
    }

    void run_size(const Mesh& base, long size)
    {
        const int k = bench::subdivision_factor_for(base, size);
        const auto t0 = Clock::now();
        const Mesh natural = bench::subdivide_triangles(base, k);
        const Index n = natural.vertex_count();
        std::printf("\n== %s vertices, %s faces (bunny subdivided %d-fold, %.1f s)\n",
                    human_count(n).c_str(), human_count(natural.face_count()).c_str(), k,
                    seconds_since(t0));
        const std::vector<std::pair<std::string, std::vector<Index>>> orders = {
            {"natural", {}},
            {"bfs", breadth_first_order(natural)},
            {"random", bench::random_order(n, 20261122)}};
        for (const auto& [order_name, order] : orders)
        {
            const Mesh mesh = order.empty() ? natural : renumber_vertices(natural, order);
            const std::string stem = o_.cache + "/bunny-" + std::to_string(k) + "x-" + order_name;
            const std::string file = stem + ".obj";
            if (!std::filesystem::exists(file))
                io::write_mesh(mesh, file);
            run_order(mesh, file, order_name);
            if (order_name == "natural")
                peak_rss(mesh, stem);
        }
    }

    void run_order(const Mesh& mesh, const std::string& file, const std::string& order)
    {
        const Index n = mesh.vertex_count();
        SolverSetup setup(mesh);
        const Topology& topology = setup.topology;
        const LocalityOrder& locality = setup.locality;
        const Mesh& work = setup.work;
        Session& plain_session = setup.plain;
        Session& combined_session = setup.combined;
        Session region_session(work, setup.work_topology,
                               setup.internal(combined_recipe(patch_region(mesh, 0.1))));
        // The denoising preset as users run it (bilateral normals, integration, volume).
        Session denoise_session(work, setup.work_topology,
                                setup.internal(read_recipe(MESHFAIR_DENOISE_RECIPE)));
        bench::OpenMeshPeer peer(mesh);

        // Same update? 10 steps of each from the input positions.
        if (peer.boundary_vertices() != boundary_vertices(topology))
            failures_.push_back(order + ": OpenMesh's boundary vertices differ from MeshFair's");
        std::vector<Scalar> x = work.positions;
        for (int s = 0; s < 10; ++s)
            plain_session.step(x);
        std::vector<Scalar> in_file_order(x.size());
        positions_to_file_order(x, locality, in_file_order);
        peer.smooth(10);
        const double difference = max_relative_difference(in_file_order, peer.positions());
        std::printf(
            "\n-- order %-7s  plain step: MeshFair and OpenMesh after 10 steps differ "
            "by %.2e (relative; must be <= 1e-12)\n",
            order.c_str(), difference);
        if (!(difference <= 1e-12))
            failures_.push_back(order + ": positions differ by " + std::to_string(difference));

        const double plain_bytes = plain_step_bytes(topology);
        const double combined_bytes = combined_step_bytes(mesh, topology);
        for (int rep = 0; rep < o_.reps; ++rep)
        {
            figure("bandwidth (triad)", n, order, "machine", "B/s")
                .samples.push_back(triad_.measure());
            figure("core clock", n, order, "machine", "Hz")
                .samples.push_back(bench::core_clock_hz());
            if (!o_.skip_load)
            {
                auto t = Clock::now();
                const Mesh loaded = io::read_mesh(file);
                const Mesh loaded_work = reorder_mesh(loaded, locality_order(loaded));
                [[maybe_unused]] const Topology loaded_topology = build_topology(loaded_work);
                figure("load + topology", n, order, "meshfair", "s")
                    .samples.push_back(seconds_since(t));
                t = Clock::now();
                bench::openmesh_read(file);
                figure("load + topology", n, order, "openmesh", "s")
                    .samples.push_back(seconds_since(t));
                t = Clock::now();
                tinyobj_load(file);
                figure("load (no topology)", n, order, "tinyobjloader", "s")
                    .samples.push_back(seconds_since(t));
            }
            figure("plain step", n, order, "meshfair", "s")
                .samples.push_back(time_steps(plain_session, work.positions));
            peer.set_positions(mesh.positions);
            auto t = Clock::now();
            peer.smooth(o_.steps);
            figure("plain step", n, order, "openmesh", "s")
                .samples.push_back(seconds_since(t) / o_.steps);
            figure("combined step", n, order, "meshfair", "s")
                .samples.push_back(time_steps(combined_session, work.positions));
            figure("combined step, 10% region", n, order, "meshfair", "s")
                .samples.push_back(time_steps(region_session, work.positions));
            figure("denoise.json step", n, order, "meshfair", "s")
                .samples.push_back(time_steps(denoise_session, work.positions));
            time_cli_loop(file, n, order);
        }
        const double bandwidth = figure("bandwidth (triad)", n, order, "machine", "B/s").median();
        figure("plain step bound", n, order, "machine", "s").samples = {plain_bytes / bandwidth};
        figure("combined step bound", n, order, "machine", "s").samples = {combined_bytes /
                                                                           bandwidth};
        print_order(n, order);
    }

    //! \brief The loop a batch user runs: meshfair-cli smooth's solve seconds (its report)
    //! with 0 and with 4 x --steps plain iterations. Their difference over the steps is the
    //! CLI's cost of a step, the bench's plain step as the CLI runs it (energies and all);
    //! the solve without steps is what a run costs once (the first and last energies, the
    //! positions put back in the file's order).
    void time_cli_loop(const std::string& file, Index n, const std::string& order)
    {
        if (o_.cli.empty())
            return;
        const int steps = 4 * o_.steps;
        const std::string out = file + "-cli.ply"; // binary: quick to write, not timed
        const double none = cli_solve_seconds(o_.cli, file, out, 0, o_.threads);
        const double some = cli_solve_seconds(o_.cli, file, out, steps, o_.threads);
        std::filesystem::remove(out);
        std::filesystem::remove(out + ".report.json");
        if (none < 0 || some < 0)
        {
            failures_.push_back("meshfair-cli smooth failed on " + file);
            return;
        }
        figure("CLI smooth, a step", n, order, "meshfair", "s")
            .samples.push_back((some - none) / steps);
        figure("CLI smooth, solve of 0 steps", n, order, "meshfair", "s").samples.push_back(none);
    }

    double time_steps(Session& session, const std::vector<Scalar>& start)
    {
        // As run() and meshfair-cli smooth step: on the session's kept positions.
        x_ = start;
        session.apply_hard_targets(x_);
        session.set_positions(x_);
        const auto t = Clock::now();
        for (int s = 0; s < o_.steps; ++s)
            session.step();
        return seconds_since(t) / o_.steps;
    }

    static void tinyobj_load(const std::string& file)
    {
        tinyobj::ObjReaderConfig config;
        config.triangulate = false;
        tinyobj::ObjReader reader;
        if (!reader.ParseFromFile(file, config))
            throw std::runtime_error("tinyobjloader could not read " + file + ": " +
                                     reader.Error());
    }

    void peak_rss(const Mesh& mesh, const std::string& stem)
    {
        if (o_.cli.empty())
            return;
        const std::string recipe_file = stem + "-combined.json";
        const std::string recipe_text = recipe_to_json(combined_recipe(std::nullopt)).dump(2);
        io::write_file_atomically(recipe_file, recipe_text + "\n");
        const double rss =
            cli_peak_rss(o_.cli, stem + ".obj", recipe_file, stem + "-smoothed.obj", o_.threads);
        if (rss < 0)
        {
            failures_.push_back("meshfair-cli smooth failed on " + stem + ".obj");
            return;
        }
        Figure& f = figure("peak RSS, CLI smooth (combined)", mesh.vertex_count(), "natural",
                           "meshfair", "B/vertex");
        f.samples = {rss / mesh.vertex_count()};
        std::printf(
            "   peak RSS of meshfair-cli smooth (combined recipe): %.0f MiB, %.1f bytes "
            "per vertex\n",
            rss / (1 << 20), f.samples[0]);
    }

    void print_row(const Figure& f, const std::string& note)
    {
        std::printf("   %-26s %-14s %s   [%s .. %s]%s\n", f.name.c_str(), f.implementation.c_str(),
                    format_value(f.median(), f.unit).c_str(), format_value(f.min(), f.unit).c_str(),
                    format_value(f.max(), f.unit).c_str(), note.c_str());
    }

    void print_order(Index n, const std::string& order)
    {
        const auto get = [&](const std::string& name, const std::string& impl) -> const Figure& {
            return figure(name, n, order, impl, "");
        };
        char note[160];
        print_row(get("bandwidth (triad)", "machine"), "");
        print_row(get("core clock", "machine"), "");
        // Cycles a thread spends per vertex of a step: step time x clock x threads / #V.
        const double clock = get("core clock", "machine").median();
        const auto cycles = [&](const Figure& f, int threads) {
            return f.median() * clock * threads / n;
        };
        if (!o_.skip_load)
        {
            const Figure& ours = get("load + topology", "meshfair");
            print_row(ours, "");
            const Figure& om = get("load + topology", "openmesh");
            std::snprintf(note, sizeof note, "  MeshFair %.2fx faster",
                          om.median() / ours.median());
            print_row(om, note);
            print_row(get("load (no topology)", "tinyobjloader"), "");
        }
        const Figure& plain = get("plain step", "meshfair");
        const double bound = get("plain step bound", "machine").median();
        std::snprintf(note, sizeof note, "  %.2fx the bound (%.3f ms); %.1f cycles/vertex",
                      plain.median() / bound, bound * 1e3, cycles(plain, omp_get_max_threads()));
        print_row(plain, note);
        const Figure& om = get("plain step", "openmesh");
        std::snprintf(note, sizeof note, "  MeshFair %.1fx faster; %.1f cycles/vertex",
                      om.median() / plain.median(), cycles(om, 1));
        print_row(om, note);
        if (!o_.cli.empty())
        {
            const Figure& cli = get("CLI smooth, a step", "meshfair");
            std::snprintf(note, sizeof note, "  %.2fx the plain step; OpenMesh's %.1fx it",
                          cli.median() / plain.median(), om.median() / cli.median());
            print_row(cli, note);
            print_row(get("CLI smooth, solve of 0 steps", "meshfair"), "");
        }
        const double combined_bound = get("combined step bound", "machine").median();
        for (const char* name : {"combined step", "combined step, 10% region"})
        {
            const Figure& c = get(name, "meshfair");
            std::snprintf(note, sizeof note,
                          "  %.2fx plain; %.2fx its bound (%.3f ms); %.1f cycles/vertex",
                          c.median() / plain.median(), c.median() / combined_bound,
                          combined_bound * 1e3, cycles(c, omp_get_max_threads()));
            print_row(c, note);
        }
        const Figure& denoise = get("denoise.json step", "meshfair");
        std::snprintf(note, sizeof note, "  %.2fx the combined step; %.2fx plain",
                      denoise.median() / get("combined step", "meshfair").median(),
                      denoise.median() / plain.median());
        print_row(denoise, note);
    }

    void write_tsv()
    {
        std::string text =
            "figure\tvertices\torder\timplementation\tunit\tmedian\tmin\tmax\tsamples\n";
        char line[512];
        for (const Figure& f : figures_)
        {
            std::snprintf(line, sizeof line, "%s\t%d\t%s\t%s\t%s\t%.9g\t%.9g\t%.9g\t%zu\n",
                          f.name.c_str(), f.vertices, f.order.c_str(), f.implementation.c_str(),
                          f.unit.c_str(), f.median(), f.min(), f.max(), f.samples.size());
            text += line;
        }
        io::write_file_atomically(o_.out, text);
    }

    Options o_;
    bench::TriadBandwidth triad_;
    std::deque<Figure> figures_; // deque: references to figures stay valid
    std::vector<std::string> failures_;
    std::vector<Scalar> x_;
};

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"meshfair-bench: MeshFair against OpenMesh and tinyobjloader, in one process"};
    Options o;
    o.cli = default_cli();
    app.add_option("--sizes", o.sizes, "minimum vertex counts of the subdivided meshes")
        ->delimiter(',')
        ->check(CLI::Range(1L, 500'000'000L));
    app.add_option("--reps", o.reps, "repetitions (medians are over these)")
        ->check(CLI::Range(1, 1000));
    app.add_option("--steps", o.steps, "solver steps per timing")->check(CLI::Range(1, 1000));
    app.add_option("--threads", o.threads, "threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--mesh", o.mesh, "triangle mesh to subdivide")->check(CLI::ExistingFile);
    app.add_option("--cache", o.cache, "directory of the generated meshes (kept between runs)");
    app.add_option("--out", o.out, "machine-readable results (TSV)");
    app.add_option("--cli", o.cli,
                   "meshfair-cli, for the CLI's step and peak-memory figures (empty: skip)");
    app.add_flag("--skip-load", o.skip_load, "do not time the readers");
    app.add_flag("--profile", o.profile,
                 "only run --steps plain and combined steps of MeshFair and OpenMesh on the "
                 "first size, for a profiler (app/bench/profile.sh)");
    CLI11_PARSE(app, argc, argv);
    if (o.threads > 0)
        omp_set_num_threads(o.threads); // the triad
    set_thread_count(o.threads);        // MeshFair's solver
    try
    {
        const bool profile = o.profile;
        Bench bench(std::move(o));
        return profile ? bench.profile() : bench.run();
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "meshfair-bench: %s\n", e.what());
        return 1;
    }
}
