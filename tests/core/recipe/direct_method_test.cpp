// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// The direct method ("method": "direct"): the minimizer of the recipe's energy over the
// free vertices, against the independent reference (tests/direct_minimizer) on every kind
// of mesh; one Jacobi step from it moves nothing; moved pins re-solve without a new
// factorization; the same bits for any thread count; a free part nothing holds refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "core/energies/volume_constraint.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "tests/direct_minimizer.h"
#include "tests/helpers.h"
#include "tests/session_checks.h"

using namespace meshfair;

namespace {

using test::noisy;
using test::RecipeCase;

// Recipes of every term the direct method solves, on mesh m: pins moved off the surface,
// weighted anchors, centroids and normals, and all of them at once.
std::vector<RecipeCase> direct_cases(const Mesh& m)
{
    const Index nv = m.vertex_count(), nf = m.face_count();
    std::vector<RecipeCase> cases;
    Recipe pins;
    pins.method = Method::Direct;
    pins.hard = HardVertices{{0, nv - 1}, {}};
    for (const Index v : pins.hard->vertices)
        pins.hard->targets.push_back(
            {m.positions[3 * v] + 0.3, m.positions[3 * v + 1], m.positions[3 * v + 2] - 0.2});
    cases.push_back({"pins moved", pins});
    Recipe soft;
    soft.method = Method::Direct;
    soft.soft = SoftVertices{{false, test::stride_indices(nv, 2)}, 0.5, {}};
    for (size_t k = 0; k < soft.soft->vertices.indices.size(); ++k)
        soft.soft->weights.push_back(0.5 + static_cast<Scalar>(k % 3));
    cases.push_back({"weighted anchors", soft});
    Recipe faces = pins;
    faces.centroid = CentroidConstraints{
        {false, test::stride_indices(nf, 2)}, 2.0, {}, CentroidDenominator::Paper};
    faces.normal =
        NormalConstraints{{false, test::stride_indices(nf, 1)}, 3.0, NormalSource::Initial, {}};
    cases.push_back({"pins, centroids and normals", faces});
    Recipe all = faces;
    all.soft = soft.soft;
    all.soft->vertices.indices = test::stride_indices(nv, 2, 1); // beside the pin at 0
    all.soft->weights.resize(all.soft->vertices.indices.size(), 1.5);
    all.hard = HardVertices{{0}, {}};
    all.normal->weights.assign(static_cast<size_t>(nf), 0);
    for (Index f = 0; f < nf; ++f)
        all.normal->weights[static_cast<size_t>(f)] = 0.25 + static_cast<Scalar>(f % 4);
    cases.push_back({"every term, weighted", all});
    Recipe plate;
    plate.method = Method::Direct;
    plate.bending = Bending{2.0, 0.0};
    plate.hard = HardVertices{{0, nv / 2, nv - 1}, {}};
    for (const Index v : plate.hard->vertices)
        plate.hard->targets.push_back(
            {m.positions[3 * v], m.positions[3 * v + 1] + 0.25, m.positions[3 * v + 2]});
    cases.push_back({"the thin plate alone, pins moved", plate});
    Recipe membrane = all;
    membrane.bending = Bending{0.5, 0.3};
    cases.push_back({"the thin plate with a membrane and every term", membrane});
    return cases;
}

// The session's run from the mesh's positions (pins at their targets first).
struct DirectRun
{
    std::vector<Scalar> start, result;
    SmoothResult run;
};

DirectRun run_direct(Session& session, const Mesh& m)
{
    DirectRun d;
    d.start = m.positions;
    session.apply_hard_targets(d.start);
    d.result = d.start;
    d.run = run(session, d.result);
    return d;
}

void check_near(const std::vector<Scalar>& got, const std::vector<Scalar>& expected, Scalar scale)
{
    REQUIRE(got.size() == expected.size());
    Scalar worst = 0;
    for (size_t k = 0; k < got.size(); ++k)
        worst = std::max(worst, std::abs(got[k] - expected[k]));
    CHECK(worst <= 1e-10 * scale);
}

std::vector<std::pair<const char*, Mesh>> small_meshes()
{
    return {{"tetrahedron", noisy(test::tetrahedron(), 0.1)},
            {"quad cube", noisy(test::quad_cube(), 0.1)},
            {"open grid", noisy(test::open_grid(5, 4), 0.1)},
            {"non-manifold fan", noisy(test::nonmanifold_fan(), 0.1)},
            {"mixed polygons", noisy(test::mixed_polygons(), 0.1)}};
}

// Calls check(m, t, diagonal, c) for every recipe case on every small mesh, named in the
// messages.
template <class Check>
void for_each_small_case(Check&& check)
{
    for (const auto& named : small_meshes())
    {
        // Not a structured binding: CAPTURE's lambda cannot name one (clang 14).
        const char* name = named.first;
        const Mesh& m = named.second;
        const Topology t = build_topology(m);
        const Scalar diagonal = bounding_box(m.positions).diagonal();
        for (const RecipeCase& c : direct_cases(m))
        {
            CAPTURE(name);
            CAPTURE(c.name);
            check(m, t, diagonal, c);
        }
    }
}

// The run's result with 1, 2 and 3 threads, compared bit for bit.
void check_same_bits_for_threads(const Mesh& m, const Topology& t, const Recipe& recipe)
{
    std::vector<std::vector<Scalar>> results;
    for (const int threads : {1, 2, 3})
    {
        set_thread_count(threads);
        Session session(m, t, recipe);
        results.push_back(run_direct(session, m).result);
    }
    set_thread_count(0);
    for (size_t k = 1; k < results.size(); ++k)
        CHECK(std::memcmp(results[0].data(), results[k].data(),
                          results[0].size() * sizeof(Scalar)) == 0);
    CHECK(results[0] != m.positions);
}

} // namespace

TEST_SUITE("direct method")
{
    TEST_CASE("the minimizer of every term on every kind of mesh, as the reference solves it")
    {
        for_each_small_case(
            [](const Mesh& m, const Topology& t, Scalar diagonal, const RecipeCase& c) {
                Session session(m, t, c.recipe);
                const DirectRun d = run_direct(session, m);
                const std::vector<Index> free(session.free_vertices().begin(),
                                              session.free_vertices().end());
                const std::vector<Scalar> expected =
                    test::direct_minimizer(m, t, c.recipe, d.start, free);
                check_near(d.result, expected, diagonal);
                // Solved in one step, refined in at most two more.
                CHECK(d.run.iterations >= 1);
                CHECK(d.run.iterations <= 3);
                CHECK(d.run.stopped_by_tolerance);
                REQUIRE(!d.run.gradients.empty());
                CHECK(d.run.gradients.front() <= 1e-9);
                // No free vertex's Jacobi displacement is left.
                CHECK(session.residual(d.result).jacobi_displacement <= 1e-9 * diagonal);
            });
    }

    TEST_CASE(
        "an implicit step is the minimizer of the energy plus |x - x0|^2 / t, on every "
        "kind of mesh")
    {
        // Backward Euler, x1 - x0 = t r(x1), is the stationarity of E(x) + |x - x0|^2 / t:
        // the reference solves that energy, with anchors of mu = 1 / t at the start on
        // every free vertex, by its own assembly.
        for_each_small_case(
            [](const Mesh& m, const Topology& t, Scalar diagonal, const RecipeCase& c) {
                if (c.recipe.soft)
                    return; // the anchors' section is the reference's
                for (const Scalar time : {0.05, 2.0})
                {
                    CAPTURE(time);
                    Recipe implicit = c.recipe;
                    implicit.method = Method::Implicit;
                    implicit.time = time;
                    implicit.iterations = 1;
                    Session session(m, t, implicit);
                    const DirectRun d = run_direct(session, m);
                    CHECK(d.run.iterations == 1);
                    Recipe anchored = c.recipe;
                    std::vector<Index> anchors; // every vertex but the pins
                    for (Index v = 0; v < m.vertex_count(); ++v)
                        if (!c.recipe.hard || std::ranges::find(c.recipe.hard->vertices, v) ==
                                                  c.recipe.hard->vertices.end())
                            anchors.push_back(v);
                    anchored.soft = SoftVertices{{false, anchors}, 1 / time, {}};
                    const std::vector<Index> free(session.free_vertices().begin(),
                                                  session.free_vertices().end());
                    check_near(d.result, test::direct_minimizer(m, t, anchored, d.start, free),
                               diagonal);
                }
            });
    }

    TEST_CASE("implicit steps smooth a whole mesh that nothing holds, stable at any time")
    {
        const Mesh m = noisy(test::icosphere(3), 0.05);
        const Topology t = build_topology(m);
        Recipe plain;
        plain.method = Method::Direct;
        CHECK_THROWS_AS(Session(m, t, plain), RecipeError); // no minimizer to solve for
        std::vector<Scalar> energies;
        for (const Scalar time : {0.01, 1.0, 1e6})
        {
            Recipe r;
            r.method = Method::Implicit;
            r.time = time;
            r.iterations = 2;
            Mesh x = m;
            const SmoothResult result = smooth(x, t, r);
            REQUIRE(result.iterations == 2);
            CHECK(result.energies[1].total() < result.energies[0].total());
            CHECK(result.energies[2].total() < result.energies[1].total());
            for (const Scalar v : x.positions)
                CHECK(std::isfinite(v));
            energies.push_back(result.energies.back().total());
        }
        // The longer the time, the smoother (and at 1e6 the mesh has all but collapsed to
        // its centroid, the edge energy's minimizer over a free mesh).
        CHECK(energies[1] < energies[0]);
        CHECK(energies[2] < energies[1]);
        CHECK(energies[2] < 1e-6 * energies[0]);

        // With the volume kept (the enclosed volume by the divergence theorem, summed here
        // over the faces' fans): the smoothing no longer shrinks the sphere.
        const auto enclosed = [&](const std::vector<Scalar>& x) {
            Scalar v = 0;
            for (Index f = 0; f < m.face_count(); ++f)
            {
                const auto c = m.face(f);
                const Scalar* a = &x[3 * c[0]];
                const Scalar* b = &x[3 * c[1]];
                const Scalar* d = &x[3 * c[2]];
                v += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                      a[2] * (b[0] * d[1] - b[1] * d[0])) /
                     6;
            }
            return v;
        };
        Recipe kept;
        kept.method = Method::Implicit;
        kept.time = 10;
        kept.iterations = 3;
        Mesh shrunk = m, held = m;
        smooth(shrunk, t, kept);
        kept.volume = KeepVolume{};
        smooth(held, t, kept);
        const Scalar v0 = enclosed(m.positions);
        CHECK(enclosed(shrunk.positions) < 0.5 * v0);
        CHECK(enclosed(held.positions) == doctest::Approx(v0).epsilon(1e-9));
    }

    TEST_CASE("\"method\": \"implicit\" with its \"time\" in a recipe file")
    {
        const Recipe r =
            parse_recipe(R"({"method": "implicit", "time": 0.5, "volume": {}})", "r.json");
        CHECK(r.method == Method::Implicit);
        CHECK(r.time == 0.5);
        CHECK(parse_recipe(recipe_to_json(r).dump(), "again.json").time == 0.5);
        const Mesh m = test::icosphere(2);
        CHECK_NOTHROW(check_recipe(r, m));
        CHECK_THROWS_WITH_AS(
            check_recipe(parse_recipe(R"({"method": "implicit", "time": 0})", "t.json"), m),
            doctest::Contains("time"), RecipeError);
        CHECK_THROWS_WITH_AS(
            check_recipe(parse_recipe(R"({"method": "implicit", "lambda": "optimal"})", "o.json"),
                         m),
            doctest::Contains("implicit"), RecipeError);
    }

    TEST_CASE("one Jacobi step from the direct result moves nothing")
    {
        const Mesh m = noisy(test::icosphere(3), 0.05);
        const Topology t = build_topology(m);
        const Scalar diagonal = bounding_box(m.positions).diagonal();
        for (const RecipeCase& c : direct_cases(m))
        {
            CAPTURE(c.name);
            Session direct(m, t, c.recipe);
            const DirectRun d = run_direct(direct, m);
            Recipe jacobi = c.recipe;
            jacobi.method = Method::Jacobi;
            jacobi.iterations = 1;
            Session step(m, t, jacobi);
            std::vector<Scalar> x = d.result;
            run(step, x);
            check_near(x, d.result, diagonal);
            // And the Jacobi iteration from the input is still far from it after one step:
            // the check could fail.
            std::vector<Scalar> y = d.start;
            run(step, y);
            Scalar apart = 0;
            for (size_t k = 0; k < y.size(); ++k)
                apart = std::max(apart, std::abs(y[k] - d.result[k]));
            CHECK(apart > 1e-4 * diagonal);
        }
    }

    TEST_CASE("moved pins: a new right-hand side, the same factorization, the new minimizer")
    {
        const Mesh m = test::open_grid(12, 10); // flat: the dome is the only height
        const Topology t = build_topology(m);
        const Scalar diagonal = bounding_box(m.positions).diagonal();
        Recipe r;
        r.method = Method::Direct;
        r.region = Region{{}, test::stride_indices(m.face_count(), 1)};
        // The border fixed by the region's rest: a region of the interior faces only.
        r.region->faces.clear();
        for (Index f = 0; f < m.face_count(); ++f)
            if (f % 12 != 0 && f % 12 != 11 && f >= 12 && f < 108)
                r.region->faces.push_back(f);
        const Index pin = 5 * 13 + 6; // the middle of the grid
        r.hard = HardVertices{{pin}, {{m.positions[3 * pin], m.positions[3 * pin + 1], 0.5}}};
        Session session(m, t, r);
        DirectRun d = run_direct(session, m);
        CHECK(d.result[3 * pin + 2] == 0.5);
        // The dome: every free vertex rose, none above the pin.
        for (const Index v : session.free_vertices())
        {
            CHECK(d.result[3 * v + 2] > m.positions[3 * v + 2]);
            CHECK(d.result[3 * v + 2] < 0.5);
        }
        const std::vector<Scalar> lifted = {m.positions[3 * pin], m.positions[3 * pin + 1], 0.9};
        session.set_hard_targets(lifted);
        session.apply_hard_targets(d.result);
        const std::vector<Scalar> from = d.result;
        session.set_positions(d.result);
        run(session);
        const std::span<const Scalar> kept = session.positions();
        Recipe moved = r;
        moved.hard->targets = {{lifted[0], lifted[1], lifted[2]}};
        const std::vector<Index> free(session.free_vertices().begin(),
                                      session.free_vertices().end());
        check_near(std::vector<Scalar>(kept.begin(), kept.end()),
                   test::direct_minimizer(m, t, moved, from, free), diagonal);
        CHECK(session.precompute_count() == 1);
    }

    TEST_CASE("a weight changed keeps the analysis: the factor of a fresh session, bit for bit")
    {
        for (const auto& entry : test::small_mesh_kinds())
        {
            const std::string kind = entry.first;
            const Mesh& m = entry.second;
            CAPTURE(kind);
            const Topology t = build_topology(m);
            Recipe r;
            r.method = Method::Direct;
            r.bending = Bending{1.0, 0.25};
            r.hard = HardVertices{{0}, {}};
            r.soft = SoftVertices{{false, test::stride_indices(m.vertex_count(), 3, 1)}, 0.5, {}};
            Session session(m, t, r);
            REQUIRE(session.factorization() != nullptr);
            // The bending weight and the anchors' weight change: the same pattern.
            Recipe heavier = r;
            heavier.bending->mu = 3.0;
            heavier.soft->mu = 2.0;
            session.set_recipe(heavier);
            REQUIRE(session.factorization() != nullptr);
            CHECK(session.factorization()->stats().factorizations == 2);
            CHECK(session.factorization()->stats().analyse_seconds == 0);
            session.set_positions(m.positions);
            run(session);
            Session fresh(m, t, heavier);
            CHECK(fresh.factorization()->stats().factorizations == 1);
            fresh.set_positions(m.positions);
            run(fresh);
            CHECK(std::ranges::equal(session.positions(), fresh.positions()));
            // Another free set is another pattern: analysed afresh.
            Recipe fewer = heavier;
            fewer.hard->vertices.push_back(2); // (not a soft one: those are 1, 4, 7, ...)
            session.set_recipe(fewer);
            CHECK(session.factorization()->stats().factorizations == 1);
            // A session made with another's factorization keeps its analysis too.
            Session handed(m, t, r, {}, session.take_factorization());
            CHECK(session.factorization() == nullptr);
            CHECK_THROWS_AS(session.step(), SolverError); // nothing left to solve with
            CHECK(handed.factorization()->stats().factorizations == 1); // another pattern
            Session again(m, t, heavier, {}, handed.take_factorization());
            CHECK(again.factorization()->stats().factorizations == 2);
            again.set_positions(m.positions);
            run(again);
            CHECK(std::ranges::equal(again.positions(), fresh.positions()));
        }
    }

    TEST_CASE("the same bits for 1, 2 and 3 threads")
    {
        const Mesh m = noisy(test::icosphere(5), 0.01); // 10,242 vertices: parallel loops
        const Topology t = build_topology(m);
        const std::vector<RecipeCase> cases = direct_cases(m);
        for (const RecipeCase& c : cases)
        {
            // The thin plate's cases factor a 2-ring stencil, in 3x3 blocks with the normal
            // term: seconds each at this size. The plate is checked once, below, on its own
            // scalar system.
            if (c.recipe.bending)
                continue;
            CAPTURE(c.name);
            check_same_bits_for_threads(m, t, c.recipe);
        }
        Recipe plate = cases[1].recipe; // weighted anchors
        plate.bending = Bending{1.0, 0.3};
        check_same_bits_for_threads(m, t, plate);
    }

    TEST_CASE("a free part that nothing holds is refused, named by its size and a vertex")
    {
        // Two triangles: one pinned, the other free with nothing holding it.
        const Mesh m = test::two_components();
        const Topology t = build_topology(m);
        Recipe r;
        r.method = Method::Direct;
        r.hard = HardVertices{{0}, {}};
        try
        {
            Session session(m, t, r);
            FAIL("an unheld part was accepted");
        }
        catch (const RecipeError& e)
        {
            const std::string what = e.what();
            CHECK(what.find("3 vertices") != std::string::npos);
            CHECK(what.find("vertex 3") != std::string::npos);
            CHECK(what.find("held by nothing") != std::string::npos);
        }
        // Named in the file's numbering when the session runs in another (LocalityRun's):
        // here the file numbers the vertices backwards, so the part is 2, 1, 0.
        const std::vector<Index> file_vertex{5, 4, 3, 2, 1, 0};
        try
        {
            Session session(m, t, r, file_vertex);
            FAIL("an unheld part was accepted");
        }
        catch (const RecipeError& e)
        {
            CHECK(std::string(e.what()).find("that holds vertex 0 ") != std::string::npos);
        }
        // Held by an anchor on that triangle, it is accepted.
        r.soft = SoftVertices{{false, {4}}, 0.1, {}};
        CHECK_NOTHROW(Session(m, t, r));
        // A closed mesh with nothing at all: plain smoothing has no minimizer.
        const Mesh sphere = test::icosphere(1);
        Recipe plain;
        plain.method = Method::Direct;
        CHECK_THROWS_AS(Session(sphere, build_topology(sphere), plain), RecipeError);
    }

    TEST_CASE("falloff anchors around pins: the Jacobi displacement vanishes")
    {
        const Mesh m = noisy(test::open_grid(10, 10), 0.02);
        const Topology t = build_topology(m);
        const Scalar diagonal = bounding_box(m.positions).diagonal();
        Recipe r;
        r.method = Method::Direct;
        const Index pin = 5 * 11 + 5;
        r.hard = HardVertices{{pin}, {{m.positions[3 * pin], m.positions[3 * pin + 1], 0.4}}};
        r.falloff = Falloff{};
        r.falloff->radius = 4;
        Session session(m, t, r);
        const DirectRun d = run_direct(session, m);
        CHECK(session.residual(d.result).jacobi_displacement <= 1e-9 * diagonal);
        CHECK(session.residual(d.start).jacobi_displacement > 1e-3 * diagonal);
    }

    TEST_CASE(
        "with the flip guard a direct step shrinks as a whole: the energy falls, nothing "
        "turns over")
    {
        // A sphere free but for a cap: the membrane's minimizer (each coordinate harmonic)
        // flattens the rest into the cap's rim, a Tutte embedding in its plane, which turns
        // the faces of one hemisphere over.
        const Mesh m = test::icosphere(3);
        const Topology t = build_topology(m);
        Recipe r;
        r.method = Method::Direct;
        r.iterations = 3;
        r.region = Region{{}, {}};
        for (Index v = 0; v < m.vertex_count(); ++v)
            if (m.positions[3 * v + 2] < 0.9)
                r.region->vertices.push_back(v);
        const auto turned = [&](const Mesh& after) {
            int count = 0;
            for (Index f = 0; f < m.face_count(); ++f)
                count += test::dot(face_area_vector(m, m.positions, f),
                                   face_area_vector(after, after.positions, f)) <= 0;
            return count;
        };
        Mesh unguarded = m;
        smooth(unguarded, t, r);
        REQUIRE(turned(unguarded) > 0);

        r.prevent_flips = true;
        Mesh guarded = m;
        const SmoothResult result = smooth(guarded, t, r);
        CHECK(turned(guarded) == 0);
        CHECK(guarded.positions != m.positions); // it went part of the way
        for (size_t k = 1; k < result.energies.size(); ++k)
            CHECK(result.energies[k].total() <= result.energies[k - 1].total());
        // Each step shortened as one: every free vertex's step, or none; after one step the
        // result lies on the segment from the input to the minimizer, at one t in (0, 1).
        for (const Index shortened : result.shortened)
            CHECK((shortened == 0 || shortened == static_cast<Index>(r.region->vertices.size())));
        r.iterations = 1;
        Mesh once = m;
        smooth(once, t, r);
        size_t far = 0;
        for (size_t k = 0; k < m.positions.size(); ++k)
            if (std::abs(unguarded.positions[k] - m.positions[k]) >
                std::abs(unguarded.positions[far] - m.positions[far]))
                far = k;
        const Scalar along = (once.positions[far] - m.positions[far]) /
                             (unguarded.positions[far] - m.positions[far]);
        CHECK(along > 0);
        CHECK(along < 1);
        Scalar off = 0;
        for (size_t k = 0; k < m.positions.size(); ++k)
            off = std::max(off, std::abs(once.positions[k] - m.positions[k] -
                                         along * (unguarded.positions[k] - m.positions[k])));
        CHECK(off <= 1e-12);
    }

    TEST_CASE("Jacobi steps keep the per-vertex flip guard: some vertices shortened, not all")
    {
        // The general step (here with the thin plate, which the fused kernels do not take)
        // shortens the vertices whose stars would turn over, each on its own; only a step
        // of the direct method shrinks as a whole.
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.08, 3);
        const Topology t = build_topology(m);
        Recipe r;
        r.lambda = 0.9;
        r.iterations = 5;
        r.bending = Bending{1.0, 1.0};
        r.prevent_flips = true;
        Mesh x = m;
        const SmoothResult result = smooth(x, t, r);
        bool partly = false;
        for (const Index shortened : result.shortened)
            partly = partly || (shortened > 0 && shortened < m.vertex_count());
        CHECK(partly);
    }

    TEST_CASE(
        "with the volume kept: the minimizer under it, by the factor and by conjugate "
        "gradients, on every kind of mesh")
    {
        for (const auto& named : small_meshes())
        {
            const char* name = named.first;
            const Mesh& m = named.second;
            CAPTURE(name);
            // Anchors too weak to hold the shape: the membrane shrinks it unless held.
            Recipe r;
            r.method = Method::Direct;
            r.soft = SoftVertices{{true, {}}, 0.05, {}};
            r.volume = KeepVolume{};
            r.iterations = 6;
            const Topology t = build_topology(m, required_topology(r));
            const Scalar diagonal = bounding_box(m.positions).diagonal();
            Session direct(m, t, r);
            const DirectRun d = run_direct(direct, m);
            CHECK(d.run.stopped_by_tolerance);
            REQUIRE(!d.run.gradients.empty());
            CHECK(d.run.gradients.back() <= 1e-9);
            // Every kept component's volume is the input's (the constraint's own count).
            std::vector<char> none(static_cast<size_t>(m.vertex_count()), 0);
            const VolumeConstraint volumes(m, t, m.positions, none);
            Index kept = 0;
            for (Index c = 0; c < volumes.component_count(); ++c)
                if (volumes.is_kept(c))
                {
                    ++kept;
                    CHECK(volumes.volume(c, d.result) ==
                          doctest::Approx(volumes.target_volumes()[c]).epsilon(1e-12));
                }
            REQUIRE(kept > 0);
            // Without it the shape shrinks: the constraint does something.
            Recipe free_volume = r;
            free_volume.volume.reset();
            Session unconstrained(m, t, free_volume);
            const DirectRun u = run_direct(unconstrained, m);
            Scalar moved = 0;
            for (Index c = 0; c < volumes.component_count(); ++c)
                if (volumes.is_kept(c))
                    moved = std::max(
                        moved, std::abs(volumes.volume(c, u.result) - volumes.target_volumes()[c]));
            CHECK(moved > 1e-4 * diagonal * diagonal * diagonal);
            // A minimizer under the constraint, told apart from its own rule: no feasible
            // shape near it (a small random move, put back on the volume) has less energy,
            // nor has the shape Jacobi steps with the volume kept settle to.
            Session energy(m, t, r);
            const Scalar e = energy.energy(d.result).total();
            VolumeConstraint back(m, t, m.positions, none);
            for (unsigned seed = 1; seed <= 8; ++seed)
            {
                Mesh near = m;
                near.positions = d.result;
                test::perturb(near, 1e-3 * diagonal, seed);
                back.project(near.positions);
                CHECK(energy.energy(near.positions).total() >= e * (1 - 1e-12));
            }
            Recipe jacobi = r;
            jacobi.method = Method::Jacobi;
            jacobi.iterations = 3000;
            Session steps(m, t, jacobi);
            std::vector<Scalar> settled = m.positions;
            run(steps, settled);
            CHECK(energy.energy(settled).total() >= e * (1 - 1e-12));
            // Conjugate gradients solve the same constrained problem.
            Recipe cg = r;
            cg.method = Method::ConjugateGradient;
            Session iterative(m, t, cg);
            const DirectRun g = run_direct(iterative, m);
            Scalar worst = 0;
            for (size_t k = 0; k < g.result.size(); ++k)
                worst = std::max(worst, std::abs(g.result[k] - d.result[k]));
            CHECK(worst <= 1e-9 * diagonal);
        }
    }

    TEST_CASE("conjugate gradients reach the same minimizer on every kind of mesh")
    {
        for_each_small_case(
            [](const Mesh& m, const Topology& t, Scalar diagonal, const RecipeCase& c) {
                Session direct(m, t, c.recipe);
                const DirectRun d = run_direct(direct, m);
                Recipe r = c.recipe;
                r.method = Method::ConjugateGradient;
                Session cg(m, t, r);
                CHECK(cg.conjugate_gradients());
                CHECK(cg.factorization() == nullptr);
                const DirectRun g = run_direct(cg, m);
                check_near(g.result, d.result, diagonal);
                CHECK(g.run.iterations <= 3);
                CHECK(g.run.stopped_by_tolerance);
                REQUIRE(!g.run.inner_iterations.empty());
                CHECK(g.run.inner_iterations.front() > 0);
                CHECK(cg.residual(g.result).jacobi_displacement <= 1e-9 * diagonal);
            });
    }

    TEST_CASE(
        "a progressive solve: conjugate gradients over calls, the energy lower at each, "
        "the bits of one solve")
    {
        // Session::begin_progressive_solve: the editor's frames without a factor.
        const Mesh m = test::open_grid(30, 30); // a plate, held at its border by pins
        const Topology t = build_topology(m);
        const Scalar diagonal = bounding_box(m.positions).diagonal();
        Recipe r;
        r.method = Method::ConjugateGradient;
        r.bending = Bending{1.0, 0.0};
        r.iterations = 1;
        r.hard = HardVertices{{}, {}};
        const Index lifted = 15 * 31 + 15;
        for (Index v = 0; v < m.vertex_count(); ++v)
            if (v % 31 == 0 || v % 31 == 30 || v < 31 || v >= 31 * 30 || v == lifted)
                r.hard->vertices.push_back(v);
        for (const Index v : r.hard->vertices)
            r.hard->targets.push_back({m.positions[3 * v], m.positions[3 * v + 1],
                                       m.positions[3 * v + 2] + (v == lifted ? 0.3 : 0)});
        // One step solved at once, from the same positions.
        Session whole(m, t, r);
        const DirectRun once = run_direct(whole, m);

        Session cg(m, t, r);
        REQUIRE(cg.can_solve_progressively());
        cg.set_positions(once.start);
        cg.begin_progressive_solve();
        Scalar energy = cg.energy().total();
        bool finished = false;
        int calls = 0, iterations = 0;
        std::vector<Scalar> partway;
        while (!finished)
        {
            const StepInfo info = cg.advance_progressive_solve(5, finished);
            CHECK(info.inner_iterations <= 3 * 5);
            iterations += info.inner_iterations;
            const Scalar now = cg.energy().total();
            CHECK(now <= energy * (1 + 1e-12)); // (in exact arithmetic it never rises)
            energy = now;
            if (++calls == 10)
                partway.assign(cg.positions().begin(), cg.positions().end());
            REQUIRE(calls < 100000);
        }
        CHECK(calls > 20);                                      // spread over calls, not one
        CHECK(iterations == once.run.inner_iterations.front()); // the iterations of one solve
        const std::vector<Scalar> got(cg.positions().begin(), cg.positions().end());
        CHECK(got == once.result); // the same sequence: the same bits
        Scalar apart = 0;
        for (size_t k = 0; k < partway.size(); ++k)
            apart = std::max(apart, std::abs(partway[k] - once.result[k]));
        CHECK(apart > 1e-6 * diagonal); // on its way after 10 calls: the checks could fail
        check_near(got, once.result, diagonal);
        CHECK_FALSE(cg.progressive_solve_under_way());
        // New positions (another step, a pin moved) end one under way: it is never taken up
        // again from the start it had.
        cg.begin_progressive_solve();
        cg.advance_progressive_solve(1, finished);
        CHECK(cg.progressive_solve_under_way());
        cg.set_positions(once.start);
        CHECK_FALSE(cg.progressive_solve_under_way());
        CHECK_THROWS_AS(cg.advance_progressive_solve(1, finished), SolverError);
        cg.begin_progressive_solve();
        cg.step();
        CHECK_FALSE(cg.progressive_solve_under_way());
        // Not for a factor.
        Recipe direct = r;
        direct.method = Method::Direct;
        CHECK_FALSE(Session(m, t, direct).can_solve_progressively());
    }

    TEST_CASE("over its factor budget the direct method solves by conjugate gradients, noted")
    {
        const Mesh m = noisy(test::icosphere(4), 0.01);
        const Topology t = build_topology(m);
        const Scalar diagonal = bounding_box(m.positions).diagonal();
        Recipe r;
        r.method = Method::Direct;
        r.bending = Bending{1.0, 0.5};
        r.hard = HardVertices{{0, 100, 2000}, {}};
        for (const Index v : r.hard->vertices)
            r.hard->targets.push_back(
                {m.positions[3 * v] * 1.2, m.positions[3 * v + 1], m.positions[3 * v + 2]});
        Session factored(m, t, r);
        REQUIRE(factored.factorization() != nullptr);
        const double factor_mb = factored.factorization()->stats().factor_bytes() / 1e6;
        const DirectRun d = run_direct(factored, m);
        r.factor_budget_mb = 0.5 * factor_mb; // the factor does not fit
        Session over(m, t, r);
        CHECK(over.factorization() == nullptr);
        CHECK(over.conjugate_gradients());
        REQUIRE(over.notes().size() == 1);
        CHECK(over.notes()[0].find("over the factor budget") != std::string::npos);
        check_near(run_direct(over, m).result, d.result, diagonal);
        r.factor_budget_mb = 2 * factor_mb; // it fits
        Session within(m, t, r);
        CHECK(within.factorization() != nullptr);
        CHECK(within.notes().empty());
    }

    TEST_CASE("conjugate gradients give the same bits for 1, 2 and 3 threads")
    {
        // Anchors on every other vertex (a well-conditioned system: few iterations), alone
        // (one solve per coordinate, 10,242 unknowns) and with normals (3x3 blocks, 30,726):
        // both above the size from which loops and sums run on several threads.
        const Mesh m = noisy(test::icosphere(5), 0.01);
        const Topology t = build_topology(m);
        const std::vector<RecipeCase> cases = direct_cases(m);
        Recipe anchors = cases[1].recipe;
        anchors.method = Method::ConjugateGradient;
        check_same_bits_for_threads(m, t, anchors);
        anchors.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Initial, {}};
        check_same_bits_for_threads(m, t, anchors);
    }

    TEST_CASE("\"method\": \"direct\" in a recipe file, and what it does not take")
    {
        const Recipe r = parse_recipe(R"({"method": "direct", "iterations": 4})", "direct.json");
        CHECK(r.method == Method::Direct);
        CHECK(parse_recipe(recipe_to_json(r).dump(), "again.json").method == Method::Direct);
        const Recipe cg = parse_recipe(R"({"method": "cg", "factor_budget_mb": 12.5})", "cg.json");
        CHECK(cg.method == Method::ConjugateGradient);
        CHECK(cg.factor_budget_mb == 12.5);
        const Recipe again = parse_recipe(recipe_to_json(cg).dump(), "again.json");
        CHECK(again.method == Method::ConjugateGradient);
        CHECK(again.factor_budget_mb == 12.5);
        CHECK_THROWS_AS(parse_recipe(R"({"factor_budget_mb": -1})", "r.json"), RecipeError);
        const Mesh m = test::tetrahedron();
        for (const char* text :
             {R"({"method": "direct", "lambda": "optimal"})",
              R"({"method": "direct", "normal": {"faces": "all"}, "joint": {"gamma": 1}})",
              R"({"method": "cg", "normal": {"faces": "all"}, "joint": {"gamma": 1}})"})
        {
            CAPTURE(text);
            CHECK_THROWS_AS(check_recipe(parse_recipe(text, "r.json"), m), RecipeError);
        }
    }
}

namespace {

// A 24 x 24 grid of quads, noisy, with a round region of radius 9 free and two groups of
// pins in it (three near the middle, two further out), under `recipe`'s terms.
struct Drag
{
    Mesh mesh;
    Recipe recipe;
    std::vector<Scalar> targets; // 3 per pin, at the rest
};

Drag drag_case(const std::string& terms)
{
    Drag d;
    d.mesh = test::open_grid(24, 24);
    test::perturb(d.mesh, 0.05, 3);
    d.recipe = parse_recipe(terms, "drag.json");
    d.recipe.method = Method::Direct;
    d.recipe.region = Region{};
    const Index row = 25;
    for (Index v = 0; v < d.mesh.vertex_count(); ++v)
        if (std::hypot(static_cast<Scalar>(v % row) - 12, static_cast<Scalar>(v / row) - 12) <= 9)
            d.recipe.region->vertices.push_back(v);
    const std::vector<Index> pins = {12 * row + 12, 12 * row + 13, 13 * row + 12, 8 * row + 16,
                                     9 * row + 16};
    d.recipe.hard = HardVertices{pins, {}};
    for (const Index v : pins)
        for (int a = 0; a < 3; ++a)
            d.targets.push_back(d.mesh.positions[3 * static_cast<size_t>(v) + a]);
    return d;
}

// The direct method's minimizer for `targets`, from a session of its own.
std::vector<Scalar> minimizer_for(const Drag& d, std::span<const Scalar> targets)
{
    Recipe r = d.recipe;
    for (size_t k = 0; k < r.hard->vertices.size(); ++k)
        r.hard->targets.push_back({targets[3 * k], targets[3 * k + 1], targets[3 * k + 2]});
    Mesh m = d.mesh;
    smooth(m, build_topology(m, required_topology(r)), r);
    return m.positions;
}

// The three near pins moved by a, the two far ones by b.
std::vector<Scalar> moved(const Drag& d, const Vec3& a, const Vec3& b)
{
    std::vector<Scalar> t = d.targets;
    for (size_t k = 0; k < 5; ++k)
        for (int c = 0; c < 3; ++c)
            t[3 * k + c] += (k < 3 ? a : b)[c];
    return t;
}

} // namespace

TEST_SUITE("direct method")
{
    TEST_CASE(
        "a pin drag follows the minimizer without a solve: the shape a solve gives, "
        "group by group, move after move")
    {
        for (const char* terms :
             {R"({"bending": {"mu": 1}})", R"({"soft": {"vertices": "all", "mu": 0.2}})",
              R"({"falloff": {"radius": 4, "units": "edge_lengths", "around": ["pins"]}})",
              R"({"bending": {"mu": 1}, "prevent_flips": true})"})
        {
            CAPTURE(terms);
            const Drag d = drag_case(terms);
            Mesh m = d.mesh;
            const Topology t = build_topology(m, required_topology(d.recipe));
            Session s(m, t, d.recipe);
            s.set_positions(m.positions);
            run(s);
            CHECK_FALSE(s.follow_pins()); // nothing moved yet: nothing to follow from
            for (const auto& [a, b] :
                 std::vector<std::pair<Vec3, Vec3>>{{{0, 0, 1.5}, {0, 0, 0}},
                                                    {{0.2, 0, 2.5}, {0, 0, -1}},
                                                    {{0.2, 0, 3}, {0, 0, -1}}})
            {
                const std::vector<Scalar> targets = moved(d, a, b);
                s.move_pins(targets);
                REQUIRE(s.follow_pins());
                const std::vector<Scalar> reference = minimizer_for(d, targets);
                Scalar far = 0;
                for (size_t k = 0; k < reference.size(); ++k)
                    far = std::max(far, std::abs(s.positions()[k] - reference[k]));
                CHECK(far <= 1e-9 * 24); // of the grid's size
            }
        }
    }

    TEST_CASE("run() after move_pins follows the minimizer in one step, judged by the rule")
    {
        const Drag d = drag_case(R"({"bending": {"mu": 1}})");
        Mesh m = d.mesh;
        const Topology t = build_topology(m, required_topology(d.recipe));
        Session s(m, t, d.recipe);
        s.set_positions(m.positions);
        run(s);
        CHECK_FALSE(s.can_follow_pins()); // the minimizer of these pins already
        const std::vector<Scalar> targets = moved(d, {0.2, 0, 2}, {0, 0, -1});
        s.move_pins(targets);
        REQUIRE(s.can_follow_pins());
        const SmoothResult result = run(s);
        CHECK(result.iterations == 1);
        CHECK(result.stopped_by_tolerance);
        REQUIRE(result.gradients.size() == 1);
        CHECK(result.gradients[0] <= 1e-12);
        CHECK_FALSE(s.can_follow_pins());
        const std::vector<Scalar> reference = minimizer_for(d, targets);
        Scalar far = 0;
        for (size_t k = 0; k < reference.size(); ++k)
            far = std::max(far, std::abs(s.positions()[k] - reference[k]));
        CHECK(far <= 1e-9 * 24);
    }

    TEST_CASE("a pin drag solves where the minimizer cannot follow the pins")
    {
        // The normal term couples the coordinates: no response per group.
        Drag d = drag_case(R"({"normal": {"faces": "all", "mu": 1, "normals": "initial"}})");
        Mesh m = d.mesh;
        const Topology t = build_topology(m, required_topology(d.recipe));
        Session s(m, t, d.recipe);
        s.set_positions(m.positions);
        run(s);
        s.move_pins(moved(d, {0, 0, 1}, {0, 0, 0}));
        CHECK_FALSE(s.follow_pins());
        // New positions since the minimizer: nothing on record.
        d = drag_case(R"({"bending": {"mu": 1}})");
        Mesh n = d.mesh;
        const Topology u = build_topology(n, required_topology(d.recipe));
        Session plate(n, u, d.recipe);
        plate.set_positions(n.positions);
        run(plate);
        plate.set_positions(n.positions);
        plate.move_pins(moved(d, {0, 0, 1}, {0, 0, 0}));
        const std::vector<Scalar> before(plate.positions().begin(), plate.positions().end());
        CHECK_FALSE(plate.follow_pins());
        CHECK(std::equal(before.begin(), before.end(), plate.positions().begin()));
        // A move that would turn faces over, with the flip guard: refused, positions kept
        // (a guarded step then solves).
        d = drag_case(R"({"bending": {"mu": 1}, "prevent_flips": true})");
        Mesh g = d.mesh;
        const Topology w = build_topology(g, required_topology(d.recipe));
        Session guarded(g, w, d.recipe);
        guarded.set_positions(g.positions);
        run(guarded);
        guarded.move_pins(moved(d, {6, 0, 0}, {-6, 0, 0})); // across each other, in the plane
        const std::vector<Scalar> kept(guarded.positions().begin(), guarded.positions().end());
        CHECK_FALSE(guarded.follow_pins());
        CHECK(std::equal(kept.begin(), kept.end(), guarded.positions().begin()));
    }
}
