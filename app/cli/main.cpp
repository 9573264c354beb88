// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-cli: the core library for scripts. Exit codes: 0 ok, 2 bad usage or input,
// 3 could not write an output, 1 internal error.
#include <malloc.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/cli/report.h"
#include "app/cli/smooth_file.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/geometry/noise.h"
#include "core/io/io.h"
#include "core/parallel/parallel.h"
#include "core/recipe/locality_run.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/topology/topology.h"
#include "core/topology/vertex_order.h"

namespace {

using namespace meshfair;

constexpr int kExitInput = 2;
constexpr int kExitWrite = 3;
constexpr int kExitInternal = 1;

//! The writer's notes on stderr, naming the file.
void print_output_notes(const std::vector<std::string>& notes, const std::string& path)
{
    for (const std::string& note : notes)
        std::cerr << "meshfair-cli: note: '" << path << "': " << note << "\n";
}

void write_text_atomically(const std::string& path, const std::string& text)
{
    if (path == "-")
    {
        std::cout << text;
        std::cout.flush();
        if (!std::cout)
            throw WriteError("standard output: write failed");
        return;
    }
    io::write_file_atomically(path, text);
}

struct InfoOptions
{
    std::string mesh;
    bool json = false;
};

int run_info(const InfoOptions& o)
{
    io::ReadReport read_report;
    io::MeshAttributes attributes;
    const Mesh mesh = io::read_mesh(o.mesh, &read_report, &attributes);
    const Topology topology = build_topology(mesh);
    const nlohmann::json j = cli::info_json(mesh, topology, read_report, attributes);
    if (o.json)
        std::cout << j.dump(2) << "\n";
    else
        std::cout << cli::info_text(j);
    return 0;
}

struct SmoothOptions
{
    std::string mesh, out, recipe, report, encoding;
    std::optional<int> iterations;
    std::optional<std::string> lambda;
    std::optional<double> tolerance;
    std::optional<std::string> method;
    std::optional<double> time;
    int threads = 0;
    bool quiet = false;
    bool keep_normals = false;
};

int run_smooth(const SmoothOptions& o)
{
    set_thread_count(o.threads);
    Recipe recipe = o.recipe.empty() ? Recipe{} : read_recipe(o.recipe);
    if (o.iterations)
        recipe.iterations = *o.iterations;
    if (o.lambda)
    {
        if (*o.lambda == "optimal")
            recipe.optimal_step = true;
        else
        {
            double value = 0;
            const char* begin = o.lambda->data();
            const char* end = begin + o.lambda->size();
            const auto [stop, ec] = std::from_chars(begin, end, value);
            if (ec != std::errc() || stop != end || !(value > 0) || !std::isfinite(value))
                throw InvalidInputError("--lambda: expected a number > 0 or 'optimal', got '" +
                                        *o.lambda + "'");
            recipe.lambda = value;
            recipe.optimal_step = false;
        }
    }
    if (o.tolerance)
        recipe.tolerance = *o.tolerance;
    if (o.method)
        recipe.method = *o.method == "jacobi"     ? Method::Jacobi
                        : *o.method == "direct"   ? Method::Direct
                        : *o.method == "cg"       ? Method::ConjugateGradient
                        : *o.method == "implicit" ? Method::Implicit
                                                  : Method::GradientDescent;
    if (o.time)
        recipe.time = *o.time;

    const nlohmann::json report =
        cli::smooth_file(o.mesh, o.out, recipe, o.recipe, o.encoding, o.keep_normals);
    print_output_notes(report["output_notes"].get<std::vector<std::string>>(), o.out);
    if (!o.report.empty())
        write_text_atomically(o.report, report.dump(2) + "\n");
    if (!o.quiet && o.report != "-")
        std::cout << cli::smooth_summary(report, o.out);
    return 0;
}

struct BatchOptions
{
    std::vector<std::string> meshes;
    std::string recipe, out_dir, encoding, format;
    int jobs = 0;
    bool keep_normals = false;
};

//! Outcome of one file of a batch, in increasing severity (the exit code is the worst).
enum class BatchStatus
{
    Ok,
    Rejected,    //!< exit 2: the file (or the recipe for it) was refused
    WriteFailed, //!< exit 3
    Internal     //!< exit 1
};

int exit_code(BatchStatus status)
{
    switch (status)
    {
        case BatchStatus::Ok:
            return 0;
        case BatchStatus::Rejected:
            return kExitInput;
        case BatchStatus::WriteFailed:
            return kExitWrite;
        case BatchStatus::Internal:
            return kExitInternal;
    }
    return kExitInternal;
}

//! `batch`: the same smoothing as `smooth` on many files, several at once (one OpenMP
//! thread per file, each file's solver on one thread), one JSON line per file on stdout
//! as it finishes, progress on stderr. A file that fails is reported and skipped; the
//! others go on. Exit code: 0 when every file was smoothed, else that of the worst
//! failure (internal 1 > write 3 > rejected input 2).
int run_batch(const BatchOptions& o)
{
    const Recipe recipe = read_recipe(o.recipe); // a bad recipe stops everything at once
    // Output names: the input's file name in --out-dir (with --format's extension).
    std::vector<std::string> outputs;
    std::map<std::string, std::string> taken;
    for (const std::string& mesh : o.meshes)
    {
        std::filesystem::path name = std::filesystem::path(mesh).filename();
        if (!o.format.empty())
            name.replace_extension("." + o.format);
        const std::string out = (std::filesystem::path(o.out_dir) / name).string();
        if (const auto [it, inserted] = taken.emplace(out, mesh); !inserted)
            throw InvalidInputError("'" + it->second + "' and '" + mesh +
                                    "' would both be written to '" + out + "'");
        io::format_from_path(out); // an unknown extension is refused before any work
        outputs.push_back(out);
    }
    std::error_code error;
    std::filesystem::create_directories(o.out_dir, error);
    if (error)
        throw WriteError("'" + o.out_dir + "': " + error.message());

    const int files = static_cast<int>(o.meshes.size());
    const int jobs = std::max(1, std::min(o.jobs > 0 ? o.jobs : thread_count(), files));
    set_thread_count(1); // parallel over files; each file's solver on its own thread
    const bool terminal = ::isatty(STDERR_FILENO) != 0;
    int done = 0, failed = 0;
    BatchStatus worst = BatchStatus::Ok;
    std::mutex output;
#pragma omp parallel for schedule(dynamic, 1) num_threads(jobs)
    for (int k = 0; k < files; ++k)
    {
        const std::string& mesh = o.meshes[static_cast<size_t>(k)];
        nlohmann::json line = {{"index", k}, {"file", mesh}};
        BatchStatus status = BatchStatus::Ok;
        try
        {
            line["report"] = cli::smooth_file(mesh, outputs[static_cast<size_t>(k)], recipe,
                                              o.recipe, o.encoding, o.keep_normals);
            line["output"] = outputs[static_cast<size_t>(k)];
        }
        catch (const InvalidInputError& e)
        {
            status = BatchStatus::Rejected;
            line["error"] = e.what();
        }
        catch (const WriteError& e)
        {
            status = BatchStatus::WriteFailed;
            line["error"] = std::string("cannot write ") + e.what();
        }
        catch (const std::exception& e)
        {
            status = BatchStatus::Internal;
            line["error"] = std::string("internal error: ") + e.what();
        }
        static constexpr const char* kStatus[] = {"ok", "rejected", "write_failed",
                                                  "internal_error"};
        line["status"] = kStatus[static_cast<int>(status)];
        const std::lock_guard lock(output);
        ++done;
        if (status != BatchStatus::Ok)
            ++failed;
        worst = std::max(worst, status);
        std::cout << line.dump() << "\n" << std::flush;
        const std::string progress = "[" + std::to_string(done) + "/" + std::to_string(files) +
                                     "] " + std::to_string(failed) + " failed";
        if (terminal) // one line, rewritten in place
            std::cerr << "\r" << progress << "  " << std::filesystem::path(mesh).filename().string()
                      << "\033[K" << (done == files ? "\n" : "") << std::flush;
        else
            std::cerr << "meshfair-cli: batch " << progress << "; "
                      << line["status"].get<std::string>() << ": " << mesh << "\n";
    }
    if (failed > 0)
        std::cerr << "meshfair-cli: batch: " << failed << " of " << files << " files failed\n";
    return exit_code(worst);
}

struct ConvertOptions
{
    std::string mesh, out, encoding;
    bool keep_normals = false;
};

int run_convert(const ConvertOptions& o)
{
    io::ReadReport read_report;
    io::MeshAttributes attributes;
    const Mesh mesh = io::read_mesh(o.mesh, &read_report, &attributes);
    const io::Format out_format = io::format_from_path(o.out);
    print_output_notes(
        cli::write_output(mesh, attributes, o.out, out_format,
                          cli::output_options(o.encoding, out_format, read_report, o.keep_normals)),
        o.out);
    return 0;
}

struct NoiseOptions
{
    std::string mesh, out, encoding;
    double sigma = 0;
    std::uint64_t seed = 1;
    bool keep_normals = false;
};

int run_noise(const NoiseOptions& o)
{
    io::ReadReport read_report;
    io::MeshAttributes attributes;
    Mesh mesh = io::read_mesh(o.mesh, &read_report, &attributes);
    const io::Format out_format = io::format_from_path(o.out);
    const Topology topology = build_topology(mesh);
    const Scalar unit = mean_edge_length(topology, mesh.positions);
    if (!(unit > 0))
        throw InvalidInputError("'" + o.mesh +
                                "': noise needs edges (sigma is in units of the mean edge "
                                "length) and this mesh has none of positive length");
    add_gaussian_noise(mesh, o.sigma * unit, o.seed);
    print_output_notes(
        cli::write_output(mesh, attributes, o.out, out_format,
                          cli::output_options(o.encoding, out_format, read_report, o.keep_normals)),
        o.out);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    // Over a file-size limit (ulimit -f) the kernel sends SIGXFSZ, which kills by
    // default in the middle of a save; ignored, the write fails with EFBIG, the save is
    // abandoned cleanly (temporary removed, target intact) and exit code 3 says why.
    std::signal(SIGXFSZ, SIG_IGN);
    // Every block of 1 MiB or more a mapping of its own, returned to the system when freed.
    // glibc's default threshold rises to the size of the largest block freed, after which
    // the reader's and the precomputation's freed arrays stay in the heap, resident beside
    // the solver's: 387 against 352 bytes a vertex at the peak of a combined smooth of 1.25M
    // vertices, read and setup no slower (docs/performance.md, Memory).
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    CLI::App app{
        "meshfair-cli: polygon mesh smoothing from scripts (Taubin 2012 energies,\n"
        "generalized Jacobi solver). Formats: .obj .off .ply .stl (from the extension)."};
    app.set_version_flag("--version", std::string("meshfair-cli ") + MESHFAIR_VERSION);
    app.require_subcommand(1);
    app.footer(
        "Exit codes: 0 ok, 2 bad usage or input, 3 could not write an output, "
        "1 internal error.");

    InfoOptions info;
    auto* info_cmd = app.add_subcommand("info", "Print counts and topology of a mesh");
    info_cmd->add_option("MESH", info.mesh, "Mesh file")->required();
    info_cmd->add_flag("--json", info.json, "Print JSON instead of text");

    const std::string encoding_help =
        "Output encoding for PLY/STL: ascii, binary (little endian) or binary-be (PLY); "
        "default: the input's encoding when the format is unchanged, else binary. "
        "STL output fan-triangulates polygons (the only place MeshFair splits them) and its "
        "binary form stores float32; every other output round-trips doubles exactly";
    const std::string keep_normals_help =
        "Write the normals the input holds as they are (with a note), instead of recomputing "
        "them from the positions written";
    SmoothOptions smooth;
    auto* smooth_cmd = app.add_subcommand("smooth", "Smooth a mesh with a recipe");
    smooth_cmd->add_option("MESH", smooth.mesh, "Input mesh")->required();
    smooth_cmd->add_option("-o,--output", smooth.out, "Output mesh (format from extension)")
        ->required();
    smooth_cmd->add_option("--recipe", smooth.recipe, "Recipe JSON (docs/recipe.md)");
    smooth_cmd->add_option("--iterations", smooth.iterations, "Number of steps (overrides recipe)")
        ->check(CLI::NonNegativeNumber);
    smooth_cmd->add_option("--lambda", smooth.lambda,
                           "Step length > 0, or 'optimal' for the exact line search");
    smooth_cmd
        ->add_option("--tolerance", smooth.tolerance,
                     "Stop at the first positions whose gradient, relative to the input's, is "
                     "at most this (every method; 0 = off)")
        ->check(CLI::NonNegativeNumber);
    smooth_cmd
        ->add_option("--method", smooth.method,
                     "jacobi (default: the paper's steps), direct (the minimizer, by sparse "
                     "Cholesky), cg (the minimizer, by conjugate gradients), implicit "
                     "(backward-Euler steps of --time each) or gradient_descent")
        ->check(CLI::IsMember({"jacobi", "direct", "cg", "implicit", "gradient_descent"}));
    smooth_cmd
        ->add_option("--time", smooth.time,
                     "Time of each step of method implicit (overrides the recipe's \"time\")")
        ->check(CLI::PositiveNumber);
    smooth_cmd->add_option("--report", smooth.report, "Write the JSON report here ('-' = stdout)");
    smooth_cmd->add_option("--encoding", smooth.encoding, encoding_help)
        ->check(CLI::IsMember({"ascii", "binary", "binary-be"}));
    smooth_cmd->add_flag("-q,--quiet", smooth.quiet, "Print nothing on success");
    smooth_cmd->add_flag("--keep-normals", smooth.keep_normals, keep_normals_help);
    smooth_cmd
        ->add_option("--threads", smooth.threads,
                     "Threads of the solver (default: every core); any count gives the same "
                     "result, bit for bit")
        ->check(CLI::Range(1, 1024));

    ConvertOptions convert;
    auto* convert_cmd =
        app.add_subcommand("convert", "Write a mesh in another format or encoding, unchanged");
    convert_cmd->add_option("MESH", convert.mesh, "Input mesh")->required();
    convert_cmd->add_option("-o,--output", convert.out, "Output mesh (format from extension)")
        ->required();
    convert_cmd->add_option("--encoding", convert.encoding, encoding_help)
        ->check(CLI::IsMember({"ascii", "binary", "binary-be"}));
    convert_cmd->add_flag("--keep-normals", convert.keep_normals, keep_normals_help);

    NoiseOptions noise;
    auto* noise_cmd = app.add_subcommand("noise", "Add Gaussian noise to every vertex");
    noise_cmd->add_option("MESH", noise.mesh, "Input mesh")->required();
    noise_cmd->add_option("-o,--output", noise.out, "Output mesh")->required();
    noise_cmd->add_option("--sigma", noise.sigma, "Standard deviation in mean edge lengths")
        ->required()
        ->check(CLI::NonNegativeNumber);
    noise_cmd->add_option("--seed", noise.seed, "Random seed (same seed, same noise)");
    noise_cmd->add_option("--encoding", noise.encoding, encoding_help)
        ->check(CLI::IsMember({"ascii", "binary", "binary-be"}));
    noise_cmd->add_flag("--keep-normals", noise.keep_normals, keep_normals_help);

    BatchOptions batch;
    auto* batch_cmd = app.add_subcommand(
        "batch", "Smooth many meshes with one recipe, several at once; one JSON line per file");
    batch_cmd->add_option("MESH", batch.meshes, "Input meshes")->required();
    batch_cmd->add_option("--recipe", batch.recipe, "Recipe JSON (docs/recipe.md)")->required();
    batch_cmd
        ->add_option("--out-dir", batch.out_dir, "Directory of the outputs (created if missing)")
        ->required();
    batch_cmd
        ->add_option("--format", batch.format,
                     "Output format (default: each input's): obj, off, ply or stl")
        ->check(CLI::IsMember({"obj", "off", "ply", "stl"}));
    batch_cmd->add_option("--encoding", batch.encoding, encoding_help)
        ->check(CLI::IsMember({"ascii", "binary", "binary-be"}));
    batch_cmd->add_option("--jobs", batch.jobs, "Files smoothed at once (default: every core)")
        ->check(CLI::Range(1, 1024));
    batch_cmd->add_flag("--keep-normals", batch.keep_normals, keep_normals_help);

    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError& e)
    {
        const int code = app.exit(e);
        return code == 0 ? 0 : kExitInput;
    }

    try
    {
        if (*info_cmd)
            return run_info(info);
        if (*smooth_cmd)
            return run_smooth(smooth);
        if (*noise_cmd)
            return run_noise(noise);
        if (*convert_cmd)
            return run_convert(convert);
        if (*batch_cmd)
            return run_batch(batch);
    }
    catch (const InvalidInputError& e)
    {
        std::cerr << "meshfair-cli: " << e.what() << "\n";
        return kExitInput;
    }
    catch (const WriteError& e)
    {
        std::cerr << "meshfair-cli: cannot write " << e.what() << "\n";
        return kExitWrite;
    }
    catch (const std::exception& e)
    {
        std::cerr << "meshfair-cli: internal error: " << e.what() << "\n";
        return kExitInternal;
    }
    return kExitInternal;
}
