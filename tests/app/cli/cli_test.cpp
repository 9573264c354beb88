// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-cli as scripts use it: exit codes, messages, files written or not.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "core/recipe/recipe.h"
#include "tests/helpers.h"

using namespace meshfair;
namespace fs = std::filesystem;

namespace {

using Run = test::CommandRun;

using test::cli;

std::string bunny()
{
    return test::shell_quote((test::assets_dir() / "bunny.obj").string());
}

// Two pins lifted on the bunny (one component, which they hold): a unique minimizer.
std::string pins_recipe(const fs::path& dir)
{
    const std::string recipe = (dir / "pins.json").string();
    test::write_bytes(recipe, R"({"iterations": 5, "hard": {"vertices": [0, 100],
        "targets": [[0, 0.2, 0], [0, 0.2, 0.05]]}})");
    return recipe;
}

// A textured scan patch as exporters write it: a wavy 20 x 20 quad grid with a texture
// seam down its middle (the right half's faces have their own texture coordinates), one
// normal and one colour per vertex, a material library, a group and a smoothing group.
std::string textured_patch_obj()
{
    const int n = 20;
    std::string s = "mtllib patch.mtl\no patch\n";
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            s += "v " + std::to_string(x) + " " + std::to_string(y) + " " +
                 std::to_string(0.3 * std::sin(1.7 * x + 2.3 * y)) + " " +
                 std::to_string(x / double(n)) + " 0.5 " + std::to_string(y / double(n)) + "\n";
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            s += "vt " + std::to_string(x / double(n)) + " " + std::to_string(y / double(n)) + "\n";
    for (int y = 0; y <= n; ++y) // the right half's own vt: a seam at x = 10
        for (int x = n / 2; x <= n; ++x)
            s += "vt " + std::to_string(0.5 + x / double(2 * n)) + " " +
                 std::to_string(y / double(n)) + "\n";
    for (int k = 0; k < (n + 1) * (n + 1); ++k)
        s += "vn 0 0 1\n";
    s += "g patch\nusemtl skin\ns 1\n";
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
        {
            s += "f";
            for (const auto& [dx, dy] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
            {
                const int v = (y + dy) * (n + 1) + x + dx + 1;
                const int t =
                    x < n / 2 ? v
                              : (n + 1) * (n + 1) + (y + dy) * (n / 2 + 1) + (x + dx - n / 2) + 1;
                s += " " + std::to_string(v) + "/" + std::to_string(t) + "/" + std::to_string(v);
            }
            s += "\n";
        }
    return s;
}

io::MeshAttributes attributes_of(const std::string& path, Mesh* mesh = nullptr)
{
    io::MeshAttributes a;
    const Mesh m = io::read_mesh(path, nullptr, &a);
    if (mesh)
        *mesh = m;
    return a;
}

} // namespace

TEST_SUITE("Cli")
{
    TEST_CASE("--help and --version succeed, no command is a usage error")
    {
        const Run help = cli("smooth --help");
        CHECK(help.code == 0);
        CHECK(help.out.find("fan-triangulates") != std::string::npos);
        const Run version = cli("--version");
        CHECK(version.code == 0);
        CHECK(version.out.find("meshfair-cli") == 0);
        CHECK(cli("").code == 2);
        CHECK(cli("smooth").code == 2);
        CHECK(cli("frobnicate x").code == 2);
    }

    TEST_CASE("info reports the topology of the bunny")
    {
        const Run r = cli("info --json " + bunny());
        REQUIRE(r.code == 0);
        const auto j = nlohmann::json::parse(r.out);
        CHECK(j["vertices"] == 34835);
        CHECK(j["faces"] == 69666);
        CHECK(j["edges"] == 104499);
        CHECK(j["boundary_edges"] == 0);
        CHECK(j["singular_edges"] == 0);
        CHECK(j["components"] == 1);
        CHECK(j["face_sizes"]["3"] == 69666);
    }

    TEST_CASE("smooth with zero iterations reproduces the input's coordinates in every format")
    {
        const fs::path dir = test::temp_dir();
        const Mesh input = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        for (const char* ext : {"obj", "off", "ply"})
        {
            const std::string out = (dir / (std::string("same.") + ext)).string();
            const Run r =
                cli("smooth " + bunny() + " -o " + test::shell_quote(out) + " --iterations 0 -q");
            REQUIRE(r.code == 0);
            CHECK(io::read_mesh(out) == input);
        }
    }

    TEST_CASE("the report has the trace of every active term and the timings")
    {
        const fs::path dir = test::temp_dir();
        const std::string recipe = (dir / "r.json").string();
        test::write_bytes(recipe, R"({"iterations": 4, "soft": {"vertices": "all", "mu": 0.1},
            "centroid": {"faces": "all"}, "normal": {"faces": "all", "normals": "smoothed"},
            "normal_smoothing": {"iterations": 3}})");
        const std::string out = (dir / "s.ply").string(), report = (dir / "report.json").string();
        const Run r = cli("smooth " + bunny() + " -o " + test::shell_quote(out) + " --recipe " +
                          test::shell_quote(recipe) + " --report " + test::shell_quote(report));
        REQUIRE(r.code == 0);
        const auto j = nlohmann::json::parse(io::read_file(report));
        CHECK(j["vertices"] == 34835);
        CHECK(j["regular_edges"] == 104499);
        CHECK(j["iterations"] == 4);
        REQUIRE(j["energy"].size() == 5);
        for (const char* term : {"edge", "soft", "centroid", "normal"})
            CHECK(j["terms"][term].size() == 5);
        for (size_t k = 0; k < 5; ++k)
        {
            const double sum =
                j["terms"]["edge"][k].get<double>() + j["terms"]["soft"][k].get<double>() +
                j["terms"]["centroid"][k].get<double>() + j["terms"]["normal"][k].get<double>();
            CHECK(j["energy"][k].get<double>() == doctest::Approx(sum).epsilon(1e-14));
        }
        CHECK(j["normal_smoothing_energy"].size() == 4);
        for (const char* phase : {"read", "setup", "solve", "write"})
            CHECK(j["seconds"][phase].get<double>() >= 0);
        CHECK(io::read_mesh(out).vertex_count() == 34835);
    }

    TEST_CASE("flags override the recipe")
    {
        const fs::path dir = test::temp_dir();
        const std::string recipe = (dir / "r.json").string();
        test::write_bytes(recipe, R"({"iterations": 50, "lambda": 0.5})");
        const Run r =
            cli("smooth " + bunny() + " -o " + test::shell_quote((dir / "o.obj").string()) +
                " --recipe " + test::shell_quote(recipe) +
                " --iterations 2 --lambda optimal --report -");
        REQUIRE(r.code == 0);
        const auto j = nlohmann::json::parse(r.out);
        CHECK(j["iterations"] == 2);
        CHECK(j["lambda"][0].get<double>() != 0.5);
    }

    TEST_CASE("--method direct: the minimizer in one solve, its gradient and factor reported")
    {
        const fs::path dir = test::temp_dir();
        const std::string recipe = pins_recipe(dir);
        const Run r =
            cli("smooth " + bunny() + " -o " + test::shell_quote((dir / "o.obj").string()) +
                " --recipe " + test::shell_quote(recipe) + " --method direct --report -");
        REQUIRE(r.code == 0);
        const auto j = nlohmann::json::parse(r.out);
        REQUIRE(j.contains("direct"));
        CHECK(j["iterations"].get<int>() <= 2);
        CHECK(j["stopped_by_tolerance"] == true);
        CHECK(j["direct"]["relative_gradient"].back().get<double>() <= 1e-12);
        CHECK(j["direct"]["jacobi_displacement"].get<double>() <= 1e-9);
        CHECK(j["direct"]["unknowns"].get<long long>() == 34835 - 2);
        CHECK(j["direct"]["factor_nonzeros"].get<double>() > 34835);
    }

    TEST_CASE("--method cg: the same minimizer by conjugate gradients, their iterations reported")
    {
        const fs::path dir = test::temp_dir();
        const std::string recipe = pins_recipe(dir);
        const auto solve = [&](const std::string& method) {
            const std::string out = (dir / (method + ".obj")).string();
            const Run r = cli("smooth " + bunny() + " -o " + test::shell_quote(out) + " --recipe " +
                              test::shell_quote(recipe) + " --method " + method + " --report -");
            REQUIRE(r.code == 0);
            return std::pair{nlohmann::json::parse(r.out), io::read_mesh(out).positions};
        };
        const auto [cg, cg_positions] = solve("cg");
        const auto [direct, direct_positions] = solve("direct");
        REQUIRE(cg.contains("cg"));
        CHECK_FALSE(cg.contains("direct"));
        CHECK(cg["cg"]["iterations"].front().get<int>() > 0);
        CHECK(cg["cg"]["relative_gradient"].back().get<double>() <= 1e-12);
        CHECK(cg["cg"]["jacobi_displacement"].get<double>() <= 1e-9);
        Scalar worst = 0;
        for (size_t k = 0; k < cg_positions.size(); ++k)
            worst = std::max(worst, std::abs(cg_positions[k] - direct_positions[k]));
        CHECK(worst <= 1e-9 * bounding_box(direct_positions).diagonal());
    }

    TEST_CASE("--method implicit --time: backward-Euler steps of a whole mesh, their time reported")
    {
        // The bunny with no pin nor region: nothing holds it (the direct method refuses it),
        // and implicit steps smooth it; the flags give what the recipe's keys give.
        const fs::path dir = test::temp_dir();
        const std::string flags = (dir / "flags.ply").string(), keys = (dir / "keys.ply").string();
        const Run refused = cli("smooth " + bunny() + " -o " + test::shell_quote(flags) +
                                " --method direct --iterations 1 -q");
        CHECK(refused.code == 2);
        CHECK(refused.err.find("is held by nothing") != std::string::npos);
        const Run r = cli("smooth " + bunny() + " -o " + test::shell_quote(flags) +
                          " --method implicit --time 2 --iterations 3 --report -");
        REQUIRE(r.code == 0);
        const auto j = nlohmann::json::parse(r.out);
        REQUIRE(j.contains("implicit"));
        CHECK_FALSE(j.contains("direct"));
        CHECK(j["implicit"]["time"] == 2.0);
        CHECK(j["implicit"]["steps"] == 3);
        CHECK(j["implicit"]["total_time"] == 6.0);
        CHECK(j["implicit"]["unknowns"].get<long long>() == 3 * 34835);
        const auto& energy = j["energy"];
        CHECK(energy.back().get<double>() < energy.front().get<double>());
        const std::string recipe = (dir / "implicit.json").string();
        test::write_bytes(recipe, R"({"method": "implicit", "time": 2, "iterations": 3})");
        REQUIRE(cli("smooth " + bunny() + " -o " + test::shell_quote(keys) + " --recipe " +
                    test::shell_quote(recipe) + " -q")
                    .code == 0);
        CHECK(io::read_file(flags) == io::read_file(keys));
    }

    TEST_CASE("CHOLMOD and its BLAS are loaded by the direct method only")
    {
        // The dynamic loader names every library it opens (LD_DEBUG=files): a process that
        // never factors must not pay for loading CHOLMOD and starting OpenBLAS's threads.
        const fs::path dir = test::temp_dir();
        const auto loads_cholmod = [&](const std::string& method) {
            const test::CommandRun r = test::run_command(
                "LD_DEBUG=files " + test::shell_quote(MESHFAIR_CLI) + " smooth " + bunny() +
                " -o " + test::shell_quote((dir / (method + ".obj")).string()) + " --recipe " +
                test::shell_quote(pins_recipe(dir)) + " --method " + method + " -q");
            REQUIRE(r.code == 0);
            return r.err.find("file=libcholmod") != std::string::npos;
        };
        CHECK_FALSE(loads_cholmod("jacobi"));
        CHECK(loads_cholmod("direct"));
    }

    TEST_CASE("noise is deterministic for a seed")
    {
        const fs::path dir = test::temp_dir();
        const std::string a = (dir / "a.obj").string(), b = (dir / "b.obj").string(),
                          c = (dir / "c.obj").string();
        CHECK(cli("noise " + bunny() + " -o " + test::shell_quote(a) + " --sigma 0.5 --seed 4")
                  .code == 0);
        CHECK(cli("noise " + bunny() + " -o " + test::shell_quote(b) + " --sigma 0.5 --seed 4")
                  .code == 0);
        CHECK(cli("noise " + bunny() + " -o " + test::shell_quote(c) + " --sigma 0.5 --seed 5")
                  .code == 0);
        CHECK(io::read_file(a) == io::read_file(b));
        CHECK(io::read_file(a) != io::read_file(c));
    }

    TEST_CASE("bad input exits 2 naming the file and line, and writes nothing")
    {
        const fs::path dir = test::temp_dir();
        const std::string bad = (dir / "bad.obj").string(), out = (dir / "out.obj").string();
        test::write_bytes(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
        const Run r = cli("smooth " + test::shell_quote(bad) + " -o " + test::shell_quote(out));
        CHECK(r.code == 2);
        CHECK(r.err.find(bad + ":4:7: vertex index 4 is past the last vertex") !=
              std::string::npos);
        CHECK_FALSE(fs::exists(out));

        const Run missing = cli("info " + test::shell_quote((dir / "none.obj").string()));
        CHECK(missing.code == 2);
        CHECK(missing.err.find("cannot open") != std::string::npos);

        const Run format =
            cli("smooth " + bunny() + " -o " + test::shell_quote((dir / "o.xyz").string()));
        CHECK(format.code == 2);
        CHECK(format.err.find("unknown mesh format '.xyz'") != std::string::npos);
    }

    TEST_CASE("an ASCII STL facet of four vertices exits 2 naming its line, the output untouched")
    {
        const fs::path dir = test::temp_dir();
        const std::string bad = (dir / "quad.stl").string(), out = (dir / "out.obj").string();
        test::write_bytes(bad,
                          "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                          "vertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
                          "endsolid q\n");
        test::write_bytes(out, "an earlier output\n");
        for (const char* command : {"smooth ", "convert "})
        {
            const Run r = cli(command + test::shell_quote(bad) + " -o " + test::shell_quote(out));
            CHECK(r.code == 2);
            CHECK(r.err.find(bad + ":7:1: facet 0 has more than 3 vertices") != std::string::npos);
            CHECK(io::read_file(out) == "an earlier output\n");
        }
    }

    TEST_CASE("a bad recipe exits 2 naming the key, and writes nothing")
    {
        const fs::path dir = test::temp_dir();
        const std::string recipe = (dir / "r.json").string(), out = (dir / "o.obj").string();
        test::write_bytes(recipe, R"({"soft": {"vertices": [1, 40000]}})");
        const Run r = cli("smooth " + bunny() + " -o " + test::shell_quote(out) + " --recipe " +
                          test::shell_quote(recipe));
        CHECK(r.code == 2);
        CHECK(r.err.find("soft.vertices[1]: vertex 40000 is out of range") != std::string::npos);
        CHECK(r.err.find(recipe) != std::string::npos);
        CHECK_FALSE(fs::exists(out));
        CHECK(cli("smooth " + bunny() + " -o " + test::shell_quote(out) + " --lambda fast").code ==
              2);
        CHECK_FALSE(fs::exists(out));

        // Weights that no double can hold beside the others (on a tilted plane every face
        // has the same normal, so a vertex's normal block is of rank one): refused, not an
        // internal error.
        std::string plane;
        for (int y = 0; y <= 4; ++y)
            for (int x = 0; x <= 4; ++x)
                plane += "v " + std::to_string(x) + " " + std::to_string(y) + " " +
                         std::to_string(0.3 * x + 0.7 * y) + "\n";
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x)
                plane += "f " + std::to_string(y * 5 + x + 1) + " " +
                         std::to_string(y * 5 + x + 2) + " " + std::to_string(y * 5 + x + 7) + " " +
                         std::to_string(y * 5 + x + 6) + "\n";
        const std::string mesh = (dir / "plane.obj").string();
        test::write_bytes(mesh, plane);
        test::write_bytes(recipe, R"({"normal": {"faces": "all", "mu": 1e300}})");
        const Run extreme = cli("smooth " + test::shell_quote(mesh) + " -o " +
                                test::shell_quote(out) + " --recipe " + test::shell_quote(recipe));
        CHECK(extreme.code == 2);
        CHECK(extreme.err.find("normal: its weights overwhelm the other terms at a vertex") !=
              std::string::npos);
        CHECK_FALSE(fs::exists(out));
    }

    TEST_CASE("writing STL says which vertices it cannot hold")
    {
        const fs::path dir = test::temp_dir();
        const std::string in = (dir / "m.obj").string(), out = (dir / "m.stl").string();
        test::write_bytes(in, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n");
        const Run r =
            cli("smooth " + test::shell_quote(in) + " -o " + test::shell_quote(out) + " -q");
        CHECK(r.code == 0);
        CHECK(r.err.find("'" + out +
                         "': STL cannot hold vertices without faces; 1 vertex is not "
                         "written") != std::string::npos);
        CHECK(io::read_mesh(out).vertex_count() == 3);
    }

    TEST_CASE("smooth keeps texture coordinates, colours, groups and materials, normals renewed")
    {
        const fs::path dir = test::temp_dir();
        const std::string in = (dir / "patch.obj").string(), out = (dir / "smooth.obj").string(),
                          report = (dir / "r.json").string();
        test::write_bytes(in, textured_patch_obj());
        Mesh input;
        const io::MeshAttributes before = attributes_of(in, &input);
        REQUIRE(before.texcoords.entry_count() == 441 + 231);
        const Run r = cli("smooth " + test::shell_quote(in) + " -o " + test::shell_quote(out) +
                          " --iterations 10 --report " + test::shell_quote(report) + " -q");
        REQUIRE(r.code == 0);
        CHECK(r.err.empty()); // OBJ holds everything: no note
        Mesh output;
        const io::MeshAttributes after = attributes_of(out, &output);
        CHECK(output.positions != input.positions);
        CHECK(output.face_vertices == input.face_vertices);
        CHECK(after.texcoords == before.texcoords); // the seam included
        CHECK(after.vertex == before.vertex);
        CHECK(after.statements == before.statements);
        // The normals are those of the smoothed surface (one per vertex, as in the file).
        REQUIRE(after.normals.entry_count() == 441);
        io::MeshAttributes expected = before;
        io::recompute_normals(output, expected);
        CHECK(after.normals.corners == expected.normals.corners);
        for (size_t k = 0; k < after.normals.values.size(); ++k)
            CHECK(after.normals.values[k] == expected.normals.values[k]);
        CHECK(after.normals.values != before.normals.values);
        const auto j = nlohmann::json::parse(io::read_file(report));
        CHECK(j["output_notes"].empty());
        CHECK(j["attributes"][0] == "vertex colours (red green blue: double)");

        // --keep-normals: the file's normals, with a note.
        const Run keep = cli("smooth " + test::shell_quote(in) + " -o " + test::shell_quote(out) +
                             " --iterations 10 --keep-normals -q");
        CHECK(keep.code == 0);
        CHECK(keep.err == "meshfair-cli: note: '" + out +
                              "': normals written as read, not recomputed from the positions "
                              "written\n");
        CHECK(attributes_of(out).normals == before.normals);

        // To PLY: per-corner texture coordinates (the seam) and colours kept, groups named.
        const std::string ply = (dir / "smooth.ply").string();
        const Run to_ply = cli("smooth " + test::shell_quote(in) + " -o " + test::shell_quote(ply) +
                               " --iterations 10 -q");
        CHECK(to_ply.code == 0);
        CHECK(to_ply.err.find("'" + ply +
                              "': PLY cannot hold the OBJ groups, objects, smoothing "
                              "groups and materials 'mtllib patch.mtl', 'o patch', 'g patch', "
                              "'usemtl skin', 's 1'; they are not written") != std::string::npos);
        Mesh from_ply;
        const io::MeshAttributes ply_attributes = attributes_of(ply, &from_ply);
        CHECK(ply_attributes.vertex.find("red")->values == before.vertex.find("red")->values);
        const io::CornerValues t = io::corner_texcoords(from_ply, ply_attributes);
        CHECK(t.corners.size() == 1600);
        bool all_equal = true;
        for (size_t k = 0; k < t.corners.size(); ++k)
            for (size_t a = 0; a < 2; ++a)
                all_equal =
                    all_equal &&
                    t.values[2 * static_cast<size_t>(t.corners[k]) + a] ==
                        before.texcoords
                            .values[2 * static_cast<size_t>(before.texcoords.corners[k]) + a];
        CHECK(all_equal);
    }

    TEST_CASE("an unwritable output exits 3 and leaves the existing file intact")
    {
        const fs::path dir = test::temp_dir();
        const Run r = cli("smooth " + bunny() + " -o " +
                          test::shell_quote((dir / "no" / "such" / "dir.obj").string()));
        CHECK(r.code == 3);
        CHECK(r.err.find("cannot write") != std::string::npos);
        // A directory in the way of the output.
        fs::create_directories(dir / "taken.obj");
        CHECK(cli("smooth " + bunny() + " -o " + test::shell_quote((dir / "taken.obj").string()))
                  .code == 3);
    }
    TEST_CASE("convert writes the same mesh in another format, whatever its coordinates")
    {
        const fs::path dir = test::temp_dir();
        const fs::path in = dir / "far.off", out = dir / "far.ply";
        test::write_bytes(in, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 1e300\n3 0 1 2\n");
        const Run r = cli("convert " + test::shell_quote(in.string()) + " -o " +
                          test::shell_quote(out.string()));
        CHECK(r.code == 0);
        CHECK(io::read_mesh(out.string()) == io::read_mesh(in.string()));
        // Smoothing the same mesh is refused, naming it: its squares would overflow.
        const Run s = cli("smooth " + test::shell_quote(in.string()) + " -o " +
                          test::shell_quote(out.string()));
        CHECK(s.code == 2);
        CHECK(s.err.find("'" + in.string() + "': vertex 2 has the coordinate 1e+300") !=
              std::string::npos);
    }

    TEST_CASE("batch smooths every good file as smooth does, reports and skips the bad ones")
    {
        const fs::path dir = test::temp_dir();
        const fs::path in = dir / "in", out = dir / "batch-out";
        fs::create_directories(in);
        const std::string recipe = (test::assets_dir() / "recipes" / "combined.json").string();
        fs::copy_file(test::assets_dir() / "bunny.obj", in / "bunny.obj");
        test::write_bytes(in / "tri.off",
                          "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0.5\n3 0 1 2\n3 1 3 2\n");
        test::write_bytes(in / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
        const std::vector<std::string> names = {"bunny.obj", "bad.obj", "tri.off"};
        std::string files;
        for (const std::string& name : names)
            files += " " + test::shell_quote((in / name).string());
        const Run r = cli("batch" + files + " --recipe " + test::shell_quote(recipe) +
                          " --out-dir " + test::shell_quote(out.string()) + " --jobs 2");
        CHECK(r.code == 2); // one input rejected
        CHECK(r.err.find("1 of 3 files failed") != std::string::npos);
        // One JSON line per file, in any order; the index says which.
        std::vector<std::string> status(3);
        std::istringstream lines(r.out);
        int count = 0;
        for (std::string line; std::getline(lines, line); ++count)
        {
            const auto j = nlohmann::json::parse(line);
            status.at(j["index"].get<size_t>()) = j["status"].get<std::string>();
            if (j["status"] == "rejected")
                CHECK(j["error"].get<std::string>().find("bad.obj:4:7: vertex index 4") !=
                      std::string::npos);
            else
                CHECK(j["report"]["iterations"].get<int>() == 20);
        }
        CHECK(count == 3);
        CHECK(status == std::vector<std::string>{"ok", "rejected", "ok"});
        CHECK_FALSE(fs::exists(out / "bad.obj"));
        // The same bytes as smooth writes, file by file.
        for (const std::string name : {"bunny.obj", "tri.off"})
        {
            CAPTURE(name);
            const fs::path single = dir / ("single-" + name);
            REQUIRE(cli("smooth " + test::shell_quote((in / name).string()) + " -o " +
                        test::shell_quote(single.string()) + " --recipe " +
                        test::shell_quote(recipe) + " -q")
                        .code == 0);
            CHECK(io::read_file((out / name).string()) == io::read_file(single.string()));
        }
        // --format changes the outputs' extension; all good files: exit 0.
        const Run ply = cli("batch " + test::shell_quote((in / "tri.off").string()) + " --recipe " +
                            test::shell_quote(recipe) + " --out-dir " +
                            test::shell_quote(out.string()) + " --format ply");
        CHECK(ply.code == 0);
        CHECK(io::read_mesh((out / "tri.ply").string()).vertex_count() == 4);

        // Attributes are kept as smooth keeps them, and what the format cannot hold is in
        // the file's report.
        test::write_bytes(in / "patch.obj", textured_patch_obj());
        const Run stl = cli("batch " + test::shell_quote((in / "patch.obj").string()) +
                            " --recipe " + test::shell_quote(recipe) + " --out-dir " +
                            test::shell_quote(out.string()) + " --format stl");
        CHECK(stl.code == 0);
        const auto line = nlohmann::json::parse(stl.out);
        CHECK(line["report"]["output_notes"][0] ==
              "STL cannot hold the vertex properties 'red', 'green', 'blue'; they are not written");
        const Run obj =
            cli("batch " + test::shell_quote((in / "patch.obj").string()) + " --recipe " +
                test::shell_quote(recipe) + " --out-dir " + test::shell_quote(out.string()));
        CHECK(obj.code == 0);
        CHECK(attributes_of((out / "patch.obj").string()).texcoords ==
              attributes_of((in / "patch.obj").string()).texcoords);
    }

    TEST_CASE("batch refuses before any work: two inputs to one output, a bad recipe")
    {
        const fs::path dir = test::temp_dir();
        fs::create_directories(dir / "a");
        fs::create_directories(dir / "b");
        fs::copy_file(test::assets_dir() / "bunny.obj", dir / "a" / "m.obj");
        fs::copy_file(test::assets_dir() / "bunny.obj", dir / "b" / "m.obj");
        const std::string recipe = (test::assets_dir() / "recipes" / "combined.json").string();
        const fs::path out = dir / "out";
        const Run twice =
            cli("batch " + test::shell_quote((dir / "a" / "m.obj").string()) + " " +
                test::shell_quote((dir / "b" / "m.obj").string()) + " --recipe " +
                test::shell_quote(recipe) + " --out-dir " + test::shell_quote(out.string()));
        CHECK(twice.code == 2);
        CHECK(twice.err.find("would both be written to") != std::string::npos);
        CHECK_FALSE(fs::exists(out));
        const std::string bad = (dir / "r.json").string();
        test::write_bytes(bad, R"({"lambda": "fast"})");
        const Run recipe_error =
            cli("batch " + test::shell_quote((dir / "a" / "m.obj").string()) + " --recipe " +
                test::shell_quote(bad) + " --out-dir " + test::shell_quote(out.string()));
        CHECK(recipe_error.code == 2);
        CHECK(recipe_error.err.find("lambda") != std::string::npos);
        CHECK_FALSE(fs::exists(out));
    }

    TEST_CASE("the CLI opens no file but those on its command line (strace)")
    {
        // An OBJ naming a material library beside it, and a recipe: only the mesh, the
        // recipe, the outputs and their temporaries may be opened, never the library.
        const fs::path dir = test::temp_dir();
        const fs::path mesh = dir / "scan.obj", mtl = dir / "secret.mtl", recipe = dir / "r.json",
                       out = dir / "out.obj", log = dir / "trace";
        test::write_bytes(mesh,
                          "mtllib secret.mtl\nusemtl skin\nv 0 0 0\nv 1 0 0\nv 0 1 "
                          "0\nv 1 1 1\nf 1 2 3\nf 2 4 3\n");
        test::write_bytes(mtl, "newmtl skin\nmap_Kd /etc/passwd\n");
        test::write_bytes(recipe, "{\"iterations\": 2}\n");
        // LeakSanitizer cannot run under ptrace: the sanitizer build turns it off here.
        const std::string traced =
            "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" strace -f -qq -e "
            "trace=open,openat,openat2,creat -o " +
            test::shell_quote(log.string()) + " " + test::shell_quote(MESHFAIR_CLI) + " ";
        const std::string args = "smooth " + test::shell_quote(mesh.string()) + " --recipe " +
                                 test::shell_quote(recipe.string()) + " -o " +
                                 test::shell_quote(out.string()) + " --report " +
                                 test::shell_quote((dir / "report.json").string()) + " -q";
        const int status = std::system((traced + args + " 2>/dev/null").c_str());
        INFO("strace must be installed (.ci/setup.sh test installs it)");
        REQUIRE(WIFEXITED(status));
        REQUIRE(WEXITSTATUS(status) == 0);
        std::vector<std::string> opened;
        for (std::string rest = io::read_file(log.string()); !rest.empty();)
        {
            const std::string line = rest.substr(0, rest.find('\n'));
            rest = rest.size() > line.size() ? rest.substr(line.size() + 1) : "";
            const auto a = line.find('"'), b = line.find('"', a + 1);
            if (a != std::string::npos && b != std::string::npos)
                opened.push_back(line.substr(a + 1, b - a - 1));
        }
        REQUIRE(!opened.empty());
        std::vector<std::string> unexpected;
        for (const std::string& path : opened)
        {
            // The loader, the C library, and the OpenMP runtime: GCC's counts the CPUs,
            // LLVM's (the sanitizer build) also reads its message catalogue and registers
            // itself in /dev/shm.
            const bool system =
                path.starts_with("/etc/ld.so") || path.starts_with("/lib") ||
                path.starts_with("/usr/lib") || path.starts_with("/proc/self/") ||
                path.starts_with("/sys/devices/system/cpu/") ||
                (path.starts_with("/usr/share/locale/") && path.ends_with("/libomp.cat")) ||
                path.starts_with("/dev/shm/__KMP_REGISTERED_LIB_");
            const bool named = path == mesh.string() || path == recipe.string() ||
                               path.starts_with(out.string() + ".tmp-") ||
                               path.starts_with((dir / "report.json").string() + ".tmp-") ||
                               path == dir.string() || path == dir.string() + "/"; // fsync
            if (!system && !named)
                unexpected.push_back(path);
        }
        std::string listed;
        for (const std::string& path : unexpected)
            listed += " " + path;
        CHECK_MESSAGE(unexpected.empty(), "opened:" << listed);
    }
}
