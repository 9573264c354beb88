// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/cli/report.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include "core/geometry/face_geometry.h"
#include "core/recipe/energy_terms.h"

namespace meshfair::cli {

namespace {

using Json = nlohmann::json;

Json counts(const Mesh& mesh, const Topology& topology)
{
    return {{"vertices", mesh.vertex_count()},
            {"faces", mesh.face_count()},
            {"edges", topology.edge_count()},
            {"boundary_edges", topology.boundary_edge_count},
            {"regular_edges", topology.regular_edge_count},
            {"singular_edges", topology.singular_edge_count}};
}

std::string format_number(double v)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.10g", v);
    return buffer;
}

} // namespace

Json info_json(const Mesh& mesh, const Topology& topology, const io::ReadReport& read_report,
               const io::MeshAttributes& attributes)
{
    Json j = counts(mesh, topology);
    const TopologySummary summary = summarize(topology);
    j["corners"] = mesh.corner_count();
    j["dual_edges"] = topology.dual_edge_count();
    j["components"] = summary.components;
    j["isolated_vertices"] = summary.isolated_vertices;
    std::map<Index, Index> histogram;
    for (Index f = 0; f < mesh.face_count(); ++f)
        ++histogram[mesh.face_size(f)];
    Json sizes = Json::object();
    for (const auto& [size, n] : histogram)
        sizes[std::to_string(size)] = n;
    j["face_sizes"] = sizes;
    const BoundingBox box = bounding_box(mesh.positions);
    j["bounding_box"] = box.empty ? Json(nullptr) : Json{{"min", box.min}, {"max", box.max}};
    j["format"] = std::string(io::format_name(read_report.format));
    j["encoding"] = std::string(io::encoding_name(read_report.encoding));
    j["attributes"] = io::describe_attributes(attributes);
    j["notes"] = read_report.notes;
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx",
                  static_cast<unsigned long long>(content_hash(mesh)));
    j["content_hash"] = hash;
    return j;
}

std::string info_text(const Json& j)
{
    std::string s;
    auto line = [&s](const std::string& key, const std::string& value) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%-18s ", (key + ":").c_str());
        s += buffer + value + "\n";
    };
    line("format", j["format"].get<std::string>() + " (" + j["encoding"].get<std::string>() + ")");
    for (const char* key : {"vertices", "faces", "edges", "boundary_edges", "regular_edges",
                            "singular_edges", "dual_edges", "components", "isolated_vertices"})
        line(key, std::to_string(j[key].get<long long>()));
    std::string sizes;
    for (const auto& [size, n] : j["face_sizes"].items())
        sizes += (sizes.empty() ? "" : ", ") + std::to_string(n.get<long long>()) + " with " +
                 size + " sides";
    line("face_sizes", sizes.empty() ? "none" : sizes);
    if (j["bounding_box"].is_null())
        line("bounding_box", "empty");
    else
    {
        std::string box;
        for (const char* end : {"min", "max"})
        {
            box += std::string(box.empty() ? "" : "  ") + end + " (";
            for (int a = 0; a < 3; ++a)
                box +=
                    format_number(j["bounding_box"][end][a].get<double>()) + (a < 2 ? ", " : ")");
        }
        line("bounding_box", box);
    }
    line("content_hash", j["content_hash"].get<std::string>());
    for (const auto& attribute : j["attributes"])
        line("attribute", attribute.get<std::string>());
    for (const auto& note : j["notes"])
        line("note", note.get<std::string>());
    return s;
}

Json smooth_report(const Mesh& mesh, const Topology& topology, const Session& session,
                   const SmoothResult& result, const io::ReadReport& read_report)
{
    Json j = counts(mesh, topology);
    const Recipe& recipe = session.recipe();
    j["iterations"] = result.iterations;
    j["stopped_by_tolerance"] = result.stopped_by_tolerance;
    j["free_vertices"] = session.free_vertices().size();
    Json energy = Json::array();
    for (const TermEnergies& e : result.energies)
        energy.push_back(e.total());
    j["energy"] = energy;
    Json per_term = Json::object();
    for (const EnergyTermInfo& t : energy_terms())
        if (t.in_recipe(recipe))
        {
            Json trace = Json::array();
            for (const TermEnergies& e : result.energies)
                trace.push_back(e.*(t.energy));
            per_term[std::string(t.key)] = trace;
        }
    j["terms"] = per_term;
    j["lambda"] = result.lambdas;
    // Steps with a tolerance: the gradient after each step, relative to the input's (the
    // rule that stops them); the solving methods give theirs in their own objects.
    if (!solves_for_minimizer(recipe.method) && !result.gradients.empty())
        j["relative_gradient"] = result.gradients;
    if (recipe.prevent_flips)
    {
        // The vertices whose steps FlipGuard shortened, step by step, and in all.
        long long total = 0;
        for (const Index n : result.shortened)
            total += n;
        j["flip_guard"] = {{"shortened", result.shortened}, {"total", total}};
    }
    if (session.conjugate_gradients() && recipe.method != Method::Implicit)
    {
        // Conjugate gradients in place of the factor: how close each solve came to the
        // minimizer and what it took.
        const Scalar diagonal = bounding_box(mesh.positions).diagonal();
        j["cg"] = {
            {"relative_gradient", result.gradients},
            {"jacobi_displacement", diagonal > 0 ? result.jacobi_displacement / diagonal : 0},
            {"unknowns", 3 * session.free_vertices().size()},
            {"iterations", result.inner_iterations}};
    }
    if (recipe.method == Method::Implicit)
    {
        // Backward-Euler steps: the time they smoothed for, and what the factor cost.
        Json implicit = {{"time", recipe.time},
                         {"steps", result.iterations},
                         {"total_time", recipe.time * result.iterations},
                         {"unknowns", 3 * session.free_vertices().size()}};
        if (const SparseCholesky* factor = session.factorization())
        {
            implicit["factor_megabytes"] = factor->stats().factor_bytes() / 1e6;
            implicit["analyse_seconds"] = factor->stats().analyse_seconds;
            implicit["factor_seconds"] = factor->stats().factor_seconds;
        }
        else
            implicit["cg_iterations"] = result.inner_iterations;
        j["implicit"] = implicit;
    }
    else if (const SparseCholesky* factor = session.factorization())
    {
        // The direct method: how close each solve came to the minimizer (the gradient over
        // the free vertices relative to the input's), and what the factorization cost.
        const FactorStats& f = factor->stats();
        const Scalar diagonal = bounding_box(mesh.positions).diagonal();
        j["direct"] = {
            {"relative_gradient", result.gradients},
            {"jacobi_displacement", diagonal > 0 ? result.jacobi_displacement / diagonal : 0},
            {"unknowns", factor->size()},
            {"factor_nonzeros", f.factor_nonzeros},
            {"factor_megabytes", f.factor_bytes() / 1e6},
            {"analyse_seconds", f.analyse_seconds},
            {"factor_seconds", f.factor_seconds}};
    }
    if (!session.normal_smoothing_trace().empty())
        j["normal_smoothing_energy"] = session.normal_smoothing_trace();
    if (const auto& noise = session.noise_estimate())
        j["noise"] = {{"estimated_sigma", noise->sigma},
                      {"height", noise->height},
                      {"edge_length", noise->edge_length},
                      {"vertices_measured", noise->vertices},
                      {"normal_smoothing_iterations", session.normal_smoothing_iterations()}};
    j["notes"] = read_report.notes;
    for (const std::string& note : session.notes())
        j["notes"].push_back(note);
    return j;
}

std::string smooth_summary(const Json& report, const std::string& output)
{
    const auto& energy = report["energy"];
    std::string s = "smoothed " + std::to_string(report["vertices"].get<long long>()) +
                    " vertices, " + std::to_string(report["faces"].get<long long>()) +
                    " faces: " + std::to_string(report["iterations"].get<int>()) +
                    " iterations, energy " + format_number(energy.front().get<double>()) + " -> " +
                    format_number(energy.back().get<double>()) + "\n";
    const auto& t = report["seconds"];
    s += "seconds: read " + format_number(t["read"].get<double>()) + ", setup " +
         format_number(t["setup"].get<double>()) + ", solve " +
         format_number(t["solve"].get<double>()) + ", write " +
         format_number(t["write"].get<double>()) + "\n";
    if (report.contains("relative_gradient"))
        s += "gradient " + format_number(report["relative_gradient"].back().get<double>()) +
             " of the input's after the last step (tolerance " +
             std::string(report["stopped_by_tolerance"].get<bool>() ? "reached" : "not reached") +
             ")\n";
    if (report.contains("direct") && !report["direct"]["relative_gradient"].empty())
        s += "direct: gradient " +
             format_number(report["direct"]["relative_gradient"].back().get<double>()) +
             " of the input's, Jacobi displacement " +
             format_number(report["direct"]["jacobi_displacement"].get<double>()) +
             " of the diagonal; factor of " +
             format_number(report["direct"]["unknowns"].get<double>()) + " unknowns, " +
             format_number(report["direct"]["factor_megabytes"].get<double>()) +
             " MB, analysed in " +
             format_number(report["direct"]["analyse_seconds"].get<double>()) + " s, factored in " +
             format_number(report["direct"]["factor_seconds"].get<double>()) + " s\n";
    if (report.contains("implicit"))
    {
        const Json& i = report["implicit"];
        s += "implicit: " + std::to_string(i["steps"].get<long long>()) +
             " backward-Euler steps of time " + format_number(i["time"].get<double>()) +
             " (in all " + format_number(i["total_time"].get<double>()) + ")";
        if (i.contains("factor_megabytes"))
            s += ", factor of " + format_number(i["unknowns"].get<double>()) + " unknowns, " +
                 format_number(i["factor_megabytes"].get<double>()) + " MB, factored in " +
                 format_number(i["factor_seconds"].get<double>()) + " s";
        s += "\n";
    }
    if (report.contains("cg") && !report["cg"]["relative_gradient"].empty())
    {
        long long iterations = 0;
        for (const auto& n : report["cg"]["iterations"])
            iterations += n.get<long long>();
        s += "conjugate gradients: gradient " +
             format_number(report["cg"]["relative_gradient"].back().get<double>()) +
             " of the input's, Jacobi displacement " +
             format_number(report["cg"]["jacobi_displacement"].get<double>()) +
             " of the diagonal, " + std::to_string(iterations) + " iterations\n";
    }
    if (report.contains("flip_guard"))
        s += "flip guard: " + std::to_string(report["flip_guard"]["total"].get<long long>()) +
             " vertex steps shortened so that no face turns over\n";
    for (const auto& note : report["notes"])
        s += "note: " + note.get<std::string>() + "\n";
    s += "wrote " + output + "\n";
    return s;
}

long long peak_resident_bytes()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.starts_with("VmHWM:"))
            return std::stoll(line.substr(6)) * 1024; // "VmHWM:    1234 kB"
    return -1;
}

} // namespace meshfair::cli
