// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/session.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"
#include "core/solver/solver.h"
#include "tests/helpers.h"
#include "tests/session_checks.h"

using namespace meshfair;

namespace {

using test::noisy;
using test::RecipeCase;

// The list without repeats, in order (small meshes make some picks coincide).
std::vector<Index> distinct(std::initializer_list<Index> picks)
{
    std::vector<Index> out;
    for (const Index p : picks)
        if (std::find(out.begin(), out.end(), p) == out.end())
            out.push_back(p);
    return out;
}

// Every term of the paper on a mesh, alone and combined (normals held fixed).
std::vector<RecipeCase> configurations(const Mesh& m)
{
    const Index nv = m.vertex_count(), nf = m.face_count();
    std::vector<RecipeCase> cases;
    Recipe base;
    base.iterations = 20;
    cases.push_back({"edge", base});

    Recipe hard = base;
    hard.hard = HardVertices{{0, nv / 2, nv - 1}, {}};
    cases.push_back({"edge + hard", hard});

    Recipe region = base;
    region.region = Region{};
    for (Index v = 0; v < nv; v += 2)
        region.region->vertices.push_back(v);
    cases.push_back({"region", region});

    Recipe soft = base;
    soft.soft = SoftVertices{};
    soft.soft->vertices.all = true;
    soft.soft->mu = 0.5;
    cases.push_back({"soft", soft});

    for (const auto d : {CentroidDenominator::Paper, CentroidDenominator::Exact})
    {
        Recipe centroid = base;
        centroid.centroid = CentroidConstraints{};
        centroid.centroid->faces.all = true;
        centroid.centroid->mu = 1.0;
        centroid.centroid->denominator = d;
        cases.push_back(
            {d == CentroidDenominator::Paper ? "centroid paper" : "centroid exact", centroid});
    }

    Recipe normal = base;
    normal.normal = NormalConstraints{};
    normal.normal->faces.all = true;
    normal.normal->mu = 2.0;
    cases.push_back({"normal", normal});

    Recipe smoothed = normal;
    smoothed.normal->source = NormalSource::Smoothed;
    smoothed.normal_smoothing = NormalSmoothing{};
    cases.push_back({"smoothed normals", smoothed});

    Recipe all = base;
    all.region = Region{};
    for (Index v = 1; v < nv; ++v)
        all.region->vertices.push_back(v);
    all.hard = HardVertices{{nv / 3}, {}};
    all.soft = SoftVertices{{false, {2, nv - 2}}, 0.3, {}};
    all.centroid = CentroidConstraints{
        {false, distinct({0, nf / 2, nf - 1})}, 1.0, {}, CentroidDenominator::Paper};
    all.normal =
        NormalConstraints{{false, distinct({1, nf / 3, nf - 2})}, 1.5, NormalSource::Smoothed, {}};
    all.normal_smoothing = NormalSmoothing{5, 0.5, {{nf - 1}, {}}, {{0}, 0.5, {}}};
    cases.push_back({"combined", all});
    return cases;
}

bool same_bits(const Mesh& a, const Mesh& b, Index v)
{
    return std::memcmp(&a.positions[3 * v], &b.positions[3 * v], 3 * sizeof(Scalar)) == 0;
}

} // namespace

TEST_SUITE("Session")
{
    TEST_CASE("each vertex's share of a term's energy sums to the term, for every term")
    {
        for (const Mesh& clean :
             {test::quad_torus(10, 6, 2, 0.6), test::open_grid(4, 3), test::nonmanifold_fan(),
              test::mixed_polygons(), test::icosphere(2)})
        {
            const Mesh m = noisy(clean);
            const Topology t = build_topology(m);
            test::check_energy_never_increases(m, t, configurations(m), false);
        }
    }

    TEST_CASE("the line search wins one step against lambda = 0.5")
    {
        const Mesh m = noisy(test::icosphere(2), 0.05, 2);
        const Topology t = build_topology(m);
        for (RecipeCase c : configurations(m))
        {
            CAPTURE(c.name);
            c.recipe.iterations = 1;
            Mesh fixed = m, optimal = m;
            const Scalar e_fixed = smooth(fixed, t, c.recipe).energies.back().total();
            c.recipe.optimal_step = true;
            const Scalar e_optimal = smooth(optimal, t, c.recipe).energies.back().total();
            CHECK(e_optimal < e_fixed);
        }
    }

    TEST_CASE("hard and out-of-region vertices stay bit-identical, moved pins sit on targets")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        for (const RecipeCase& c : configurations(m))
        {
            CAPTURE(c.name);
            Mesh x = m;
            Recipe r = c.recipe;
            r.iterations = 50;
            smooth(x, t, r);
            if (r.hard)
                for (const Index v : r.hard->vertices)
                    CHECK(same_bits(x, m, v));
            if (r.region)
            {
                std::vector<char> inside(m.vertex_count(), 0);
                for (const Index v : r.region->vertices)
                    inside[v] = 1;
                for (Index v = 0; v < m.vertex_count(); ++v)
                    if (!inside[v])
                        CHECK(same_bits(x, m, v));
            }
        }
        Recipe pinned;
        pinned.iterations = 30;
        pinned.hard = HardVertices{{4, 9}, {{0.5, 0.25, 2.0}, {-1.0, 0.0, 0.125}}};
        Mesh x = m;
        smooth(x, t, pinned);
        CHECK(x.position(4) == pinned.hard->targets[0]);
        CHECK(x.position(9) == pinned.hard->targets[1]);
    }

    TEST_CASE("Laplacian smoothing shrinks a closed mesh to its centroid")
    {
        // Every vertex of the torus has n_i = 4, so the Jacobi iteration keeps the centroid.
        Mesh m = noisy(test::quad_torus(12, 8, 2, 0.7));
        const Topology t = build_topology(m);
        Vec3 centroid{0, 0, 0};
        for (Index i = 0; i < m.vertex_count(); ++i)
            for (int a = 0; a < 3; ++a)
                centroid[a] += m.positions[3 * i + a] / m.vertex_count();
        Recipe r;
        r.iterations = 3000;
        smooth(m, t, r);
        for (Index i = 0; i < m.vertex_count(); ++i)
            for (int a = 0; a < 3; ++a)
                CHECK(m.positions[3 * i + a] ==
                      doctest::Approx(centroid[a]).epsilon(1e-6).scale(1));
    }

    TEST_CASE("constraints prevent the shrinkage")
    {
        const Mesh m = noisy(test::icosphere(3), 0.01);
        const Topology t = build_topology(m);
        auto radius = [](const Mesh& x) {
            Scalar sum = 0;
            for (Index i = 0; i < x.vertex_count(); ++i)
            {
                const Vec3 p = x.position(i);
                sum += std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            }
            return sum / x.vertex_count();
        };
        Recipe plain;
        plain.iterations = 200;
        Mesh a = m;
        smooth(a, t, plain);
        CHECK(radius(a) < 0.5);
        for (int kind = 0; kind < 3; ++kind)
        {
            Recipe r = plain;
            if (kind == 0)
                r.soft = SoftVertices{{true, {}}, 1.0, {}};
            if (kind == 1)
                r.centroid = CentroidConstraints{{true, {}}, 10.0, {}, CentroidDenominator::Paper};
            if (kind == 2)
                r.normal = NormalConstraints{{true, {}}, 10.0, NormalSource::Initial, {}};
            CAPTURE(kind);
            Mesh b = m;
            smooth(b, t, r);
            CHECK(radius(b) > 0.9);
        }
    }

    TEST_CASE("a planar patch with a fixed boundary stays planar")
    {
        Mesh m = test::open_grid(6, 5);
        for (Index i = 0; i < m.vertex_count(); ++i)
            m.positions[3 * i] += 0.1 * std::sin(i); // in-plane noise only
        const Topology t = build_topology(m);
        Recipe r;
        r.iterations = 100;
        r.hard = HardVertices{};
        for (Index e = 0; e < t.edge_count(); ++e)
            if (t.edge_kind(e) == EdgeKind::Boundary)
                for (const Index v : {t.edge_vertices[2 * e], t.edge_vertices[2 * e + 1]})
                    if (std::find(r.hard->vertices.begin(), r.hard->vertices.end(), v) ==
                        r.hard->vertices.end())
                        r.hard->vertices.push_back(v);
        r.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Initial, {}};
        smooth(m, t, r);
        for (Index i = 0; i < m.vertex_count(); ++i)
            CHECK(m.positions[3 * i + 2] == 0.0);
    }

    TEST_CASE("many Jacobi iterations reach the direct minimizer of the same quadratic")
    {
        const Mesh m = noisy(test::mixed_polygons(), 0.1);
        const Topology t = build_topology(m);
        std::vector<RecipeCase> cases;
        Recipe base;
        base.iterations = 20000;
        base.hard = HardVertices{{0, 3, 8, 11}, {}};
        cases.push_back({"edge + hard", base});
        Recipe soft = base;
        soft.hard.reset();
        soft.soft = SoftVertices{{false, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}}, 0.5, {}};
        cases.push_back({"soft", soft});
        for (const auto d : {CentroidDenominator::Paper, CentroidDenominator::Exact})
        {
            Recipe c = base;
            c.centroid = CentroidConstraints{{false, {0, 1, 2, 3, 4, 5, 6}}, 2.0, {}, d};
            cases.push_back({"centroid", c});
        }
        Recipe normal = base;
        normal.normal =
            NormalConstraints{{false, {0, 1, 2, 3, 4, 5, 6}}, 3.0, NormalSource::Initial, {}};
        cases.push_back({"normal", normal});
        Recipe all = normal;
        all.hard = HardVertices{{0, 11}, {}};
        all.soft = SoftVertices{{false, {3, 8, 12}}, 0.5, {}};
        all.centroid = CentroidConstraints{{false, {1, 5}}, 2.0, {}, CentroidDenominator::Paper};
        cases.push_back({"combined", all});
        test::check_reaches_direct_minimizer(m, t, cases);
    }

    TEST_CASE("precompute once + k steps equals k one-shot runs, bit for bit")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        for (const RecipeCase& c : configurations(m))
        {
            CAPTURE(c.name);
            Mesh a = m;
            Session session(a, t, c.recipe);
            session.apply_hard_targets(a.positions);
            session.set_positions(a.positions);
            for (int k = 0; k < 7; ++k)
                session.step(); // on the kept positions, as run() steps them
            Mesh b = m;
            Recipe seven = c.recipe;
            seven.iterations = 7;
            smooth(b, t, seven);
            const std::span<const Scalar> kept = session.positions();
            CHECK(std::vector<Scalar>(kept.begin(), kept.end()) == b.positions);
            CHECK(session.precompute_count() == 1);
        }
    }

    TEST_CASE("a face list in any order gives the same positions and the same energy")
    {
        // The fused step reads the constrained faces in the mesh's order whatever the
        // list's (a file's numbering renumbered for locality comes scrambled).
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count(), nf = m.face_count();
        Recipe ascending;
        ascending.iterations = 9;
        ascending.region = Region{};
        for (Index v = 0; v < nv; v += 3) // some constrained faces have no free vertex
            ascending.region->vertices.push_back(v);
        ascending.centroid = CentroidConstraints{};
        for (Index f = 0; f < nf; f += 2)
            ascending.centroid->faces.indices.push_back(f);
        Recipe descending = ascending;
        std::ranges::reverse(descending.centroid->faces.indices);
        Mesh a = m, b = m;
        const SmoothResult ra = smooth(a, t, ascending);
        const SmoothResult rb = smooth(b, t, descending);
        CHECK(a.positions == b.positions);
        REQUIRE(ra.energies.size() == rb.energies.size());
        for (size_t k = 0; k < ra.energies.size(); ++k)
            CHECK(rb.energies[k].centroid ==
                  doctest::Approx(ra.energies[k].centroid).epsilon(1e-12));
        // The sweep's energy is the term's own, summed in the list's order.
        Mesh c = m;
        Session session(c, t, descending);
        session.set_positions(c.positions);
        for (int k = 0; k < 4; ++k)
            session.step();
        TermEnergies swept; // at x_4
        session.step(swept);
        REQUIRE(ra.energies[4].centroid > 0);
        CHECK(swept.centroid == doctest::Approx(ra.energies[4].centroid).epsilon(1e-12));
    }

    TEST_CASE("adopted positions run to the same bits as copied ones, with the mesh's moved out")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        for (const RecipeCase& c : configurations(m))
        {
            CAPTURE(c.name);
            Mesh a = m;
            const SmoothResult expected = smooth(a, t, c.recipe);

            Mesh b = m;
            Session session(b, t, c.recipe);
            CHECK_THROWS_AS(run(session), SolverError); // no positions yet
            session.apply_hard_targets(b.positions);
            // The mesh then has no positions (and so no vertices) while the session runs.
            session.adopt_positions(std::move(b.positions));
            CHECK(b.positions.empty());
            const SmoothResult result = run(session);
            CHECK(result.iterations == expected.iterations);
            CHECK(result.energies.back().total() == expected.energies.back().total());
            b.positions = session.release_positions();
            CHECK(b.positions == a.positions);
            CHECK_FALSE(session.has_positions());
            CHECK(session.positions().empty());
            CHECK_THROWS_AS(session.step(), SolverError);
            std::vector<Scalar> short_positions(6, 0);
            CHECK_THROWS_AS(session.adopt_positions(std::move(short_positions)), SolverError);
        }
    }

    TEST_CASE("a topology of the required parts only gives the same bits, fewer are refused")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology whole = build_topology(m);
        std::vector<RecipeCase> cases = configurations(m);
        Recipe joint;
        joint.iterations = 5;
        joint.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Initial, {}};
        joint.joint = Joint{0.5};
        cases.push_back({"normal, joint mode", joint});
        for (const RecipeCase& c : cases)
        {
            CAPTURE(c.name);
            const TopologyParts parts = required_topology(c.recipe);
            const Topology lean = build_topology(m, parts);
            Mesh a = m, b = m;
            smooth(a, whole, c.recipe);
            smooth(b, lean, c.recipe);
            CHECK(a.positions == b.positions);
            // Without any one of the required parts the session refuses to start.
            for (const TopologyParts part :
                 {TopologyParts::Neighbors, TopologyParts::Corners, TopologyParts::Dual})
                if (has_parts(parts, part))
                {
                    const auto fewer = static_cast<TopologyParts>(static_cast<unsigned>(parts) &
                                                                  ~static_cast<unsigned>(part));
                    CHECK_THROWS_AS(Session(m, build_topology(m, fewer), c.recipe), SolverError);
                }
        }
    }

    TEST_CASE("moving a pin changes the right-hand side only")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        Recipe r;
        r.hard = HardVertices{{5, 6}, {}};
        r.soft = SoftVertices{{false, {10}}, 1.0, {}};
        r.centroid = CentroidConstraints{{false, {3}}, 1.0, {}, CentroidDenominator::Paper};
        Mesh x = m;
        Session session(x, t, r);
        session.step(x.positions);
        const std::vector<Scalar> pins{1, 2, 3, 4, 5, 6};
        session.set_hard_targets(pins);
        session.set_soft_targets(std::vector<Scalar>{0, 0, 0});
        session.set_centroid_targets(std::vector<Scalar>{1, 1, 1});
        session.apply_hard_targets(x.positions);
        session.step(x.positions);
        CHECK(session.precompute_count() == 1);
        CHECK(x.position(5) == Vec3{1, 2, 3});
        CHECK(x.position(6) == Vec3{4, 5, 6});
        session.set_recipe(r);
        CHECK(session.precompute_count() == 2);
        CHECK_THROWS_AS(session.set_hard_targets(std::vector<Scalar>{1, 2, 3}), InvalidInputError);
    }

    TEST_CASE("plain gradient descent needs a small step, the Jacobi step does not")
    {
        // The paper's question: the descent directions differ by 1/n_i. Without it,
        // lambda = 0.5 makes the energy grow on a mesh of valence 5-6.
        const Mesh m = noisy(test::icosphere(2), 0.05, 4);
        const Topology t = build_topology(m);
        Recipe r;
        r.iterations = 5;
        r.method = Method::GradientDescent;
        Mesh gd = m;
        const SmoothResult grows = smooth(gd, t, r);
        CHECK(grows.energies.back().total() > grows.energies.front().total());
        // With the exact line search gradient descent decreases too, but the
        // preconditioned (Jacobi) direction goes further in the same number of steps.
        r.iterations = 20;
        r.optimal_step = true;
        Mesh a = m, b = m;
        r.soft = SoftVertices{{true, {}}, 0.1, {}};
        const Scalar e_gd = smooth(a, t, r).energies.back().total();
        r.method = Method::Jacobi;
        const Scalar e_jacobi = smooth(b, t, r).energies.back().total();
        CHECK(e_jacobi < e_gd);
    }

    TEST_CASE("the tolerance stops early, zero tolerance runs every iteration")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        Recipe r;
        r.iterations = 500;
        r.soft = SoftVertices{{true, {}}, 1.0, {}};
        Mesh a = m;
        const SmoothResult all = smooth(a, t, r);
        CHECK(all.iterations == 500);
        CHECK_FALSE(all.stopped_by_tolerance);
        CHECK(all.gradients.empty());
        r.tolerance = 1e-4;
        Mesh b = m;
        const SmoothResult early = smooth(b, t, r);
        CHECK(early.stopped_by_tolerance);
        CHECK(early.iterations < 500);
        // run() learns each step's gradient from its sweep, one step late, and undoes the
        // step past the stop: the positions and the count of a loop that assembles the
        // gradient after every step.
        Mesh c = m;
        Session session(c, t, r);
        int steps = 0;
        const Scalar first = session.residual(c.positions).gradient;
        Scalar relative = 1;
        for (; relative > r.tolerance && steps < r.iterations; ++steps)
        {
            session.step(c.positions);
            relative = session.residual(c.positions).gradient / first;
        }
        CHECK(steps == early.iterations);
        CHECK(c.positions == b.positions);
        CHECK(early.energies.size() == static_cast<size_t>(early.iterations) + 1);
        CHECK(early.lambdas.size() == static_cast<size_t>(early.iterations));
        REQUIRE(early.gradients.size() == static_cast<size_t>(early.iterations));
        CHECK(early.gradients.back() == doctest::Approx(relative).epsilon(1e-9));
    }

    TEST_CASE(
        "the tolerance is the gradient's for every step method: a run stops at the "
        "first positions within it")
    {
        // The fused Jacobi step (and on triangles with normals, where its sweep takes r_i
        // back from the displacement), the line search, gradient descent, the thin plate's
        // general step, an implicit step. (Taubin's pairs keep the low frequencies: they
        // have no minimizer to converge to, and a note says so.)
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        const Scalar tolerance = 0.02;
        const std::vector<std::pair<const char*, std::string>> recipes = {
            {"jacobi", R"({"soft": {"vertices": "all", "mu": 0.5}})"},
            {"normal shares",
             R"({"soft": {"vertices": "all", "mu": 0.5}, "normal": {"faces": "all", "mu": 2, "normals": "initial"}})"},
            {"optimal", R"({"lambda": "optimal", "centroid": {"faces": "all", "mu": 1}})"},
            {"gradient descent",
             R"({"method": "gradient_descent", "lambda": 0.05, "soft": {"vertices": "all", "mu": 0.5}})"},
            {"bending", R"({"bending": {"mu": 0.2}, "soft": {"vertices": "all", "mu": 0.5}})"},
            {"implicit",
             R"({"method": "implicit", "time": 0.5, "soft": {"vertices": "all", "mu": 0.5}})"},
        };
        for (const auto& [label, json] : recipes)
        {
            const std::string name = label;
            CAPTURE(name);
            Recipe r = parse_recipe(json, "r.json");
            r.iterations = 2000;
            r.tolerance = tolerance;
            const Topology topology = build_topology(m, required_topology(r));
            Mesh x = m;
            const SmoothResult result = smooth(x, topology, r);
            REQUIRE(result.stopped_by_tolerance);
            REQUIRE(result.iterations > 0);
            // Within the tolerance where it stopped, measured afresh ...
            Mesh start = m;
            Session fresh(start, topology, r);
            const Scalar first = fresh.residual(start.positions).gradient;
            const Scalar reached = fresh.residual(x.positions).gradient / first;
            CHECK(reached <= tolerance * (1 + 1e-9));
            CHECK(result.gradients.back() == doctest::Approx(reached).epsilon(1e-6));
            // ... and not one step before.
            Recipe shorter = r;
            shorter.tolerance = 0;
            shorter.iterations = result.iterations - 1;
            Mesh y = m;
            smooth(y, topology, shorter);
            CHECK(fresh.residual(y.positions).gradient / first > tolerance * (1 - 1e-9));
        }
    }

    TEST_CASE("a recipe that does not fit the mesh is refused before any work")
    {
        const Mesh m = test::tetrahedron();
        const Topology t = build_topology(m);
        Recipe r;
        r.hard = HardVertices{{7}, {}};
        CHECK_THROWS_WITH_AS(Session(m, t, r), doctest::Contains("hard.vertices[0]"), RecipeError);
        Mesh x = m;
        Recipe ok;
        Session session(x, t, ok);
        std::vector<Scalar> wrong(5);
        CHECK_THROWS_AS(session.step(wrong), SolverError);
    }

    TEST_CASE("core checks hold on the bundled bunny in every format")
    {
        const Mesh bunny = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        const auto dir = test::temp_dir();
        for (const char* ext : {"obj", "off", "ply", "stl"})
        {
            CAPTURE(ext);
            const auto path = (dir / (std::string("bunny.") + ext)).string();
            io::write_mesh(bunny, path, {io::Encoding::Ascii});
            const Mesh m = noisy(io::read_mesh(path), 0.002, 9);
            const Topology t = build_topology(m);
            for (RecipeCase c : configurations(m))
            {
                CAPTURE(c.name);
                c.recipe.iterations = 3;
                Mesh x = m;
                const SmoothResult r = smooth(x, t, c.recipe);
                for (size_t k = 1; k < r.energies.size(); ++k)
                    CHECK(r.energies[k].total() <= r.energies[k - 1].total());
                if (c.recipe.hard)
                    for (const Index v : c.recipe.hard->vertices)
                        CHECK(same_bits(x, m, v));
            }
        }
    }
}
