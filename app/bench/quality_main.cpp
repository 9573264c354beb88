// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-quality: denoising quality as the mesh-denoising literature measures it (mean
// normal angle, vertex distance to the clean surface, volume change, seams at a region's
// border), of MeshFair's recipes run through the product path (read_recipe, smooth) and of
// two reference filters written in app/bench/reference_filters.cpp, on the generated meshes
// of app/bench/quality_meshes.h and the bundled bunny, under the noise models of
// app/bench/quality_noise.h. One run, seeded: the same numbers on every machine.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/bench/quality_meshes.h"
#include "app/bench/quality_metrics.h"
#include "app/bench/quality_noise.h"
#include "app/bench/reference_filters.h"
#include "app/bench/sdfilter_peer.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/geometry/noise_estimate.h"
#include "core/io/io.h"
#include "core/parallel/parallel.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/topology/topology.h"

namespace {

using namespace meshfair;
using namespace meshfair::bench;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr Scalar kNaN = std::numeric_limits<Scalar>::quiet_NaN();

struct Options
{
    std::vector<std::string> recipes; //!< name=path; empty: assets/recipes/*.json
    std::vector<std::string> meshes;  //!< empty: all (quick: cube)
    std::string bunny = MESHFAIR_DEFAULT_MESH;
    std::string out = "quality-results.tsv";
    std::string markdown;
    std::string write_meshes;
    std::string denoise_preset = "denoise";
    std::string organic_preset = "denoise-organic";
    int taubin_pairs = TaubinSettings{}.pairs;
    Scalar bilateral_sigma_r = BilateralSettings{}.sigma_r;
    std::uint64_t seed = 1;
    int threads = 0;
    bool quick = false;
    bool skip_sdfilter = false;
};

struct NamedRecipe
{
    std::string name;
    Recipe recipe;
};

//! One line of the results: a method on one noisy mesh.
struct Row
{
    std::string mesh, noise;
    Scalar level = 0;
    std::string method;
    Scalar theta_deg = kNaN, ev = kNaN, dv_percent = kNaN, seconds = kNaN;
    Index turned = 0; //!< faces turned over against the noisy mesh it was given
    //! The run's own volume change: against the noisy mesh it was given, in %
    Scalar dv_run_percent = kNaN;
    //! Of the noisy mesh only: the noise estimate_noise finds in it, in mean edge lengths
    Scalar estimated_sigma = kNaN;
    std::string note; //!< "refused: why" when the recipe did not fit the mesh
};

//! One line of the seam table.
struct SeamRow
{
    std::string what; //!< "bunny experiment" or "mesh noise level"
    std::string method;
    SeamFigure figure;
    std::string note;
    Scalar dv_percent = std::numeric_limits<Scalar>::quiet_NaN(); //!< of the whole mesh
};

struct MeshInfo
{
    std::string name;
    Index vertices = 0, faces = 0;
    Scalar mean_edge = 0;
    bool is_closed = false, is_quads = false;
    Index loops = 0; //!< boundary loops (capped for the volume of an open mesh)
};

std::string format(const char* spec, double v)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, spec, v);
    return buffer;
}

std::string level_name(Scalar level)
{
    return format("%.1f", level);
}

//! FNV-1a of the base seed and the case's name: each mesh and case has its own stream.
std::uint64_t case_seed(std::uint64_t base, const std::string& name)
{
    std::uint64_t h = 14695981039346656037ull ^ base;
    for (const unsigned char c : name)
        h = (h ^ c) * 1099511628211ull;
    return h;
}

std::vector<NamedRecipe> load_recipes(const Options& o)
{
    std::vector<std::pair<std::string, std::string>> specs; // name, path
    if (o.recipes.empty())
    {
        for (const auto& entry : fs::directory_iterator(MESHFAIR_RECIPES_DIR))
            if (entry.path().extension() == ".json")
                specs.emplace_back(entry.path().stem().string(), entry.path().string());
        std::sort(specs.begin(), specs.end());
    }
    for (const std::string& spec : o.recipes)
    {
        const size_t eq = spec.find('=');
        if (eq == std::string::npos)
            specs.emplace_back(fs::path(spec).stem().string(), spec);
        else
            specs.emplace_back(spec.substr(0, eq), spec.substr(eq + 1));
    }
    std::vector<NamedRecipe> recipes;
    std::set<std::string> names{"noisy", "bilateral", "taubin"};
    for (const auto& [name, path] : specs)
    {
        if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQ"
                                                   "RSTUVWXYZ0123456789_.-") != std::string::npos)
            throw InvalidInputError("--recipe '" + name + "=" + path +
                                    "': a name is letters, digits, '_', '.' or '-'");
        if (!names.insert(name).second)
            throw InvalidInputError("--recipe: the name '" + name + "' is taken");
        try
        {
            recipes.push_back({name, read_recipe(path)});
        }
        catch (const InvalidInputError& e)
        {
            throw InvalidInputError("recipe '" + name + "': " + e.what());
        }
    }
    return recipes;
}

std::vector<std::string> mesh_names(const Options& o)
{
    std::vector<std::string> known = generated_mesh_names();
    known.push_back("bunny");
    if (o.meshes.empty())
        return o.quick ? std::vector<std::string>{"cube"} : known;
    for (const std::string& name : o.meshes)
        if (std::find(known.begin(), known.end(), name) == known.end())
        {
            std::string list;
            for (const std::string& k : known)
                list += (list.empty() ? "" : ", ") + k;
            throw InvalidInputError("--meshes: unknown mesh '" + name + "' (known: " + list + ")");
        }
    return o.meshes;
}

Mesh load_mesh(const std::string& name, const Options& o)
{
    return name == "bunny" ? io::read_mesh(o.bunny) : generated_mesh(name);
}

//! The region's vertices: its listed vertices and the corners of its faces.
std::vector<Index> region_vertices(const Region& region, const Mesh& mesh)
{
    std::vector<Index> v = region.vertices;
    for (const Index f : region.faces)
        for (const Index i : mesh.face(f))
            v.push_back(i);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

void write_positions(const Mesh& mesh, std::span<const Scalar> x, const fs::path& path)
{
    fs::create_directories(path.parent_path());
    Mesh copy = mesh;
    copy.positions.assign(x.begin(), x.end());
    io::write_mesh(copy, path.string());
}

double seconds_since(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

//! Runs a recipe through the product path on a copy of `noisy`; false (and `note`) when
//! the recipe does not fit the mesh.
//! \brief Whether the recipe fairs a region and has no place on a whole mesh: it solves
//! for its minimizer and holds nothing (no region, pin or anchor), so a whole mesh has no
//! unique one (fair-region). Such a recipe runs in the seam experiment only.
bool fairs_a_region(const Recipe& recipe)
{
    return solves_for_minimizer(recipe.method) && !recipe.region && !recipe.hard && !recipe.soft &&
           !recipe.centroid;
}

bool run_recipe(const Recipe& recipe, const Mesh& mesh, const Topology& topology,
                std::span<const Scalar> noisy, std::vector<Scalar>& x, double& seconds,
                std::string& note)
{
    Mesh m = mesh;
    m.positions.assign(noisy.begin(), noisy.end());
    const auto start = Clock::now();
    try
    {
        smooth(m, topology, recipe);
    }
    catch (const InvalidInputError& e)
    {
        note = std::string("refused: ") + e.what();
        return false;
    }
    catch (const SolverError& e)
    {
        note = std::string("refused: ") + e.what();
        return false;
    }
    seconds = seconds_since(start);
    x = std::move(m.positions);
    return true;
}

class QualityRun
{
public:
    QualityRun(Options o, std::vector<NamedRecipe> recipes)
        : o_(std::move(o)), recipes_(std::move(recipes))
    {
    }

    void run_mesh(const std::string& name);
    void run_seam_experiment();
    void write_tsv() const;
    std::string markdown() const;

private:
    std::string noise_table(const std::string& noise, std::vector<std::string>& notes) const;
    std::string noise_found_table() const;
    std::string time_table() const;
    std::string seam_table() const;
    Row measure(const std::string& mesh, const std::string& noise, Scalar level,
                const std::string& method, const Mesh& m, const Topology& topology,
                std::span<const Scalar> x, std::span<const Scalar> noisy,
                const SurfaceDistance& clean, bool is_closed, double seconds) const;
    std::string goals() const;

    Options o_;
    std::vector<NamedRecipe> recipes_;
    std::vector<MeshInfo> meshes_;
    std::vector<Row> rows_;
    std::vector<SeamRow> seams_;
    std::string seam_setup_;
};

Row QualityRun::measure(const std::string& mesh, const std::string& noise, Scalar level,
                        const std::string& method, const Mesh& m, const Topology& topology,
                        std::span<const Scalar> x, std::span<const Scalar> noisy,
                        const SurfaceDistance& clean, bool is_closed, double seconds) const
{
    Row row;
    row.mesh = mesh, row.noise = noise, row.level = level, row.method = method;
    row.theta_deg = mean_normal_angle_deg(m, x, m.positions);
    row.ev = mean_relative_distance(clean, x);
    // Open meshes: the volume with their boundary loops capped, as the presets keep it.
    const auto volume = [&](std::span<const Scalar> at) {
        return is_closed ? signed_volume(m, at) : capped_volume(m, topology, at);
    };
    const Scalar v = volume(x), v_clean = volume(m.positions), v_noisy = volume(noisy);
    row.dv_percent = 100 * (v - v_clean) / v_clean;
    row.dv_run_percent = 100 * (v - v_noisy) / v_noisy;
    row.turned = turned_over_faces(m, x, noisy);
    row.seconds = seconds;
    return row;
}

void QualityRun::run_mesh(const std::string& name)
{
    const Mesh mesh = load_mesh(name, o_);
    const Topology topology = build_topology(mesh);
    const SurfaceDistance clean(mesh, mesh.positions);
    MeshInfo info{name,
                  mesh.vertex_count(),
                  mesh.face_count(),
                  mean_edge_length(topology, mesh.positions),
                  topology.boundary_edge_count == 0 && topology.singular_edge_count == 0,
                  mesh.corner_count() == 4 * mesh.face_count(),
                  VolumeConstraint(mesh, topology, mesh.positions,
                                   std::vector<char>(static_cast<size_t>(mesh.vertex_count()), 0))
                      .loop_count()};
    meshes_.push_back(info);
    const fs::path dir = fs::path(o_.write_meshes) / name;
    if (!o_.write_meshes.empty())
        write_positions(mesh, mesh.positions, dir / "clean.obj");

    std::vector<NoiseCase> cases = standard_noise_cases();
    if (o_.quick)
        cases = {{NoiseModel::GaussianNormal, 0.4}};
    for (const NoiseCase& noise : cases)
    {
        const std::string noise_id = noise_name(noise.model), level = level_name(noise.level);
        std::fprintf(stderr, "meshfair-quality: %s, %s %s\n", name.c_str(), noise_id.c_str(),
                     level.c_str());
        const std::vector<Scalar> noisy =
            noisy_positions(mesh, noise, case_seed(o_.seed, name + "/" + noise_id + "/" + level));
        const fs::path case_dir = dir / (noise_id + "-" + level);
        const auto record = [&](const std::string& method, std::span<const Scalar> x,
                                double seconds) {
            rows_.push_back(measure(name, noise_id, noise.level, method, mesh, topology, x, noisy,
                                    clean, info.is_closed, seconds));
            if (!o_.write_meshes.empty())
                write_positions(mesh, x, case_dir / (method + ".obj"));
        };
        // A method that gave no result: its row says why.
        const auto record_note = [&](const std::string& method, const std::string& note) {
            Row row;
            row.mesh = name, row.noise = noise_id, row.level = noise.level;
            row.method = method, row.note = note;
            rows_.push_back(row);
        };
        record("noisy", noisy, 0);
        rows_.back().estimated_sigma = estimate_noise(mesh, topology, noisy).sigma;

        std::vector<Scalar> x = noisy;
        auto start = Clock::now();
        BilateralSettings bilateral;
        bilateral.sigma_r = o_.bilateral_sigma_r;
        bilateral_normal_filter(mesh, topology, x, bilateral);
        record("bilateral", x, seconds_since(start));

        x = noisy;
        start = Clock::now();
        taubin_smooth(topology, x, TaubinSettings{o_.taubin_pairs});
        record("taubin", x, seconds_since(start));

        if (!o_.skip_sdfilter)
        {
            x = noisy;
            start = Clock::now();
            if (sdfilter_denoise(mesh, x))
                record("sdfilter", x, seconds_since(start));
            else
                record_note("sdfilter", "the library reported a failure");
        }

        for (const NamedRecipe& r : recipes_)
        {
            if (fairs_a_region(r.recipe))
                continue;
            double seconds = 0;
            std::string note;
            if (!run_recipe(r.recipe, mesh, topology, noisy, x, seconds, note))
            {
                record_note(r.name, note);
                continue;
            }
            record(r.name, x, seconds);
            if (r.recipe.region)
                seams_.push_back(
                    {name + " " + noise_id + " " + level, r.name,
                     seam_figure(mesh, topology, x, region_vertices(*r.recipe.region, mesh)), ""});
        }
    }
}

//! The seam experiment's runs: the 10 steps, and the 80 in which plain smoothing
//! erases relief.
constexpr int kSeamSteps[] = {10, 80};

void QualityRun::run_seam_experiment()
{
    // The bunny with Gaussian noise of 0.4 mean edge lengths along the normals inside a region
    // (a noisy patch of a clean scan), the 30% of its vertices nearest to its highest vertex
    // (largest y: the head and ears). The rest is clean, so that a step at the region's
    // border shows in the border rings' dihedral angles.
    const Mesh bunny = io::read_mesh(o_.bunny);
    const Topology topology = build_topology(bunny);
    const NoiseCase noise{NoiseModel::GaussianNormal, 0.4};
    const std::vector<Scalar> noisy_everywhere =
        noisy_positions(bunny, noise, case_seed(o_.seed, "seam"));
    const Index nv = bunny.vertex_count();
    Index top = 0;
    for (Index i = 1; i < nv; ++i)
        if (bunny.positions[3 * i + 1] > bunny.positions[3 * top + 1])
            top = i;
    std::vector<Index> order(static_cast<size_t>(nv));
    std::iota(order.begin(), order.end(), 0);
    const auto distance2 = [&](Index i) {
        Scalar d = 0;
        for (int a = 0; a < 3; ++a)
            d += std::pow(bunny.positions[3 * i + a] - bunny.positions[3 * top + a], 2);
        return d;
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](Index a, Index b) { return distance2(a) < distance2(b); });
    std::vector<Index> region(order.begin(), order.begin() + nv * 3 / 10);
    std::sort(region.begin(), region.end());
    const Scalar radius = region.empty() ? 0 : std::sqrt(distance2(order[region.size() - 1]));
    std::vector<Scalar> noisy = bunny.positions;
    for (const Index v : region)
        for (int a = 0; a < 3; ++a)
            noisy[3 * v + a] = noisy_everywhere[3 * v + a];
    seam_setup_ = "Bunny (" + std::to_string(nv) + " vertices), Gaussian noise along the " +
                  "normals, s = 0.4, inside the region only; region: the " +
                  std::to_string(region.size()) + " vertices (30%) within " +
                  format("%.3f", radius) + " of vertex " + std::to_string(top) +
                  " (the highest); each recipe with that region, for 10 iterations (where a " +
                  "jagged step shows first) and for 80 (where plain smoothing has shrunk the " +
                  "patch away from its fixed border).";
    const fs::path dir = fs::path(o_.write_meshes) / "seam";
    const auto record = [&](const std::string& what, const std::string& method,
                            std::span<const Scalar> x, const std::string& note) {
        seams_.push_back({what, method,
                          x.empty() ? SeamFigure{} : seam_figure(bunny, topology, x, region), note,
                          x.empty() ? std::numeric_limits<Scalar>::quiet_NaN()
                                    : volume_change_percent(bunny, x, bunny.positions)});
        if (!o_.write_meshes.empty() && !x.empty())
            write_positions(bunny, x,
                            dir / (what.substr(what.find(',') + 2) + " " + method + ".obj"));
    };
    record("bunny, input", "clean", bunny.positions, "");
    record("bunny, input", "noisy", noisy, "");
    if (!o_.write_meshes.empty())
    {
        std::ofstream list(dir / "region-vertices.txt");
        for (const Index v : region)
            list << v << "\n";
    }
    for (const int steps : kSeamSteps)
        for (const NamedRecipe& r : recipes_)
        {
            Recipe recipe = r.recipe;
            recipe.region = Region{region, {}};
            recipe.iterations = steps;
            std::vector<Scalar> x;
            double seconds = 0;
            std::string note;
            if (!run_recipe(recipe, bunny, topology, noisy, x, seconds, note))
                x.clear();
            record("bunny, " + std::to_string(steps) + " steps", r.name, x, note);
        }
}

void QualityRun::write_tsv() const
{
    if (o_.out.empty())
        return;
    const fs::path path(o_.out);
    if (path.has_parent_path())
        fs::create_directories(path.parent_path());
    std::ostringstream s;
    s << "mesh\tnoise\tlevel\tmethod\ttheta_deg\tev\tdv_percent\tdv_run_"
         "percent\tturned\tseconds\testimated_sigma\tnote\n";
    const auto number = [](Scalar v) {
        return std::isnan(v) ? std::string("NA") : format("%.9g", v);
    };
    for (const Row& r : rows_)
    {
        std::string note = r.note;
        std::replace_if(
            note.begin(), note.end(), [](char c) { return c == '\t' || c == '\n'; }, ' ');
        s << r.mesh << '\t' << r.noise << '\t' << level_name(r.level) << '\t' << r.method << '\t'
          << number(r.theta_deg) << '\t' << number(r.ev) << '\t' << number(r.dv_percent) << '\t'
          << number(r.dv_run_percent) << '\t'
          << (r.note.empty() ? std::to_string(r.turned) : std::string("NA")) << '\t'
          << number(r.seconds) << '\t' << number(r.estimated_sigma) << '\t' << note << '\n';
    }
    io::write_file_atomically(path.string(), s.str());
}

//! The Markdown separator of `columns` right-aligned columns.
std::string separator(size_t columns)
{
    std::string s;
    for (size_t k = 0; k < columns; ++k)
        s += "---:|";
    return s;
}

//! The columns of the whole-mesh tables: the references, then the recipes that smooth a
//! whole mesh.
std::vector<std::string> method_names(const std::vector<NamedRecipe>& recipes)
{
    std::vector<std::string> names{"noisy", "bilateral", "taubin", "sdfilter"};
    for (const NamedRecipe& r : recipes)
        if (!fairs_a_region(r.recipe))
            names.push_back(r.name);
    return names;
}

std::string QualityRun::goals() const
{
    std::ostringstream s;
    s << "## Goals\n\n";
    // The curved meshes without a crease (organic: the bunny, the rounded box) and the ones
    // with creases (the CAD-like parts, the cube and cylinder, the scan patch's ridge and
    // valleys), as the denoising goals tell them apart: each has its preset.
    const auto is_organic = [](const std::string& mesh) {
        return mesh == "bunny" || mesh == "quad-box";
    };
    const auto find = [&](const Row& like, const std::string& method) -> const Row* {
        for (const Row& r : rows_)
            if (r.mesh == like.mesh && r.noise == like.noise && r.level == like.level &&
                r.method == method)
                return &r;
        return nullptr;
    };
    const auto has_recipe = [&](const std::string& name) {
        return std::any_of(recipes_.begin(), recipes_.end(),
                           [&](const NamedRecipe& r) { return r.name == name; });
    };
    // One goal: figure(preset) <= factor x figure(reference) on the cases `applies` takes.
    const auto ratio_goal = [&](const std::string& what, const std::string& preset,
                                const std::string& reference, Scalar Row::*figure, Scalar factor,
                                const std::function<bool(const Row&)>& applies) {
        if (!has_recipe(preset))
        {
            s << "- " << what << ": skipped, no recipe named '" << preset << "' in this run\n";
            return;
        }
        int cases = 0;
        Scalar worst = 0;
        std::vector<std::string> failures;
        for (const Row& r : rows_)
            if (r.method == reference && r.note.empty() && applies(r))
            {
                const Row* p = find(r, preset);
                ++cases;
                const Scalar ratio = p ? p->*figure / (r.*figure) : kNaN;
                worst = std::isnan(ratio) ? worst : std::max(worst, ratio);
                if (!p || !p->note.empty() || !(ratio <= factor))
                    failures.push_back(r.mesh + " " + r.noise + " " + level_name(r.level) + " (" +
                                       (p ? format("%.2f", ratio) : "?") + "x)");
            }
        if (cases == 0)
        {
            s << "- " << what << ": no such case in this run\n";
            return;
        }
        s << "- " << what << ": " << (failures.empty() ? "PASS" : "FAIL") << " ("
          << cases - static_cast<int>(failures.size()) << "/" << cases
          << format(" pass; largest ratio %.2f", worst) << ")";
        for (size_t k = 0; k < failures.size(); ++k)
            s << (k == 0 ? "; fails on " : ", ") << failures[k];
        s << "\n";
    };
    const std::string& hard = o_.denoise_preset;
    const std::string& organic = o_.organic_preset;
    const auto heavy = [](const Row& r) { return r.level >= 0.7 && r.noise != "impulsive"; };
    const auto creased = [&](const Row& r) { return !is_organic(r.mesh); };
    const auto curved = [&](const Row& r) { return is_organic(r.mesh); };
    ratio_goal("theta(" + hard +
                   ") <= 0.7 x theta(bilateral) on the meshes with creases, noise of 0.2-0.4 "
                   "and impulsive",
               hard, "bilateral", &Row::theta_deg, 0.7,
               [&](const Row& r) { return creased(r) && !heavy(r); });
    ratio_goal("theta(" + hard +
                   ") <= 0.3 x theta(bilateral) on the meshes with creases, Gaussian noise of 0.7",
               hard, "bilateral", &Row::theta_deg, 0.3,
               [&](const Row& r) { return creased(r) && heavy(r); });
    ratio_goal("E_v(" + hard + ") <= 1.1 x E_v(bilateral) on the meshes with creases", hard,
               "bilateral", &Row::ev, 1.1, creased);
    ratio_goal("theta(" + organic + ") <= 0.9 x theta(bilateral) on the organic meshes (bunny, " +
                   "quad-box)",
               organic, "bilateral", &Row::theta_deg, 0.9, curved);
    ratio_goal("E_v(" + organic + ") <= 1.1 x E_v(bilateral) on the organic meshes", organic,
               "bilateral", &Row::ev, 1.1, curved);
    ratio_goal("E_v(" + organic + ") <= E_v(relax) on the organic meshes (no creases invented)",
               organic, "relax", &Row::ev, 1.0, curved);
    // Seams: for every recipe with a falloff, the border rings no rougher than the interior;
    // for a recipe that fairs the region (the thin plate, which takes the noise away inside
    // it), the border rings no rougher than the clean input's there (no crease where the
    // faired patch meets the fixed rest).
    const SeamRow* clean = nullptr;
    for (const SeamRow& r : seams_)
        if (r.what == "bunny, input" && r.method == "clean")
            clean = &r;
    for (const NamedRecipe& recipe : recipes_)
    {
        const bool plate = fairs_a_region(recipe.recipe);
        if (!recipe.recipe.falloff && !plate)
            continue;
        std::vector<std::string> cases;
        bool ok = true, any = false;
        for (const SeamRow& r : seams_)
            if (r.method == recipe.name && r.what.rfind("bunny, ", 0) == 0 && r.note.empty())
            {
                const Scalar bound = plate ? (clean ? 1.1 * clean->figure.border_p95_deg : -1)
                                           : r.figure.interior_p95_deg;
                any = true;
                const bool pass = r.figure.border_p95_deg <= bound;
                ok = ok && pass;
                cases.push_back(r.what.substr(7) + ": " + format("%.2f", r.figure.border_p95_deg) +
                                " vs " + format("%.2f", bound));
            }
        if (plate)
            s << "- border rings' dihedral p95 <= 1.1 x the clean input's for " << recipe.name
              << " (the region faired) in the seam experiment: ";
        else
            s << "- border rings' dihedral p95 <= the interior's for " << recipe.name
              << " (a falloff) in the seam experiment: ";
        s << (any && ok ? "PASS" : "FAIL");
        for (size_t k = 0; k < cases.size(); ++k)
            s << (k == 0 ? " (" : "; ") << cases[k];
        s << (cases.empty() ? "\n" : ")\n");
    }
    // The volume each recipe keeps: its run's own change, against the noisy mesh it was
    // given (the noise's own change against the clean mesh is the table's dV).
    for (const NamedRecipe& recipe : recipes_)
    {
        if (fairs_a_region(recipe.recipe)) // in the seam experiment only
            continue;
        const Row* worst = nullptr;
        int refused = 0, runs = 0;
        for (const Row& r : rows_)
            if (r.method == recipe.name)
            {
                if (!r.note.empty())
                    ++refused;
                else if (++runs, !std::isnan(r.dv_run_percent) &&
                                     (!worst ||
                                      std::abs(r.dv_run_percent) > std::abs(worst->dv_run_percent)))
                    worst = &r;
            }
        const bool ok =
            refused == 0 && runs > 0 && (!worst || std::abs(worst->dv_run_percent) <= 0.5);
        s << "- |dV| of the run <= 0.5% for " << recipe.name
          << " on every mesh and noise case (against the noisy mesh it was given; an open "
             "one's volume capped by its boundary loops), none refused: "
          << (ok ? "PASS" : "FAIL") << " (" << runs << " runs";
        if (worst)
            s << "; largest " << format("%+.3f", worst->dv_run_percent) << "% on " << worst->mesh
              << " " << worst->noise << " " << level_name(worst->level);
        if (refused)
            s << "; refused on " << refused << " cases";
        s << ")\n";
    }
    // No face turned over against the mesh a recipe was given (the presets' flip guard).
    for (const NamedRecipe& recipe : recipes_)
    {
        if (fairs_a_region(recipe.recipe))
            continue;
        int runs = 0;
        Index turned = 0, worst = 0;
        std::string where;
        for (const Row& r : rows_)
            if (r.method == recipe.name && r.note.empty())
            {
                ++runs;
                turned += r.turned;
                if (r.turned > worst)
                {
                    worst = r.turned;
                    where = r.mesh + " " + r.noise + " " + level_name(r.level);
                }
            }
        s << "- no face turned over by " << recipe.name
          << " (of the faces that lie in the surface it was given, none more than 90 degrees "
             "from its normal there): "
          << (turned == 0 && runs > 0 ? "PASS" : "FAIL") << " (" << turned << " faces in " << runs
          << " runs" << (worst > 0 ? "; most: " + std::to_string(worst) + " on " + where : "")
          << ")\n";
    }
    // The references are not held to it; what they turn over is said beside (the goals'
    // count, for comparison).
    for (const char* reference : {"bilateral", "taubin", "sdfilter"})
    {
        int runs = 0;
        Index turned = 0;
        for (const Row& r : rows_)
            if (r.method == reference && r.note.empty())
            {
                ++runs;
                turned += r.turned;
            }
        s << "- (reference) faces turned over by " << reference << ": " << turned << " in " << runs
          << " runs\n";
    }
    return s.str();
}

std::string QualityRun::noise_table(const std::string& noise, std::vector<std::string>& notes) const
{
    const std::vector<std::string> methods = method_names(recipes_);
    std::ostringstream s;
    s << "\n## " << noise << "\n\n| mesh | s |";
    for (const std::string& m : methods)
        s << " " << m << " |";
    s << "\n|---|---|" << separator(methods.size()) << "\n";
    std::map<std::pair<std::string, Scalar>, std::map<std::string, const Row*>> table;
    std::vector<std::pair<std::string, Scalar>> order;
    for (const Row& r : rows_)
        if (r.noise == noise)
        {
            const auto key = std::pair{r.mesh, r.level};
            if (!table.contains(key))
                order.push_back(key);
            table[key][r.method] = &r;
        }
    for (const auto& key : order)
    {
        s << "| " << key.first << " | " << level_name(key.second) << " |";
        for (const std::string& m : methods)
        {
            const auto it = table[key].find(m);
            if (it == table[key].end())
                s << " |";
            else if (!it->second->note.empty())
            {
                s << " refused |";
                notes.push_back(m + ": " + it->second->note);
            }
            else
                s << " " << format("%.2f", it->second->theta_deg) << " / "
                  << format("%.3f", 1e3 * it->second->ev) << " / "
                  << (std::isnan(it->second->dv_percent) ? std::string("-")
                                                         : format("%+.2f", it->second->dv_percent))
                  << " |";
        }
        s << "\n";
    }
    return s.str();
}

std::string QualityRun::time_table() const
{
    const std::vector<std::string> methods = method_names(recipes_);
    std::ostringstream s;
    s << "\n## Time (seconds of one run, mean over the noise cases)\n\n| mesh |";
    for (size_t k = 1; k < methods.size(); ++k)
        s << " " << methods[k] << " |";
    s << "\n|---|" << separator(methods.size() - 1) << "\n";
    for (const MeshInfo& mesh : meshes_)
    {
        s << "| " << mesh.name << " |";
        for (size_t k = 1; k < methods.size(); ++k)
        {
            Scalar sum = 0;
            int n = 0;
            for (const Row& r : rows_)
                if (r.mesh == mesh.name && r.method == methods[k] && r.note.empty())
                    sum += r.seconds, ++n;
            s << " " << (n ? format("%.3f", sum / n) : std::string("-")) << " |";
        }
        s << "\n";
    }
    return s.str();
}

std::string QualityRun::seam_table() const
{
    std::ostringstream s;
    s << "\n## Seams\n\n"
      << seam_setup_ << " Dihedral angles (degrees, 0 = flat), 95th "
      << "percentile: border rings = edges with an end within 2 rings of the region's border "
      << "ring (inside or out); inner border = those of them with both ends in the region; "
      << "interior = edges inside the region further in. Edge counts in parentheses. dV: "
      << "the bunny's volume change, %.\n\n"
      << "| case | method | border rings p95 | inner border p95 | interior p95 | dV |\n"
      << "|---|---|---:|---:|---:|---:|\n";
    for (const SeamRow& r : seams_)
    {
        s << "| " << r.what << " | " << r.method << " | ";
        const auto cell = [](Scalar p95, Index edges) {
            return (std::isnan(p95) ? std::string("-") : format("%.2f", p95)) + " (" +
                   std::to_string(edges) + ")";
        };
        if (!r.note.empty())
            s << r.note << " | | | |\n";
        else
            s << cell(r.figure.border_p95_deg, r.figure.border_edges) << " | "
              << cell(r.figure.inner_border_p95_deg, r.figure.inner_border_edges) << " | "
              << cell(r.figure.interior_p95_deg, r.figure.interior_edges) << " | "
              << (std::isnan(r.dv_percent) ? std::string("-") : format("%+.3f", r.dv_percent))
              << " |\n";
    }
    return s.str();
}

std::string QualityRun::markdown() const
{
    std::ostringstream s;
    s << "# MeshFair denoising quality (meshfair-quality, seed " << o_.seed << ")\n\n";
    s << "| mesh | vertices | faces | mean edge | closed |\n|---|---:|---:|---:|---|\n";
    for (const MeshInfo& m : meshes_)
        s << "| " << m.name << " | " << m.vertices << " | " << m.faces
          << (m.is_quads ? " quads" : "") << " | " << format("%.4f", m.mean_edge) << " | "
          << (m.is_closed ? std::string("yes")
                          : "no (" + std::to_string(m.loops) + " boundary loop" +
                                (m.loops == 1 ? "" : "s") + ")")
          << " |\n";
    s << "\nEach cell: theta (mean face-normal angle to the clean mesh, degrees) / E_v (mean "
         "vertex distance to the clean surface, in 1e-3 of the bounding-box diagonal) / dV "
         "(volume change, %; of an open mesh, the volume with its boundary loops capped by fans "
         "from their centroids, as the presets keep it). s: noise in mean edge lengths. Taubin: "
      << o_.taubin_pairs << " lambda|mu pairs (0.5, -0.53); bilateral: 20 normal and 10 vertex "
      << "iterations, sigma_r = " << o_.bilateral_sigma_r
      << "; sdfilter: the static/dynamic filter (Zhang, Deng et al.) through "
         "libmeshsdfilter-dev with its authors' denoising defaults (lambda 2, eta 1.5, mu 1.5, "
         "nu 0.3, 5 outer and 20 mesh-update iterations), on the faces split into triangles.\n";
    std::vector<std::string> noises, notes;
    for (const Row& r : rows_)
        if (std::find(noises.begin(), noises.end(), r.noise) == noises.end())
            noises.push_back(r.noise);
    for (const std::string& noise : noises)
        s << noise_table(noise, notes);
    // Each refusal once, with the number of cases it stands for (a region-only recipe is
    // refused on every whole mesh for the same reason).
    std::vector<std::pair<std::string, int>> refusals;
    for (const std::string& n : notes)
    {
        const auto same = std::find_if(refusals.begin(), refusals.end(),
                                       [&](const auto& r) { return r.first == n; });
        if (same == refusals.end())
            refusals.emplace_back(n, 1);
        else
            ++same->second;
    }
    for (const auto& [note, cases] : refusals)
    {
        const size_t colon = note.find(": ");
        std::string why = note.substr(colon + 2);
        if (why.rfind("refused: ", 0) == 0)
            why = why.substr(9);
        s << "\n- " << note.substr(0, colon) << ", refused in " << cases << " case"
          << (cases == 1 ? "" : "s") << ": " << why;
    }
    s << (notes.empty() ? "" : "\n") << noise_found_table() << time_table() << seam_table() << "\n"
      << goals();
    return s.str();
}

std::string QualityRun::noise_found_table() const
{
    // What "iterations": "auto" reads (estimate_noise) in each noisy mesh, against the
    // noise put in: the normal part of noise in other directions, the outliers' share of
    // impulsive noise.
    std::vector<std::string> noises;
    for (const Row& r : rows_)
        if (r.method == "noisy" && std::find(noises.begin(), noises.end(), r.noise) == noises.end())
            noises.push_back(r.noise);
    std::ostringstream s;
    s << "\n## Noise found (estimate_noise, in mean edge lengths; the noise put in: s)\n\n"
         "| mesh |";
    std::vector<std::pair<std::string, Scalar>> columns;
    for (const std::string& noise : noises)
        for (const Row& r : rows_)
            if (r.method == "noisy" && r.noise == noise && r.mesh == rows_.front().mesh)
            {
                columns.emplace_back(noise, r.level);
                s << " " << noise << " " << level_name(r.level) << " |";
            }
    s << "\n|---|" << separator(columns.size()) << "\n";
    for (const MeshInfo& mesh : meshes_)
    {
        s << "| " << mesh.name << " |";
        for (const auto& [noise, level] : columns)
        {
            const auto row = std::find_if(rows_.begin(), rows_.end(), [&](const Row& r) {
                return r.method == "noisy" && r.mesh == mesh.name && r.noise == noise &&
                       r.level == level;
            });
            s << " "
              << (row == rows_.end() ? std::string("-") : format("%.3f", row->estimated_sigma))
              << " |";
        }
        s << "\n";
    }
    return s.str();
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{
        "meshfair-quality: denoising quality of MeshFair's recipes against a bilateral "
        "normal filter and Taubin smoothing, on generated meshes with creases and the "
        "bunny"};
    Options o;
    app.add_option("--recipe", o.recipes,
                   "a recipe as NAME=PATH (repeatable; default: every assets/recipes/*.json, "
                   "named by its stem)");
    app.add_option("--meshes", o.meshes,
                   "meshes to run, comma-separated: cube, cylinder, cad-part, cut-sphere, "
                   "quad-box, scan-patch, holed-part, bunny (default: all)")
        ->delimiter(',');
    app.add_option("--bunny", o.bunny, "the bunny's file")->check(CLI::ExistingFile);
    app.add_option("--out", o.out, "results, one row per mesh, noise case and method (TSV)");
    app.add_option("--markdown", o.markdown, "also write the Markdown report there");
    app.add_option("--write-meshes", o.write_meshes,
                   "write the clean, noisy and smoothed meshes (OBJ) under this directory");
    app.add_option("--denoise-preset", o.denoise_preset,
                   "the recipe the goals on the meshes with creases are checked for");
    app.add_option("--organic-preset", o.organic_preset,
                   "the recipe the goals on the organic meshes are checked for");
    app.add_option("--taubin-pairs", o.taubin_pairs, "lambda|mu pairs of Taubin smoothing")
        ->check(CLI::Range(1, 100000));
    app.add_option("--bilateral-sigma-r", o.bilateral_sigma_r,
                   "range width of the bilateral normal filter (on |n_f - n_g|)")
        ->check(CLI::PositiveNumber);
    app.add_option("--seed", o.seed, "base seed of the noise");
    app.add_option("--threads", o.threads, "threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_flag("--quick", o.quick,
                 "smoke configuration: the cube (unless --meshes), Gaussian noise along the "
                 "normals at s = 0.4 only");
    app.add_flag("--skip-sdfilter", o.skip_sdfilter,
                 "leave the static/dynamic filter out (its columns stay empty): a faster run "
                 "for trying recipes");
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError& e)
    {
        return app.exit(e) == 0 ? 0 : 2;
    }
    set_thread_count(o.threads);
    try
    {
        const auto start = Clock::now();
        std::vector<NamedRecipe> recipes = load_recipes(o);
        const std::vector<std::string> meshes = mesh_names(o);
        QualityRun run(o, std::move(recipes));
        for (const std::string& name : meshes)
            run.run_mesh(name);
        run.run_seam_experiment();
        run.write_tsv();
        const std::string report = run.markdown();
        std::cout << report;
        if (!o.markdown.empty())
            io::write_file_atomically(o.markdown, report);
        std::fprintf(stderr, "meshfair-quality: done in %.1f s\n", seconds_since(start));
        return 0;
    }
    catch (const InvalidInputError& e)
    {
        std::fprintf(stderr, "meshfair-quality: %s\n", e.what());
        return 2;
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "meshfair-quality: %s\n", e.what());
        return 1;
    }
}
