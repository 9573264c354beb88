// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/cli/smooth_file.h"

#include <chrono>
#include <utility>

#include "app/cli/report.h"
#include "core/errors.h"
#include "core/recipe/locality_run.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/topology/vertex_order.h"

namespace meshfair::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

io::WriteOptions output_options(const std::string& requested, io::Format out_format,
                                const io::ReadReport& input, bool keep_normals)
{
    io::WriteOptions options;
    options.normals = keep_normals ? io::Normals::Keep : io::Normals::Recompute;
    if (requested == "ascii")
        options.encoding = io::Encoding::Ascii;
    else if (requested == "binary")
        options.encoding = io::Encoding::BinaryLittleEndian;
    else if (requested == "binary-be")
        options.encoding = io::Encoding::BinaryBigEndian;
    else if (out_format == input.format)
        options.encoding = input.encoding;
    return options;
}

std::vector<std::string> write_output(const Mesh& mesh, const io::MeshAttributes& attributes,
                                      const std::string& path, io::Format format,
                                      const io::WriteOptions& options)
{
    std::vector<std::string> notes;
    io::write_file_atomically(path,
                              io::write_mesh_data(mesh, format, options, &attributes, &notes));
    return notes;
}

nlohmann::json smooth_file(const std::string& mesh_path, const std::string& out_path,
                           const Recipe& recipe, const std::string& recipe_name,
                           const std::string& encoding, bool keep_normals)
{
    const io::Format out_format = io::format_from_path(out_path); // refuse before working
    const auto t_read = Clock::now();
    io::ReadReport read_report;
    io::MeshAttributes attributes; // in the file's numbering, as the output is written
    Mesh mesh = io::read_mesh(mesh_path, &read_report, &attributes);
    const double read_seconds = seconds_since(t_read);

    const auto t_setup = Clock::now();
    // Check the recipe in the file's numbering, so errors name the file's indices.
    try
    {
        check_recipe(recipe, mesh);
    }
    catch (const RecipeError& e)
    {
        throw RecipeError(e.key(), e.message(), recipe_name);
    }
    catch (const InvalidInputError& e)
    {
        throw InvalidInputError("'" + mesh_path + "': " + e.what()); // name the mesh at fault
    }
    nlohmann::json report;
    double setup_seconds = 0, solve_seconds = 0;
    // Solve in the locality numbering (neighbours near each other in memory): the one copy
    // of the mesh is renumbered in place and back before writing, so the output, the
    // recipe and the report keep the file's numbering (LocalityRun, as the editor runs).
    LocalityRun::Released solved;
    {
        // The solver's data lives in this scope only: it is freed before the output is
        // written.
        LocalityRun run(std::move(mesh), recipe);
        setup_seconds = seconds_since(t_setup);

        const auto t_solve = Clock::now();
        const SmoothResult result = meshfair::run(run.session());
        solve_seconds = seconds_since(t_solve);
        solved = std::move(run).release();
        validate_mesh(solved.mesh); // never write garbage: every coordinate is still finite
        report = smooth_report(solved.mesh, run.topology(), run.session(), result, read_report);
    }
    const auto t_back = Clock::now();
    mesh = file_order_mesh(std::move(solved));
    solve_seconds += seconds_since(t_back);

    const auto t_write = Clock::now();
    const std::vector<std::string> output_notes =
        write_output(mesh, attributes, out_path, out_format,
                     output_options(encoding, out_format, read_report, keep_normals));
    const double write_seconds = seconds_since(t_write);
    report["attributes"] = io::describe_attributes(attributes);
    report["output_notes"] = output_notes;

    report["seconds"] = {{"read", read_seconds},
                         {"setup", setup_seconds},
                         {"solve", solve_seconds},
                         {"write", write_seconds}};
    report["peak_memory_bytes"] = peak_resident_bytes();
    return report;
}

} // namespace meshfair::cli
