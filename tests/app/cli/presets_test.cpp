// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Every preset of assets/recipes/ on every kind of mesh users bring, through meshfair-cli:
// closed, open with one and with many boundary loops, several components, quads and mixed
// polygons, non-manifold edges and vertices, isolated vertices; a point cloud refused.
// Each run exits 0 and turns no face over. The smoothing presets keep each component's
// volume (capped by its boundary loops where it is open) within 0.5 %; fair-region, which
// fairs a region (and changes its shape by design), is given one on every mesh, leaves
// every vertex outside it where it was, and refuses a whole mesh with the reason. The
// volumes and loops are measured here by code of the test's own (maps, not the solver's
// arrays).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "tests/helpers.h"

using namespace meshfair;
namespace fs = std::filesystem;

namespace {

const char* const kPresets[] = {"denoise", "denoise-organic", "relax", "fair-region", "combined"};

using test::cli;

//! The faces of m that `keep` accepts (by their centroid), unused vertices dropped.
template <class Keep>
Mesh kept_faces(const Mesh& m, Keep keep)
{
    std::vector<Index> renumber(m.vertex_count(), kInvalidIndex);
    Mesh out;
    for (Index f = 0; f < m.face_count(); ++f)
    {
        if (!keep(face_centroid(m, m.positions, f)))
            continue;
        std::vector<Index> face;
        for (const Index v : m.face(f))
        {
            if (renumber[v] == kInvalidIndex)
            {
                renumber[v] = out.vertex_count();
                out.add_vertex(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
            }
            face.push_back(renumber[v]);
        }
        out.add_face(face);
    }
    return out;
}

Mesh bunny_mesh()
{
    return io::read_mesh((test::assets_dir() / "bunny.obj").string());
}

//! The bunny below a plane cut away: an open scan with one boundary loop.
Mesh open_bunny()
{
    const Mesh b = bunny_mesh();
    const BoundingBox box = bounding_box(b.positions);
    const Scalar cut = box.min[1] + 0.25 * (box.max[1] - box.min[1]);
    return kept_faces(b, [&](const Vec3& c) { return c[1] > cut; });
}

//! The bunny with twelve holes of 3 % of its diagonal around vertices spread over it.
Mesh holed_bunny()
{
    const Mesh b = bunny_mesh();
    const Scalar r = 0.03 * bounding_box(b.positions).diagonal();
    std::vector<Vec3> centres;
    for (Index k = 0; k < 12; ++k)
        centres.push_back(b.position((k * 2903 + 17) % b.vertex_count()));
    return kept_faces(b, [&](const Vec3& c) {
        return std::ranges::all_of(centres, [&](const Vec3& p) {
            return std::hypot(c[0] - p[0], c[1] - p[1], c[2] - p[2]) > r;
        });
    });
}

//! A wavy open quad grid (a height field), its z perturbed.
Mesh wavy_grid(int n)
{
    Mesh m = test::open_grid(n, n);
    for (Index v = 0; v < m.vertex_count(); ++v)
        m.positions[3 * v + 2] =
            0.2 * std::sin(0.9 * m.positions[3 * v]) * std::cos(0.7 * m.positions[3 * v + 1]);
    return m;
}

//! Two closed tetrahedra sharing one vertex, both oriented outwards: a non-manifold
//! (pinched) vertex.
Mesh pinched_tetrahedra()
{
    return test::make_mesh(
        {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
        {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}});
}

//! Three sheets of triangles on one edge (a non-manifold edge), each a fan of 4 triangles.
Mesh book_of_three()
{
    std::vector<Vec3> points = {{0, 0, 0}, {0, 0, 1}};
    std::vector<std::vector<Index>> faces;
    for (int sheet = 0; sheet < 3; ++sheet)
    {
        const Scalar angle = 2.1 * sheet, c = std::cos(angle), s = std::sin(angle);
        const Index first = static_cast<Index>(points.size());
        for (int k = 0; k < 3; ++k)
            points.push_back({c * (1 + 0.3 * k), s * (1 + 0.3 * k), 0.5 * k});
        faces.push_back({0, 1, first});
        faces.push_back({1, first + 2, first + 1});
        faces.push_back({1, first + 1, first});
    }
    return test::make_mesh(points, faces);
}

//! Each component's volume, capped where it is open: the faces fanned from their first
//! corners, plus for each loop of the boundary chain (edges traversed more often one way
//! than the other) the fan (p, b, a) from the loop's centroid p. Open: it has a loop.
struct Volumes
{
    std::vector<Scalar> volume;
    std::vector<char> open;
};

Scalar det(const Vec3& a, const Vec3& b, const Vec3& c)
{
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

Volumes capped_volumes(const Mesh& m)
{
    std::vector<Index> parent(m.vertex_count());
    std::iota(parent.begin(), parent.end(), Index(0));
    const auto root = [&](Index v) {
        while (parent[v] != v)
            v = parent[v];
        return v;
    };
    for (Index f = 0; f < m.face_count(); ++f)
        for (const Index v : m.face(f))
            parent[root(v)] = root(m.face(f)[0]);
    std::map<Index, size_t> component; // root -> number
    std::vector<size_t> of_face;
    for (Index f = 0; f < m.face_count(); ++f)
        of_face.push_back(
            component.try_emplace(root(m.face(f)[0]), component.size()).first->second);
    Volumes out{std::vector<Scalar>(component.size(), 0), std::vector<char>(component.size(), 0)};
    std::map<std::pair<Index, Index>, int> net; // (low, high) -> traversals low->high minus back
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const auto face = m.face(f);
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Index a = face[k], b = face[(k + 1) % face.size()];
            net[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
        }
        for (size_t k = 1; k + 1 < face.size(); ++k)
            out.volume[of_face[f]] +=
                det(m.position(face[0]), m.position(face[k]), m.position(face[k + 1])) / 6;
    }
    std::map<Index, std::vector<Index>> next; // the chain's edges leaving each vertex
    for (const auto& [edge, count] : net)
        for (int c = 0; c < std::abs(count); ++c)
            next[count > 0 ? edge.first : edge.second].push_back(count > 0 ? edge.second
                                                                           : edge.first);
    for (auto& [start, targets] : next)
        while (!targets.empty())
        {
            std::vector<Index> loop{start};
            for (Index v = start;;)
            {
                const Index w = next[v].front();
                next[v].erase(next[v].begin());
                if (w == start)
                    break;
                loop.push_back(v = w);
            }
            Vec3 p{0, 0, 0};
            for (const Index v : loop)
                for (int a = 0; a < 3; ++a)
                    p[a] += m.position(v)[a] / static_cast<Scalar>(loop.size());
            const size_t c = component.at(root(start));
            out.open[c] = 1;
            for (size_t k = 0; k < loop.size(); ++k)
                out.volume[c] +=
                    det(p, m.position(loop[(k + 1) % loop.size()]), m.position(loop[k])) / 6;
        }
    return out;
}

using test::dot;

//! \brief Faces turned over: their Newell vector more than 90 degrees from the input's.
//! Counted among the faces that lie in the input surface, within 60 degrees of the surface
//! around them (the sum of the Newell vectors of the faces sharing a vertex with them, each
//! once per vertex it shares); a face the input itself has folded or pinched may be turned
//! back into the surface (docs/math.md, "Faces never turned over"). Those are in `odd`.
int turned_over(const Mesh& before, const Mesh& after, int* odd = nullptr)
{
    std::vector<Vec3> own(before.face_count());
    for (Index f = 0; f < before.face_count(); ++f)
        own[f] = face_area_vector(before, before.positions, f);
    std::vector<std::vector<Index>> faces_at(before.vertex_count());
    for (Index f = 0; f < before.face_count(); ++f)
        for (const Index v : before.face(f))
            faces_at[v].push_back(f);
    int count = 0, others = 0;
    for (Index f = 0; f < before.face_count(); ++f)
    {
        Vec3 around{0, 0, 0};
        for (const Index v : before.face(f))
            for (const Index g : faces_at[v])
                for (int a = 0; a < 3; ++a)
                    around[a] += own[g][a];
        const Vec3 now = face_area_vector(after, after.positions, f);
        if (!(dot(own[f], own[f]) > 0) || dot(own[f], now) > 0)
            continue;
        const bool lies_in_surface =
            dot(own[f], around) > 0.5 * std::sqrt(dot(own[f], own[f]) * dot(around, around));
        ++(lies_in_surface ? count : others);
    }
    if (odd != nullptr)
        *odd = others;
    return count;
}

struct Case
{
    const char* name;
    Mesh mesh;
    size_t open_components, closed_components;
};

std::string preset(const char* name)
{
    return test::shell_quote(
        (test::assets_dir() / "recipes" / (std::string(name) + ".json")).string());
}

//! Whether the preset fairs a region (and refuses a whole mesh): fair-region.
bool fairs_a_region(const std::string& name)
{
    return name == "fair-region";
}

//! \brief The region a test gives fair-region on `m`: every vertex of a face but the first
//! corners of every fourth face, which stay fixed (each component has some, so each free
//! part is held), and the vertices of no face (which a selection of faces never takes).
std::vector<Index> test_region(const Mesh& m)
{
    std::vector<char> in(m.vertex_count(), 0);
    for (Index f = 0; f < m.face_count(); ++f)
        for (const Index v : m.face(f))
            in[v] = 1;
    for (Index f = 0; f < m.face_count(); f += 4)
        in[m.face(f)[0]] = 0;
    std::vector<Index> region;
    for (Index v = 0; v < m.vertex_count(); ++v)
        if (in[v])
            region.push_back(v);
    return region;
}

//! \brief The recipe file a run of preset `name` on `m` takes, written in `dir`: the
//! preset's own, with test_region(m) added for fair-region.
std::string preset_on(const char* name, const Mesh& m, const fs::path& dir)
{
    if (!fairs_a_region(name))
        return preset(name);
    auto recipe = nlohmann::json::parse(
        io::read_file((test::assets_dir() / "recipes" / (std::string(name) + ".json")).string()));
    recipe["region"] = {{"vertices", test_region(m)}};
    const fs::path file = dir / (std::string(name) + "-with-region.json");
    test::write_bytes(file, recipe.dump());
    return test::shell_quote(file.string());
}

//! Runs every preset on the case's mesh and checks what the issue asks of each run.
void check_presets(const Case& c)
{
    CAPTURE(c.name);
    const fs::path dir = test::temp_dir();
    const fs::path in = dir / (std::string(c.name) + ".off");
    io::write_mesh(c.mesh, in.string());
    const Volumes v0 = capped_volumes(c.mesh);
    REQUIRE(static_cast<size_t>(std::ranges::count(v0.open, 1)) == c.open_components);
    REQUIRE(static_cast<size_t>(std::ranges::count(v0.open, 0)) == c.closed_components);
    const Scalar scale = std::pow(bounding_box(c.mesh.positions).diagonal(), 3);
    for (const char* name : kPresets)
    {
        CAPTURE(name);
        const fs::path out = dir / (std::string(name) + ".off"), report = dir / "report.json";
        const test::CommandRun r =
            cli("smooth " + test::shell_quote(in.string()) + " -o " +
                test::shell_quote(out.string()) + " --recipe " + preset_on(name, c.mesh, dir) +
                " --report " + test::shell_quote(report.string()));
        REQUIRE_MESSAGE(r.code == 0, r.err);
        const Mesh after = io::read_mesh(out.string());
        CHECK(turned_over(c.mesh, after) == 0);
        if (fairs_a_region(name))
        {
            // Outside the region nothing moves; inside, the thin plate moved the surface.
            const std::vector<Index> region = test_region(c.mesh);
            Scalar moved = 0;
            for (Index v = 0; v < c.mesh.vertex_count(); ++v)
            {
                const bool free = std::binary_search(region.begin(), region.end(), v);
                for (int a = 0; a < 3; ++a)
                {
                    const Scalar d =
                        std::abs(after.positions[3 * v + a] - c.mesh.positions[3 * v + a]);
                    if (free)
                        moved = std::max(moved, d);
                    else
                        CHECK(d == 0);
                }
            }
            CHECK(moved > 0);
            // A whole mesh has no region to fair: refused with the reason, nothing written.
            const fs::path whole = dir / "whole.off";
            const test::CommandRun refused =
                cli("smooth " + test::shell_quote(in.string()) + " -o " +
                    test::shell_quote(whole.string()) + " --recipe " + preset(name));
            CHECK(refused.code == 2);
            CHECK(refused.err.find("is held by nothing") != std::string::npos);
            CHECK_FALSE(fs::exists(whole));
            continue;
        }
        const Volumes v1 = capped_volumes(after);
        for (size_t k = 0; k < v0.volume.size(); ++k)
        {
            CAPTURE(k);
            CAPTURE(v0.volume[k]);
            CAPTURE(v1.volume[k]);
            CHECK(std::abs(v1.volume[k] - v0.volume[k]) <=
                  0.005 * std::abs(v0.volume[k]) + 1e-12 * scale);
        }
        const auto j = nlohmann::json::parse(io::read_file(report.string()));
        // The guard's count, step by step, adds up to its total.
        const auto& guard = j["flip_guard"];
        REQUIRE(guard["shortened"].size() == j["iterations"].get<size_t>());
        long long sum = 0;
        for (const auto& n : guard["shortened"])
            sum += n.get<long long>();
        CHECK(guard["total"].get<long long>() == sum);
        // Open components are named, with the rule that keeps them, in the report.
        const bool noted = std::ranges::any_of(j["notes"], [](const nlohmann::json& note) {
            return note.get<std::string>().find("capped by fans from the loops' centroids") !=
                   std::string::npos;
        });
        CHECK(noted == (c.open_components > 0));
    }
}

} // namespace

TEST_SUITE("Presets")
{
    TEST_CASE("every preset on closed meshes: the bunny, a quad torus, pinched tetrahedra")
    {
        check_presets({"bunny", bunny_mesh(), 0, 1});
        check_presets({"quad torus", test::quad_torus(24, 12, 2.0, 0.7), 0, 1});
        check_presets({"pinched", pinched_tetrahedra(), 0, 1});
    }

    TEST_CASE("every preset on open meshes: one loop, twelve holes, quads, mixed polygons")
    {
        check_presets({"open bunny", open_bunny(), 1, 0});
        check_presets({"holed bunny", holed_bunny(), 1, 0});
        check_presets({"wavy grid", wavy_grid(12), 1, 0});
        check_presets({"mixed polygons", test::mixed_polygons(), 1, 0});
    }

    TEST_CASE("every preset on several components, a non-manifold edge, isolated vertices")
    {
        Mesh sphere = test::icosphere(3);
        test::perturb(sphere, 0.01, 5);
        check_presets({"sphere and grid", test::joined(sphere, wavy_grid(8), {3, 0, 0}), 1, 1});
        check_presets({"book of three", book_of_three(), 1, 0});
        Mesh isolated = sphere;
        isolated.add_vertex(5, 5, 5);
        isolated.add_vertex(-5, 0, 1);
        check_presets({"isolated vertices", isolated, 0, 1});
    }

    TEST_CASE("the presets turn faces of the bunny over without the flip guard")
    {
        // What the guard prevents is there to prevent: the same recipes without it.
        const fs::path dir = test::temp_dir();
        const Mesh b = bunny_mesh();
        int without = 0;
        for (const char* name : kPresets)
        {
            CAPTURE(name);
            auto recipe = nlohmann::json::parse(io::read_file(
                (test::assets_dir() / "recipes" / (std::string(name) + ".json")).string()));
            if (fairs_a_region(name))
                recipe["region"] = {{"vertices", test_region(b)}};
            REQUIRE(recipe["prevent_flips"] == true);
            recipe.erase("prevent_flips");
            test::write_bytes(dir / "raw.json", recipe.dump());
            const fs::path out = dir / "raw.off";
            REQUIRE(cli("smooth " + test::shell_quote((test::assets_dir() / "bunny.obj").string()) +
                        " -o " + test::shell_quote(out.string()) + " -q --recipe " +
                        test::shell_quote((dir / "raw.json").string()))
                        .code == 0);
            without += turned_over(b, io::read_mesh(out.string()));
        }
        CHECK(without > 0);
    }

    TEST_CASE("batch runs a preset over a folder of open scans, one malformed: the others finish")
    {
        const fs::path dir = test::temp_dir();
        const fs::path in = dir / "scans", out = dir / "smoothed";
        fs::create_directories(in);
        io::write_mesh(open_bunny(), (in / "open.ply").string());
        io::write_mesh(holed_bunny(), (in / "holed.off").string());
        test::write_bytes(in / "torn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 9\n");
        std::string files;
        for (const char* name : {"open.ply", "torn.obj", "holed.off"})
            files += " " + test::shell_quote((in / name).string());
        const test::CommandRun r = cli("batch" + files + " --recipe " + preset("denoise") +
                                       " --out-dir " + test::shell_quote(out.string()));
        CHECK(r.code == 2); // the worst failure: a malformed file
        std::vector<std::string> status(3);
        std::istringstream lines(r.out);
        for (std::string line; std::getline(lines, line);)
        {
            const auto j = nlohmann::json::parse(line);
            const size_t k = j["index"].get<size_t>();
            status.at(k) = j["status"].get<std::string>();
            if (k == 1)
                CHECK(j["error"].get<std::string>().find("torn.obj:5:7: vertex index 9") !=
                      std::string::npos);
            else
            {
                CHECK(j["report"]["flip_guard"]["shortened"].size() ==
                      j["report"]["iterations"].get<size_t>());
                CHECK(j["report"]["notes"].dump().find("capped by fans") != std::string::npos);
            }
        }
        CHECK(status == std::vector<std::string>{"ok", "rejected", "ok"});
        for (const char* name : {"open.ply", "holed.off"})
        {
            CAPTURE(name);
            const Mesh before = io::read_mesh((in / name).string());
            const Mesh after = io::read_mesh((out / name).string());
            CHECK(turned_over(before, after) == 0);
            const Volumes v0 = capped_volumes(before), v1 = capped_volumes(after);
            CHECK(std::abs(v1.volume[0] - v0.volume[0]) <= 0.005 * std::abs(v0.volume[0]));
        }
        CHECK_FALSE(fs::exists(out / "torn.obj"));
    }

    TEST_CASE("a point cloud is refused by every preset: it has no faces")
    {
        const fs::path dir = test::temp_dir();
        test::write_bytes(dir / "cloud.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\n");
        for (const char* name : kPresets)
        {
            CAPTURE(name);
            const test::CommandRun r =
                cli("smooth " + test::shell_quote((dir / "cloud.obj").string()) + " -o " +
                    test::shell_quote((dir / "out.obj").string()) + " --recipe " + preset(name));
            CHECK(r.code == 2);
            CHECK(r.err.find("cloud.obj': the mesh has no faces (a point cloud of 4 vertices)") !=
                  std::string::npos);
            CHECK_FALSE(fs::exists(dir / "out.obj"));
        }
    }
}
