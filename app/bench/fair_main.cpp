// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-bench-fair: the time to the minimizer of a fairing problem (a region with lifted
// pins, the paper's constrained edge energy), MeshFair's direct method and its Jacobi
// steps against CGAL's Polygon_mesh_processing::fair, in one process, repetitions
// interleaved, with each solver's peak memory measured in a process of its own. See
// docs/performance.md, "Time to the minimizer".
#include <fcntl.h>
#include <malloc.h>
#include <omp.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/bench/bench_common.h"
#include "app/bench/fair_case.h"
#include "app/bench/mesh_generator.h"
#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "core/parallel/parallel.h"
#include "core/recipe/locality_run.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/topology/topology.h"
#include "core/topology/vertex_order.h"

#if MESHFAIR_HAVE_CGAL
#include "app/bench/cgal_fair_peer.h"
#endif

extern char** environ;

namespace {

using namespace meshfair;
using Clock = std::chrono::steady_clock;
using bench::default_cli;
using bench::human_count;
using bench::seconds_since;
using bench::self_path;

//! CPU seconds of every thread of this process so far (user + system).
double cpu_seconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

//! A figure's samples, one per repetition (or one in all).
struct Samples
{
    std::string name;
    Index vertices = 0; //!< the mesh's
    std::string unit;   //!< "s" (seconds), "B" (bytes), "B/vertex", "steps", "" (a number)
    std::vector<double> values;

    double median() const { return bench::median(values); }
    double min() const { return *std::min_element(values.begin(), values.end()); }
    double max() const { return *std::max_element(values.begin(), values.end()); }
};

struct Options
{
    std::vector<long> sizes{30'000, 1'000'000};
    int reps = 3;
    int threads = 0;
    std::string mesh = MESHFAIR_DEFAULT_MESH;
    std::string cache = "bench-meshes";
    std::string out = "bench-fair-results.tsv";
    std::string cli;
    int jacobi_steps = 20'000;
    double jacobi_seconds = 60;
    int jacobi_check = 100;
    double jacobi_goal = 1e-6;
    long cgal_max_vertices = 2'000'000;
    bool cgal_cotangent = false;
    bool skip_memory = false;
    // A process of its own that runs one solver once and reports its peak memory.
    std::string peak_memory_of;
    std::string child_mesh, child_recipe, child_report;
};

std::string format_value(double v, const std::string& unit)
{
    char buffer[64];
    if (unit == "s")
        std::snprintf(buffer, sizeof buffer, "%11.2f ms", v * 1e3);
    else if (unit == "B")
        std::snprintf(buffer, sizeof buffer, "%10.1f MiB", v / (1 << 20));
    else if (unit == "B/vertex")
        std::snprintf(buffer, sizeof buffer, "%12.0f B/v", v);
    else if (unit == "steps")
        std::snprintf(buffer, sizeof buffer, "%14.0f", v);
    else
        std::snprintf(buffer, sizeof buffer, "%14.3g", v);
    return buffer;
}

//! The largest |a_i - b_i| over the vertices (3 values each).
Scalar max_distance(std::span<const Scalar> a, std::span<const Scalar> b)
{
    Scalar worst = 0;
    for (size_t i = 0; i + 2 < a.size(); i += 3)
    {
        const Scalar dx = a[i] - b[i], dy = a[i + 1] - b[i + 1], dz = a[i + 2] - b[i + 2];
        worst = std::max(worst, dx * dx + dy * dy + dz * dz);
    }
    return std::sqrt(worst);
}

#if MESHFAIR_HAVE_CGAL
//! The positions with the pins moved to their targets (the hard section's).
std::vector<Scalar> with_targets(const Mesh& mesh, const Recipe& recipe)
{
    std::vector<Scalar> x = mesh.positions;
    if (recipe.hard)
        for (size_t k = 0; k < recipe.hard->targets.size(); ++k)
            for (int a = 0; a < 3; ++a)
                x[3 * static_cast<size_t>(recipe.hard->vertices[k]) + a] =
                    recipe.hard->targets[k][a];
    return x;
}
#endif

//! Runs `args` (args[0] the program) with stdout to /dev/null; true when it exits with 0.
bool run_program(std::vector<std::string> args)
{
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, args[0].c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    int status = 0;
    return spawned == 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
           WEXITSTATUS(status) == 0;
}

//! The BLAS library this process has loaded (CHOLMOD's, once it factored), by its path.
std::string loaded_blas()
{
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line))
        if (const size_t at = line.find('/');
            at != std::string::npos && (line.find("libblas") != std::string::npos ||
                                        line.find("libopenblas") != std::string::npos))
            return std::filesystem::canonical(line.substr(at)).string();
    return "none loaded";
}

//! \brief A process's peak memory stage by stage: at the end of each stage its high-water
//! mark is read, then reset to the current resident set (Linux's clear_refs "5"), so the
//! next stage's peak is its own. ru_maxrss cannot be reset, and a forked child's would
//! include its parent's memory: these processes are spawned, and read their own.
class StagePeaks
{
public:
    //! Ends a stage: report[name] holds its peak and the resident set it started from.
    void end_stage(const std::string& name, nlohmann::json& report)
    {
        const double peak = bench::status_bytes("VmHWM:");
        process_peak_ = std::max(process_peak_, peak);
        report[name] = {{"peak_bytes", peak}, {"start_bytes", stage_start_}};
        // Where the reset is refused, the next stage's peak is the process's so far.
        report[name]["reset"] = bench::reset_peak_memory();
        stage_start_ = bench::status_bytes("VmRSS:");
    }
    double process_peak() const { return process_peak_; }

private:
    double process_peak_ = 0;
    double stage_start_ = bench::status_bytes("VmRSS:");
};

//! \brief The child's side of the peak-memory figures: loads the mesh and the recipe (in
//! the file's numbering), then runs one solver once as a user would, and reports the peak
//! of each stage and of the process. "none" only loads: the baseline.
int peak_memory_child(const Options& o)
{
    // meshfair-cli's allocator setting, for every solver: each block of 1 MiB or more a
    // mapping of its own, returned when freed (glibc's default threshold rises with the
    // blocks freed, and freed arrays then stay resident beside the solver's).
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    const auto t = Clock::now();
    StagePeaks peaks;
    nlohmann::json report;
    Mesh mesh = io::read_mesh(o.child_mesh);
    Recipe recipe = read_recipe(o.child_recipe);
    const std::string& solver = o.peak_memory_of;
    if (solver == "direct" || solver == "jacobi")
    {
        peaks.end_stage("load", report);
        if (solver == "jacobi")
        {
            recipe.method = Method::Jacobi;
            recipe.lambda = 1;
            recipe.iterations = 100;
            recipe.tolerance = 0;
        }
        // As meshfair-cli smooth runs it: the mesh renumbered in place, its topology, the
        // session (the factorization), the hard vertices at their targets.
        LocalityRun run(std::move(mesh), recipe);
        const SmoothResult result = meshfair::run(run.session());
        report["iterations"] = result.iterations;
        peaks.end_stage("solve", report);
    }
    else if (solver == "cgal")
    {
#if MESHFAIR_HAVE_CGAL
        // The load is CGAL's halfedge mesh with the pins at their targets; MeshFair's mesh,
        // read first, is freed (a CGAL user holds the Surface_mesh only).
        const bench::FairCase fair_case{recipe.region->vertices, recipe.hard->vertices, {}, {}, 0};
        std::optional<bench::CgalFairPeer> peer;
        {
            const std::vector<Scalar> start = with_targets(mesh, recipe);
            peer.emplace(mesh);
            peer->set_positions(start);
            mesh = Mesh{};
        }
        const std::vector<Index> unknowns = fair_case.free_vertices();
        peaks.end_stage("load", report);
        if (!peer->fair(unknowns, bench::CgalFairWeights::Uniform))
            throw std::runtime_error("CGAL's fair failed");
        peaks.end_stage("solve", report);
#else
        throw std::runtime_error("built without CGAL (MESHFAIR_BENCH_CGAL)");
#endif
    }
    else if (solver == "none")
        peaks.end_stage("load", report);
    else
        throw std::runtime_error("--peak-memory-of: unknown solver " + solver);
    report["peak_memory_bytes"] = peaks.process_peak();
    report["seconds"] = seconds_since(t);
    io::write_file_atomically(o.child_report, report.dump() + "\n");
    return 0;
}

class FairBench
{
public:
    explicit FairBench(Options options) : o_(std::move(options)) {}

    int run()
    {
        std::filesystem::create_directories(o_.cache);
        const Mesh base = io::read_mesh(o_.mesh);
        std::printf(
            "meshfair-bench-fair: %d thread(s), %d repetitions, base mesh %s (%s vertices), "
            "CGAL %s\n",
            omp_get_max_threads(), o_.reps, o_.mesh.c_str(),
            human_count(base.vertex_count()).c_str(), have_cgal ? "built" : "not built");
        for (const long size : o_.sizes)
            run_size(base, size);
        write_tsv();
        std::printf("\nBLAS: %s\nresults: %s\n", loaded_blas().c_str(), o_.out.c_str());
        if (!failures_.empty())
        {
            for (const std::string& f : failures_)
                std::fprintf(stderr, "meshfair-bench-fair: FAILED: %s\n", f.c_str());
            return 1;
        }
        return 0;
    }

private:
#if MESHFAIR_HAVE_CGAL
    static constexpr bool have_cgal = true;
#else
    static constexpr bool have_cgal = false;
#endif

    Samples& figure(const std::string& name, const std::string& unit)
    {
        for (Samples& s : figures_)
            if (s.name == name && s.vertices == current_vertices_)
                return s;
        figures_.push_back(Samples{name, current_vertices_, unit, {}});
        return figures_.back();
    }

    void run_size(const Mesh& base, long size)
    {
        const int k = bench::subdivision_factor_for(base, size);
        const Mesh mesh = k == 1 ? base : bench::subdivide_triangles(base, k);
        const Index n = mesh.vertex_count();
        current_vertices_ = n;
        // Children and meshfair-cli read the mesh from a file: the bunny's own, or the
        // subdivision in meshfair-bench's cache (the same file name, reused).
        const std::string stem = o_.cache + "/bunny-" + std::to_string(k) + "x-natural";
        const std::string file = k == 1 ? o_.mesh : stem + ".obj";
        if (k > 1 && !std::filesystem::exists(file))
            io::write_mesh(mesh, file);

        const bench::FairCase fair_case = bench::make_fair_case(mesh, base.vertex_count());
        const std::vector<Index> free_file = fair_case.free_vertices();
        std::printf(
            "\n== %s vertices (the bunny subdivided %d-fold): region %s, %s unknowns, %zu pins "
            "lifted by %.0f %% of the diagonal (%.4g), then %.0f %%\n",
            human_count(n).c_str(), k,
            human_count(static_cast<long>(fair_case.region.size())).c_str(),
            human_count(static_cast<long>(free_file.size())).c_str(), fair_case.pins.size(),
            bench::FairCaseShape{}.first_lift * 100, fair_case.diagonal,
            bench::FairCaseShape{}.second_lift * 100);

        const Recipe direct_file = fair_recipe(fair_case, fair_case.first_targets, Method::Direct);
        measure_times(mesh, fair_case, direct_file);
        if (!o_.skip_memory)
        {
            const std::string recipe_file = stem + "-fair.json";
            io::write_file_atomically(recipe_file, recipe_to_json(direct_file).dump() + "\n");
            measure_memory(file, recipe_file, stem, n);
        }
        print_size(n);
    }

    //! \brief The timed repetitions: in each, MeshFair's direct method (its first result,
    //! then a re-solve for moved pins), its conjugate gradients, its Jacobi steps toward the
    //! direct result, and CGAL's fair, in this order.
    void measure_times(const Mesh& mesh, const bench::FairCase& fair_case,
                       const Recipe& direct_file)
    {
        const Index n = mesh.vertex_count();
        const Scalar diagonal = fair_case.diagonal;
        // What every solver starts from: the load, MeshFair's locality numbering and its
        // topology, CGAL's halfedge mesh. Timed once; not part of a result's time.
        auto t = Clock::now();
        const LocalityOrder order = locality_order(mesh);
        const Mesh work = reorder_mesh(mesh, order);
        const Recipe direct = renumber_recipe(direct_file, order.vertex_index, order.face_index);
        const Topology topology = build_topology(work, required_topology(direct));
        figure("MeshFair: locality numbering + topology", "s").values = {seconds_since(t)};
        Recipe jacobi = direct;
        jacobi.method = Method::Jacobi;
        // The undamped step, x_i <- the mean of its neighbours: on the slowest modes, which
        // decide the steps to the minimizer, twice as fast as the default 0.5.
        jacobi.lambda = 1;
        const std::vector<Scalar> second_targets = bench::FairCase::flat(fair_case.second_targets);
        const std::vector<Scalar> first_targets = bench::FairCase::flat(fair_case.first_targets);
        std::vector<Scalar> start(work.positions);
        // The measure of every result: |r| and the Jacobi displacement at the free vertices,
        // with the pins at their first targets.
        Session checker(work, topology, jacobi);
        checker.apply_hard_targets(start);
        [[maybe_unused]] const Scalar start_gradient = checker.residual(start).gradient;
#if MESHFAIR_HAVE_CGAL
        const bool cgal = n <= o_.cgal_max_vertices;
        std::optional<bench::CgalFairPeer> peer;
        const std::vector<Index> free_file = fair_case.free_vertices();
        const std::vector<Scalar> start_file = with_targets(mesh, direct_file);
        if (cgal)
        {
            t = Clock::now();
            peer.emplace(mesh);
            figure("CGAL: Surface_mesh", "s").values = {seconds_since(t)};
        }
        else
            std::printf("   CGAL's fair not run above %s vertices (--cgal-max-vertices)\n",
                        human_count(o_.cgal_max_vertices).c_str());
#endif
        std::vector<Scalar> minimizer; // the direct method's first result (solver numbering)
        std::optional<Session> session;
        for (int rep = 0; rep < o_.reps; ++rep)
        {
            // 1. MeshFair direct, as a library user runs it: the session (analysis and
            // factorization), the pins at their targets, run() to the tolerance.
            session.reset();
            Recipe recipe = direct;
            recipe.iterations = 3;
            recipe.tolerance = 1e-9;
            t = Clock::now();
            double cpu = cpu_seconds();
            session.emplace(work, topology, recipe);
            const double precomputation = seconds_since(t);
            std::vector<Scalar> x = work.positions;
            session->apply_hard_targets(x);
            session->adopt_positions(std::move(x));
            const SmoothResult result = meshfair::run(*session);
            const double first = seconds_since(t);
            cpu = cpu_seconds() - cpu;
            const FactorStats& stats = session->factorization()->stats();
            figure("MeshFair direct: first result", "s").values.push_back(first);
            figure("MeshFair direct: precomputation (the session)", "s")
                .values.push_back(precomputation);
            figure("MeshFair direct: analyse", "s").values.push_back(stats.analyse_seconds);
            figure("MeshFair direct: factor", "s").values.push_back(stats.factor_seconds);
            figure("MeshFair direct: first result, CPU / wall", "ratio")
                .values.push_back(cpu / first);
            figure("MeshFair direct: steps", "steps").values.push_back(result.iterations);
            figure("MeshFair direct: relative gradient", "")
                .values.push_back(result.gradients.back());
            figure("MeshFair direct: Jacobi displacement / diagonal", "")
                .values.push_back(result.jacobi_displacement / diagonal);
            // A supernodal factor holds a value per nonzero and row indices per supernode,
            // not per nonzero: its size is about 8 B a nonzero (FactorStats::factor_bytes
            // counts 16).
            figure("MeshFair direct: factor values (8 B a nonzero)", "B/vertex").values = {
                8 * stats.factor_nonzeros / n};
            figure("MeshFair direct: factor nonzeros", "").values = {stats.factor_nonzeros};
            figure("MeshFair direct: unknowns", "").values = {
                static_cast<double>(session->factorization()->size())};
            if (rep == 0)
                minimizer.assign(session->positions().begin(), session->positions().end());

            // The pins move again (a drag): new targets, the same factorization.
            t = Clock::now();
            session->set_hard_targets(second_targets);
            x = session->release_positions();
            session->apply_hard_targets(x);
            session->adopt_positions(std::move(x));
            const StepInfo resolve = session->step();
            figure("MeshFair direct: re-solve", "s").values.push_back(seconds_since(t));
            const Session::Residual after = session->residual(session->positions());
            figure("MeshFair direct: re-solve relative gradient", "")
                .values.push_back(after.gradient / resolve.gradient);
            figure("MeshFair direct: re-solve Jacobi displacement / diagonal", "")
                .values.push_back(after.jacobi_displacement / diagonal);
            if (session->precompute_count() != 1)
                failures_.push_back("the re-solve precomputed again (" +
                                    std::to_string(session->precompute_count()) + " times)");
            if (!(result.gradients.back() <= 1e-9))
                failures_.push_back("the direct method stopped at a relative gradient of " +
                                    std::to_string(result.gradients.back()));

            // A pin drag, as the editor's M tool and a script's Session move pins: each
            // move's minimizer followed from the last one's (Session::follow_pins: the
            // first move of this group of pins solves for its response, later ones reuse
            // it). Two more moves by the step from the first targets to the second.
            for (int move = 1; move <= 2; ++move)
            {
                std::vector<Scalar> targets = second_targets;
                for (size_t k = 0; k < targets.size(); ++k)
                    targets[k] += move * (second_targets[k] - first_targets[k]);
                t = Clock::now();
                session->move_pins(targets);
                const bool followed = session->follow_pins();
                const double seconds = seconds_since(t);
                figure(move == 1 ? "MeshFair direct: pin drag, first move (its response solved)"
                                 : "MeshFair direct: pin drag, next move (the response kept)",
                       "s")
                    .values.push_back(seconds);
                const Session::Residual at = session->residual(session->positions());
                figure("MeshFair direct: pin drag, relative gradient", "")
                    .values.push_back(at.gradient / resolve.gradient);
                if (!followed)
                    failures_.push_back("the pin drag's minimizer was not followed");
            }

            // What a weight's slider costs: the recipe set again (this case's only weight is
            // the edge term's, 1; a factorization costs the same whatever the values), the
            // same pattern, so the session factors again on the analysis it keeps, then
            // solves.
            t = Clock::now();
            session->set_recipe(recipe);
            x = session->release_positions(); // the pins back at the recipe's targets
            session->apply_hard_targets(x);
            session->adopt_positions(std::move(x));
            const SmoothResult reweighted = meshfair::run(*session);
            figure("MeshFair direct: the recipe set again (analysis kept), to the result", "s")
                .values.push_back(seconds_since(t));
            if (session->factorization()->stats().factorizations != 2 ||
                !(reweighted.gradients.back() <= 1e-9))
                failures_.push_back(
                    "the recipe set again did not keep the analysis (" +
                    std::to_string(session->factorization()->stats().factorizations) +
                    " factorizations on it), or stopped at a relative gradient of " +
                    std::to_string(reweighted.gradients.back()));
            session.reset();

            // 2. MeshFair's conjugate gradients (no factor), to the same tolerance.
            cg_run(work, topology, direct, minimizer, diagonal);

            // 3. MeshFair Jacobi from the same start, toward the direct result.
            jacobi_run(work, topology, jacobi, minimizer, diagonal);

#if MESHFAIR_HAVE_CGAL
            // 4. CGAL's fair on the unknowns, the pins already at their targets.
            if (cgal)
            {
                cgal_run(*peer, bench::CgalFairWeights::Uniform, "CGAL fair (uniform weights)",
                         start_file, free_file, order, minimizer, checker, start_gradient, diagonal,
                         rep);
                if (o_.cgal_cotangent)
                    cgal_run(*peer, bench::CgalFairWeights::Cotangent,
                             "CGAL fair (cotangent weights)", start_file, free_file, order,
                             minimizer, checker, start_gradient, diagonal, rep);
            }
#endif
            std::printf("   repetition %d of %d done\n", rep + 1, o_.reps);
            std::fflush(stdout);
        }
    }

    //! \brief Conjugate gradients (preconditioned by the paper's Jacobi blocks) as a library
    //! user runs them: the session (the matrix, no factor), run() to the tolerance.
    void cg_run(const Mesh& work, const Topology& topology, const Recipe& direct,
                const std::vector<Scalar>& minimizer, Scalar diagonal)
    {
        Recipe recipe = direct;
        recipe.method = Method::ConjugateGradient;
        recipe.iterations = 3;
        recipe.tolerance = 1e-9;
        const auto t = Clock::now();
        Session session(work, topology, recipe);
        std::vector<Scalar> x = work.positions;
        session.apply_hard_targets(x);
        session.adopt_positions(std::move(x));
        const SmoothResult result = meshfair::run(session);
        figure("MeshFair CG: first result", "s").values.push_back(seconds_since(t));
        int iterations = 0;
        for (const int n : result.inner_iterations)
            iterations += n;
        figure("MeshFair CG: iterations", "steps").values.push_back(iterations);
        figure("MeshFair CG: relative gradient", "").values.push_back(result.gradients.back());
        figure("MeshFair CG: distance to the direct result / diagonal", "")
            .values.push_back(max_distance(session.positions(), minimizer) / diagonal);
        if (!(result.gradients.back() <= 1e-9))
            failures_.push_back("conjugate gradients stopped at a relative gradient of " +
                                std::to_string(result.gradients.back()));
    }

    void jacobi_run(const Mesh& work, const Topology& topology, const Recipe& recipe,
                    const std::vector<Scalar>& minimizer, Scalar diagonal)
    {
        auto t = Clock::now();
        Session jacobi(work, topology, recipe);
        std::vector<Scalar> x = work.positions;
        jacobi.apply_hard_targets(x);
        jacobi.adopt_positions(std::move(x));
        double seconds = seconds_since(t);
        const Scalar goal = o_.jacobi_goal * diagonal;
        // (steps, distance) at each check, for the rate of the last stretch.
        std::vector<std::pair<int, Scalar>> checks{
            {0, max_distance(jacobi.positions(), minimizer)}};
        int steps = 0;
        while (checks.back().second > goal && steps < o_.jacobi_steps &&
               seconds < o_.jacobi_seconds)
        {
            const int chunk = std::min(o_.jacobi_check, o_.jacobi_steps - steps);
            t = Clock::now();
            for (int s = 0; s < chunk; ++s)
                jacobi.step();
            seconds += seconds_since(t);
            steps += chunk;
            checks.emplace_back(steps, max_distance(jacobi.positions(), minimizer));
        }
        figure("MeshFair Jacobi (lambda 1): steps", "steps").values.push_back(steps);
        figure("MeshFair Jacobi (lambda 1): time", "s").values.push_back(seconds);
        figure("MeshFair Jacobi (lambda 1): distance to the minimizer / diagonal", "")
            .values.push_back(checks.back().second / diagonal);
        // The steps still needed at the rate of the last half of the run: a lower bound
        // in practice, as the rate slows when the slowest modes are left.
        const auto& [k1, d1] = checks.back();
        const auto& [k0, d0] = checks[checks.size() / 2];
        if (d1 > goal && k1 > k0 && d1 < d0)
        {
            const double rate = std::log(d1 / d0) / (k1 - k0);
            figure("MeshFair Jacobi (lambda 1): steps to the goal, extrapolated", "steps")
                .values.push_back(k1 + std::log(goal / d1) / rate);
        }
    }

#if MESHFAIR_HAVE_CGAL
    void cgal_run(bench::CgalFairPeer& peer, bench::CgalFairWeights weights,
                  const std::string& name, const std::vector<Scalar>& start_file,
                  const std::vector<Index>& free_file, const LocalityOrder& order,
                  const std::vector<Scalar>& minimizer, Session& checker, Scalar start_gradient,
                  Scalar diagonal, int rep)
    {
        peer.set_positions(start_file);
        const auto t = Clock::now();
        double cpu = cpu_seconds();
        const bool ok = peer.fair(free_file, weights);
        const double seconds = seconds_since(t);
        cpu = cpu_seconds() - cpu;
        if (!ok)
        {
            failures_.push_back(name + " failed");
            return;
        }
        figure(name, "s").values.push_back(seconds);
        figure(name + ", CPU / wall", "ratio").values.push_back(cpu / seconds);
        if (rep != 0)
            return;
        // Its result in the solver's numbering, measured as MeshFair's own.
        const std::vector<Scalar> file = peer.positions();
        std::vector<Scalar> internal(file.size());
        for (size_t k = 0; k < order.vertex_order.size(); ++k)
            for (int a = 0; a < 3; ++a)
                internal[3 * k + a] = file[3 * static_cast<size_t>(order.vertex_order[k]) + a];
        figure(name + ": distance to MeshFair's direct result / diagonal", "").values = {
            max_distance(internal, minimizer) / diagonal};
        const Session::Residual r = checker.residual(internal);
        figure(name + ": relative gradient (MeshFair's energy)", "").values = {r.gradient /
                                                                               start_gradient};
        figure(name + ": Jacobi displacement / diagonal", "").values = {r.jacobi_displacement /
                                                                        diagonal};
    }
#endif

    //! \brief Each solver's peak memory, in a process of its own that reads the mesh file
    //! and the recipe and runs the solver once (a forked child's ru_maxrss would include
    //! this process's memory; these report their own high-water mark, VmHWM); "none"
    //! only reads them. Then meshfair-cli smooth with the recipe, as a user runs it.
    void measure_memory(const std::string& file, const std::string& recipe_file,
                        const std::string& stem, Index n)
    {
        std::vector<std::string> solvers = {"none", "direct", "jacobi"};
        if (have_cgal && n <= o_.cgal_max_vertices)
            solvers.push_back("cgal");
        const std::string self = self_path();
        for (const std::string& solver : solvers)
        {
            const std::string report = stem + "-peak-" + solver + ".json";
            std::vector<std::string> args = {
                self,        "--peak-memory-of", solver, "--child-mesh", file, "--child-recipe",
                recipe_file, "--child-report",   report};
            if (o_.threads > 0)
                args.insert(args.end(), {"--threads", std::to_string(o_.threads)});
            const auto t = Clock::now();
            if (!run_program(args))
            {
                failures_.push_back("the peak-memory process of " + solver + " failed");
                continue;
            }
            const nlohmann::json json = nlohmann::json::parse(io::read_file(report));
            std::filesystem::remove(report);
            const double peak = json["peak_memory_bytes"].get<double>();
            figure("peak memory: " + solver + " (process)", "B").values = {peak};
            if (json.contains("solve") && json["load"]["reset"].get<bool>())
                figure("peak memory: " + solver + ", solving beyond the loaded mesh", "B")
                    .values = {json["solve"]["peak_bytes"].get<double>() -
                               json["solve"]["start_bytes"].get<double>()};
            std::printf("   peak memory of %-6s %8.1f MiB (its process: %.1f s)\n", solver.c_str(),
                        peak / (1 << 20), seconds_since(t));
            std::fflush(stdout);
        }
        if (o_.cli.empty())
            return;
        const std::string out = stem + "-fair-cli.ply";
        const std::string report = out + ".report.json";
        std::vector<std::string> args = {o_.cli,     "smooth",    file,       "-o",   out,
                                         "--recipe", recipe_file, "--report", report, "--quiet"};
        if (o_.threads > 0)
            args.insert(args.end(), {"--threads", std::to_string(o_.threads)});
        const bool ok = run_program(args);
        if (!ok)
        {
            failures_.push_back("meshfair-cli smooth --recipe " + recipe_file + " failed");
            return;
        }
        const nlohmann::json json = nlohmann::json::parse(io::read_file(report));
        std::filesystem::remove(out);
        std::filesystem::remove(report);
        figure("peak memory: meshfair-cli smooth, direct (process)", "B").values = {
            json["peak_memory_bytes"].get<double>()};
        figure("meshfair-cli smooth (direct): solve", "s").values = {
            json["seconds"]["solve"].get<double>()};
        figure("meshfair-cli smooth (direct): setup", "s").values = {
            json["seconds"]["setup"].get<double>()};
    }

    void print_row(const Samples& s, const std::string& note = "")
    {
        if (s.values.size() > 1)
            std::printf("   %-62s %s  [%s .. %s]%s\n", s.name.c_str(),
                        format_value(s.median(), s.unit).c_str(),
                        format_value(s.min(), s.unit).c_str(),
                        format_value(s.max(), s.unit).c_str(), note.c_str());
        else
            std::printf("   %-62s %s%s\n", s.name.c_str(), format_value(s.median(), s.unit).c_str(),
                        note.c_str());
    }

    void print_size(Index n)
    {
        std::printf("\n");
        char note[160];
        const Samples* direct = nullptr;
        const Samples* cgal = nullptr;
        for (const Samples& s : figures_)
            if (s.vertices == n)
            {
                if (s.name == "MeshFair direct: first result")
                    direct = &s;
                if (s.name == "CGAL fair (uniform weights)")
                    cgal = &s;
            }
        for (const Samples& s : figures_)
        {
            if (s.vertices != n)
                continue;
            note[0] = 0;
            if (&s == cgal && direct)
                std::snprintf(note, sizeof note, "   MeshFair direct faster by %.2fx",
                              cgal->median() / direct->median());
            if (s.unit == "B")
                std::snprintf(note, sizeof note, "   %7.0f B/vertex", s.median() / n);
            print_row(s, note);
        }
        std::fflush(stdout);
    }

    void write_tsv()
    {
        std::string text = "figure\tvertices\tunit\tmedian\tmin\tmax\tsamples\n";
        char line[512];
        for (const Samples& s : figures_)
        {
            std::snprintf(line, sizeof line, "%s\t%d\t%s\t%.9g\t%.9g\t%.9g\t%zu\n", s.name.c_str(),
                          s.vertices, s.unit.c_str(), s.median(), s.min(), s.max(),
                          s.values.size());
            text += line;
        }
        io::write_file_atomically(o_.out, text);
    }

    Options o_;
    std::deque<Samples> figures_; // deque: references to figures stay valid
    Index current_vertices_ = 0;
    std::vector<std::string> failures_;
};

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{
        "meshfair-bench-fair: time to the minimizer of a region with lifted pins, "
        "MeshFair against CGAL's fair"};
    Options o;
    o.cli = default_cli();
    app.add_option("--sizes", o.sizes,
                   "minimum vertex counts of the subdivided bunnies (the bunny itself for "
                   "sizes up to its own)")
        ->delimiter(',')
        ->check(CLI::Range(1L, 500'000'000L));
    app.add_option("--reps", o.reps, "repetitions (medians are over these)")
        ->check(CLI::Range(1, 1000));
    app.add_option("--threads", o.threads, "MeshFair's threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--mesh", o.mesh, "triangle mesh to subdivide (y up)")->check(CLI::ExistingFile);
    app.add_option("--cache", o.cache, "directory of the generated meshes (kept between runs)");
    app.add_option("--out", o.out, "machine-readable results (TSV)");
    app.add_option("--cli", o.cli, "meshfair-cli, for its peak memory (empty: skip)");
    app.add_option("--jacobi-steps", o.jacobi_steps, "most Jacobi steps a repetition")
        ->check(CLI::Range(0, 100'000'000));
    app.add_option("--jacobi-seconds", o.jacobi_seconds,
                   "most seconds of Jacobi steps a repetition")
        ->check(CLI::Range(0.0, 1e6));
    app.add_option("--jacobi-check", o.jacobi_check, "Jacobi steps between distance checks")
        ->check(CLI::Range(1, 1'000'000));
    app.add_option("--jacobi-goal", o.jacobi_goal,
                   "distance to the direct result, over the diagonal, that ends the Jacobi steps")
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--cgal-max-vertices", o.cgal_max_vertices,
                   "largest mesh CGAL's fair runs on (it takes about 5 KB a vertex)");
    app.add_flag("--cgal-cotangent", o.cgal_cotangent,
                 "also time CGAL's fair with its default (cotangent) weights");
    app.add_flag("--skip-memory", o.skip_memory, "do not measure the peak memories");
    app.add_option("--peak-memory-of", o.peak_memory_of,
                   "(internal) run one solver once and report its peak memory: "
                   "none|direct|jacobi|cgal");
    app.add_option("--child-mesh", o.child_mesh, "(internal) the mesh of --peak-memory-of");
    app.add_option("--child-recipe", o.child_recipe, "(internal) the recipe of --peak-memory-of");
    app.add_option("--child-report", o.child_report, "(internal) where it writes its report");
    CLI11_PARSE(app, argc, argv);
    set_thread_count(o.threads);
    try
    {
        if (!o.peak_memory_of.empty())
            return peak_memory_child(o);
        FairBench bench(std::move(o));
        return bench.run();
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "meshfair-bench-fair: %s\n", e.what());
        return 1;
    }
}
