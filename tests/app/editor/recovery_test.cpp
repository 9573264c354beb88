// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Recovery files: a round trip of the whole edit state, offered only when their editor is
// gone, refused with the file named when damaged or for another mesh.
#include "app/editor/recovery.h"

#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "core/io/io.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;
namespace fs = std::filesystem;

namespace {

// A pid that no process has: a child that has exited and been reaped.
long dead_pid()
{
    const pid_t child = fork();
    if (child == 0)
        _exit(0);
    int status = 0;
    waitpid(child, &status, 0);
    return child;
}

Document edited(const fs::path& dir)
{
    const fs::path mesh = dir / "grid.obj";
    io::write_mesh(test::open_grid(6, 5), mesh.string());
    Document d = load_document(mesh.string());
    d.mesh.positions[4] += 0.25;
    d.base_positions[7] -= 0.5;
    d.selected_vertices[3] = 1;
    d.selected_faces[2] = 1;
    ConstraintSet pins{"pins", ConstraintKind::Pin, {1, 5}, {},   {{0, 0, 1}, {1, 1, 1}},
                       {},     {1, 0, 0},           true,   true, std::nullopt,
                       {}};
    // A set out of the solve with a weight of its own: both kept.
    ConstraintSet normals{"up",      ConstraintKind::Normal,
                          {},        {0, 4},
                          {},        {{0, 1, 0}, {0, 1, 0}},
                          {0, 0, 1}, false,
                          false,     2.5,
                          {}};
    // A painted region: its weight map comes back bit for bit.
    ConstraintSet painted{
        "brush", ConstraintKind::Region, {2, 3, 9},      {}, {}, {}, {0, 1, 0}, true,
        true,    std::nullopt,           {0.125, 1, 0.1}};
    d.sets = {pins, normals, painted};
    d.solver.lambda = 0.25;
    d.solver.joint = true;
    // The settings of denoising, Taubin's method, the volume and the falloff come back too.
    d.solver.method = Method::Taubin;
    d.solver.taubin_mu = -0.6;
    d.solver.bilateral = BilateralWeights{2.0, 0.3, 3, FaceNeighborhood::Vertex, 1.0};
    d.solver.keep_volume = true;
    d.solver.falloff = Falloff{5.0, false, FalloffCurve::Sharp, 2.0, true, false};
    d.steps_from_base = 17;
    d.reproducible = false;
    return d;
}

// Makes the recovery files look as if a crashed editor had written them.
void orphan(const std::string& dir)
{
    const fs::path state = fs::path(dir) / "state.json";
    std::string text = io::read_file(state.string());
    const std::string key = "\"pid\": ";
    const size_t at = text.find(key) + key.size();
    text.replace(at, text.find(',', at) - at, std::to_string(dead_pid()));
    io::write_file_atomically(state.string(), text);
}

// Writes the recovery files of `d` under `root`; returns their folder.
std::string written_folder(const Document& d, const std::string& root)
{
    write_recovery(d, root);
    std::string folder;
    for (const auto& entry : fs::directory_iterator(root))
        folder = entry.path().string();
    return folder;
}

} // namespace

TEST_SUITE("Recovery")
{
    TEST_CASE("the whole edit state comes back, once its editor is gone")
    {
        const fs::path dir = test::temp_dir();
        const std::string root = (dir / "recovery").string();
        Document d = edited(dir);
        d.up_axis = UpAxis::NegZ; // (the file's up axis travels with its edit state)
        write_recovery(d, root);
        // Written by this (running) process: not offered.
        CHECK_FALSE(find_recovery(d.path, root));
        std::optional<RecoveryInfo> info;
        for (const auto& entry : fs::directory_iterator(root))
            info = RecoveryInfo{entry.path().string(), d.path, 0, ""};
        REQUIRE(info);
        orphan(info->dir);
        const std::optional<RecoveryInfo> offer = find_recovery(d.path, root);
        REQUIRE(offer);
        CHECK(offer->saved_at.size() == 19);
        CHECK_FALSE(find_recovery((dir / "other.obj").string(), root));

        Document fresh = load_document(d.path);
        restore_recovery(*offer, fresh);
        CHECK(fresh.mesh.positions == d.mesh.positions);
        CHECK(fresh.base_positions == d.base_positions);
        CHECK(fresh.selected_vertices == d.selected_vertices);
        CHECK(fresh.selected_faces == d.selected_faces);
        CHECK((fresh.sets == d.sets));
        CHECK((fresh.solver == d.solver));
        CHECK(fresh.steps_from_base == 17);
        CHECK(fresh.up_axis == UpAxis::NegZ);
        CHECK_FALSE(fresh.reproducible);
        CHECK(fresh.modified);
        remove_recovery(d.path, root);
        CHECK_FALSE(find_recovery(d.path, root));
    }

    TEST_CASE("damaged files and another mesh's files are refused, the document kept")
    {
        const fs::path dir = test::temp_dir();
        const std::string root = (dir / "recovery").string();
        const Document d = edited(dir);
        const std::string folder = written_folder(d, root);
        orphan(folder);
        const RecoveryInfo info = *find_recovery(d.path, root);

        // Another mesh under the same name: other counts.
        Document other = make_document(test::open_grid(3, 3), d.path);
        const std::vector<Scalar> before = other.mesh.positions;
        CHECK_THROWS_WITH_AS(restore_recovery(info, other),
                             doctest::Contains("saved for a mesh of 42 vertices and 30 faces"),
                             InvalidInputError);
        CHECK(other.mesh.positions == before);

        // A truncated positions file.
        Document same = load_document(d.path);
        const std::string positions = (fs::path(folder) / "positions.bin").string();
        io::write_file_atomically(positions, io::read_file(positions).substr(8));
        CHECK_THROWS_WITH_AS(restore_recovery(info, same), doctest::Contains("positions.bin"),
                             InvalidInputError);
        // A state file that is not JSON.
        write_recovery(d, root);
        orphan(folder);
        io::write_file_atomically((fs::path(folder) / "state.json").string(), "{\"mesh\": ");
        CHECK_FALSE(find_recovery(d.path, root)); // nothing to offer
        CHECK_THROWS_WITH_AS(restore_recovery(info, same),
                             doctest::Contains("damaged recovery file"), InvalidInputError);
    }

    TEST_CASE("recovery files holding what no editor writes are refused, with what is wrong named")
    {
        const fs::path dir = test::temp_dir();
        const std::string root = (dir / "recovery").string();
        const Document d = edited(dir);
        const std::string folder = written_folder(d, root);
        const auto file = [&](const char* name) {
            return io::read_file((fs::path(folder) / name).string());
        };
        const RecoveryFiles written{folder, file("state.json"), file("positions.bin"),
                                    file("base.bin"), file("selection.bin")};
        {
            Document fresh = load_document(d.path);
            restore_recovery_files(written, fresh);
            CHECK(fresh.mesh.positions == d.mesh.positions);
            CHECK(fresh.sets == d.sets);
            CHECK(fresh.solver == d.solver);
        }
        using Json = nlohmann::json;
        const Json state = Json::parse(written.state);
        // Each a change of one file, and the words the refusal must hold.
        struct Damage
        {
            const char* what;
            std::function<void(RecoveryFiles&, Json&)> apply;
        };
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const std::vector<Damage> damages = {
            {"vertex 2 has a coordinate",
             [&](RecoveryFiles& f, Json&) { std::memcpy(f.positions.data() + 7 * 8, &nan, 8); }},
            {"base.bin': vertex 0",
             [&](RecoveryFiles& f, Json&) { std::memcpy(f.base.data(), &nan, 8); }},
            {"byte 5 is 2", [](RecoveryFiles& f, Json&) { f.selection[5] = 2; }},
            {"indices of this mesh's vertices",
             [](RecoveryFiles&, Json& j) { j["sets"][0]["vertices"][1] = 42; }},
            {"indices of this mesh's faces",
             [](RecoveryFiles&, Json& j) { j["sets"][1]["faces"][0] = 1.5; }},
            {"targets must be one per vertex",
             [](RecoveryFiles&, Json& j) { j["sets"][0]["targets"].erase(1); }},
            {"normals must be one per face",
             [](RecoveryFiles&, Json& j) {
                 j["sets"][1]["normals"].push_back({0, 0, 1});
             }},
            {"[x, y, z]",
             [](RecoveryFiles&, Json& j) {
                 j["sets"][0]["targets"][0] = {1, 2};
             }},
            {"colour must be fractions",
             [](RecoveryFiles&, Json& j) { j["sets"][2]["color"][1] = 1e300; }},
            {"weight map needs an anchor or region set",
             [](RecoveryFiles&, Json& j) {
                 j["sets"][0]["weights"] = {0.5, 0.5};
             }},
            {"mu must be a number >= 0", [](RecoveryFiles&, Json& j) { j["sets"][1]["mu"] = -1; }},
            {"lambda must be a number > 0",
             [](RecoveryFiles&, Json& j) { j["solver"]["lambda"] = 0; }},
            {"iterations_per_frame must be an integer from 1",
             [](RecoveryFiles&, Json& j) { j["solver"]["iterations_per_frame"] = 0; }},
            {"normal_smoothing_iterations must be an integer",
             [](RecoveryFiles&, Json& j) { j["solver"]["normal_smoothing_iterations"] = 1e20; }},
            {"steps_from_base must be an integer",
             [](RecoveryFiles&, Json& j) { j["steps_from_base"] = -3; }},
            {"sets must be a list", [](RecoveryFiles&, Json& j) { j["sets"] = 7; }},
        };
        for (const Damage& damage : damages)
        {
            CAPTURE(damage.what);
            RecoveryFiles files = written;
            Json j = state;
            damage.apply(files, j);
            files.state = j.dump(1);
            Document fresh = load_document(d.path);
            const std::vector<Scalar> before = fresh.mesh.positions;
            CHECK_THROWS_WITH_AS(restore_recovery_files(files, fresh),
                                 doctest::Contains(damage.what), InvalidInputError);
            CHECK(fresh.mesh.positions == before);
            CHECK(fresh.sets.empty());
        }
    }
}
