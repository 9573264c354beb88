// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/parallel/parallel.h"

#include <doctest/doctest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <vector>

#include "core/errors.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"
#include "tests/session_checks.h"

using namespace meshfair;

namespace {

bool same_bits(const std::vector<Scalar>& a, const std::vector<Scalar>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Scalar)) == 0;
}

struct ThreadRun
{
    std::vector<Scalar> positions;
    std::vector<Scalar> energies; // total after each step
    std::vector<Scalar> lambdas;
};

ThreadRun run_steps(const Mesh& mesh, const Topology& topology, const Recipe& recipe, int threads)
{
    set_thread_count(threads);
    Mesh x = mesh;
    Session session(x, topology, recipe);
    session.apply_hard_targets(x.positions);
    ThreadRun r;
    for (int k = 0; k < 4; ++k)
    {
        r.lambdas.push_back(session.step(x.positions).lambda);
        r.energies.push_back(session.energy(x.positions).total());
    }
    r.positions = x.positions;
    // The energies that the steps on kept positions compute in their sweeps.
    session.set_positions(x.positions);
    for (int k = 0; k < 3; ++k)
    {
        TermEnergies before;
        session.step(before);
        for (const Scalar e : {before.edge, before.soft, before.centroid, before.normal})
            r.energies.push_back(e);
    }
    const std::span<const Scalar> kept = session.positions();
    r.positions.insert(r.positions.end(), kept.begin(), kept.end());
    return r;
}

// run() of `recipe` for 5 iterations from the mesh's positions (hard targets applied).
std::vector<Scalar> run_five(const Mesh& mesh, const Topology& topology, const Recipe& recipe)
{
    Recipe five = recipe;
    five.iterations = 5;
    Session session(mesh, topology, five);
    std::vector<Scalar> y = mesh.positions;
    session.apply_hard_targets(y);
    run(session, y);
    return y;
}

} // namespace

TEST_SUITE("Parallel")
{
    TEST_CASE("parallel_for really uses the threads it is given, and no more")
    {
        test::ThreadCountGuard guard;
        const Index n = 16 * kParallelThreshold;
        std::vector<int> who(static_cast<size_t>(n), -1);
        for (const int threads : {1, 2, 3})
        {
            CAPTURE(threads);
            set_thread_count(threads);
            CHECK(thread_count() == threads);
            parallel_for(n, [&](Index k) { who[static_cast<size_t>(k)] = omp_get_thread_num(); });
            const std::set<int> ids(who.begin(), who.end());
            CHECK(ids.size() == static_cast<size_t>(threads));
            // Static chunks: each thread's indices are one contiguous range.
            for (size_t k = 1; k < who.size(); ++k)
                CHECK(who[k] >= who[k - 1]);
        }
        // Short loops stay on the calling thread.
        set_thread_count(2);
        std::vector<int> small(100, -1);
        parallel_for(100, [&](Index k) { small[static_cast<size_t>(k)] = omp_get_thread_num(); });
        CHECK(std::set<int>(small.begin(), small.end()) == std::set<int>{0});
    }

    TEST_CASE("deterministic_sum: the same bits for any thread count, close to the exact sum")
    {
        test::ThreadCountGuard guard;
        std::mt19937_64 random(5);
        std::uniform_real_distribution<double> value(-1e3, 1e3);
        for (const Index n : {0, 1, 4095, 4097, 100'000, 5'000'001})
        {
            CAPTURE(n);
            std::vector<double> data(static_cast<size_t>(n));
            for (double& d : data)
                d = value(random) * value(random);
            long double exact = 0;
            for (const double d : data)
                exact += d;
            std::vector<Scalar> sums;
            for (const int threads : {1, 2, 3, 4})
            {
                set_thread_count(threads);
                sums.push_back(
                    deterministic_sum(n, [&](Index k) { return data[static_cast<size_t>(k)]; }));
            }
            for (const Scalar s : sums)
                CHECK(std::memcmp(&s, &sums[0], sizeof s) == 0);
            CHECK(static_cast<double>(std::abs(sums[0] - exact)) <=
                  1e-9 * (1 + std::abs(static_cast<double>(exact))));
        }
    }

    TEST_CASE("the solver gives the same bits for 1, 2, 3 and 4 threads")
    {
        test::ThreadCountGuard guard;
        Mesh m = test::icosphere(6); // 40,962 vertices: every loop runs in parallel
        test::perturb(m, 0.003, 11);
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count(), nf = m.face_count();
        Recipe plain;
        Recipe combined;
        combined.soft = SoftVertices{{true, {}}, 0.1, {}};
        combined.centroid = CentroidConstraints{{true, {}}, 1.0, {}, CentroidDenominator::Paper};
        combined.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Smoothed, {}};
        combined.normal_smoothing = NormalSmoothing{2, 0.5, {}, {}};
        Recipe optimal = combined;
        optimal.optimal_step = true;
        Recipe joint = optimal;
        joint.joint = Joint{1.0};
        Recipe region = combined;
        region.region = Region{test::all_indices(nv / 3), {}};
        region.hard = HardVertices{{0, 1}, {{0, 0, 1.2}, {0.1, 0.2, 0.9}}};
        Recipe descent = plain;
        descent.method = Method::GradientDescent;
        descent.lambda = 0.05;
        // A weight per element in every weighted term (soft normals of the smoothing too).
        Recipe weighted = combined;
        const auto ramp = [](Index n) {
            std::vector<Scalar> w(static_cast<size_t>(n));
            for (size_t k = 0; k < w.size(); ++k)
                w[k] = static_cast<Scalar>(k % 7) * 0.5;
            return w;
        };
        weighted.soft->weights = ramp(nv);
        weighted.centroid->weights = ramp(nf);
        weighted.normal->weights = ramp(nf);
        weighted.normal_smoothing->soft =
            SoftNormals{test::all_indices(nf / 2), 0.5, {}, ramp(nf / 2)};
        Recipe weighted_joint = weighted;
        weighted_joint.optimal_step = true;
        weighted_joint.joint = Joint{1.0};
        const std::pair<const char*, const Recipe*> recipes[] = {
            {"plain", &plain},       {"combined", &combined},
            {"optimal", &optimal},   {"joint", &joint},
            {"region", &region},     {"gradient descent", &descent},
            {"weighted", &weighted}, {"weighted, joint and optimal", &weighted_joint}};
        REQUIRE(nf > kParallelThreshold);
        for (const auto& entry : recipes)
        {
            // (Not a structured binding: clang 14 cannot capture one in CAPTURE's lambda.)
            const char* name = entry.first;
            const Recipe* recipe = entry.second;
            CAPTURE(name);
            const ThreadRun one = run_steps(m, t, *recipe, 1);
            CHECK(!same_bits(one.positions, m.positions)); // something moved
            for (const int threads : {2, 3, 4})
            {
                CAPTURE(threads);
                const ThreadRun many = run_steps(m, t, *recipe, threads);
                CHECK(same_bits(many.positions, one.positions));
                CHECK(same_bits(many.energies, one.energies));
                CHECK(same_bits(many.lambdas, one.lambdas));
            }
        }
    }
}

TEST_SUITE("Solver")
{
    TEST_CASE("Session: kept positions and step() give step(x)'s positions, run() uses them")
    {
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.02, 6);
        const Topology t = build_topology(m);
        // step() runs one fused sweep per combination of terms (bit 0 soft, 1 centroid,
        // 2 normal); step(x) the general path: the same bits, or with a normal term on
        // these triangles (Session::normal_shares) the same to rounding. Every
        // combination, with a region and hard targets in some, and with or without a
        // weight per element.
        std::vector<Recipe> recipes;
        for (int terms = 0; terms < 16; ++terms) // bit 3: a weight per element
            for (const bool region : {false, true})
            {
                Recipe r;
                if (terms & 1)
                    r.soft = SoftVertices{{false, {1, 2, 3}}, 0.5, {}};
                // With a region, every face constrained: the fused step then computes the
                // residuals of the faces with a free vertex only, a strict subset.
                if (terms & 2)
                    r.centroid =
                        region
                            ? CentroidConstraints{{true, {}}, 1.0, {}, CentroidDenominator::Paper}
                            : CentroidConstraints{
                                  {false, {0, 5, 9}}, 1.0, {}, CentroidDenominator::Paper};
                if (terms & 4)
                    r.normal = NormalConstraints{{true, {}}, 0.7, NormalSource::Initial, {}};
                if (terms & 8)
                {
                    if (!(terms & 7))
                        continue; // nothing to weigh
                    const auto weights = [](size_t n) {
                        std::vector<Scalar> w(n);
                        for (size_t k = 0; k < n; ++k)
                            w[k] = static_cast<Scalar>(k % 5) * 0.75;
                        return w;
                    };
                    if (r.soft)
                        r.soft->weights = weights(r.soft->vertices.indices.size());
                    if (r.centroid)
                        r.centroid->weights =
                            weights(r.centroid->faces.all ? m.face_count()
                                                          : r.centroid->faces.indices.size());
                    if (r.normal)
                        r.normal->weights = weights(m.face_count());
                }
                if (region)
                {
                    r.region = Region{test::all_indices(m.vertex_count() / 2), {}};
                    r.hard = HardVertices{{7, 8}, {Vec3{0, 0, 0}, Vec3{0.1, 0.2, 0.3}}};
                }
                recipes.push_back(r);
            }
        {
            // Centroids on every face and normals on some: two passes over the faces, the
            // normal term's adding its shares to the residuals.
            Recipe r;
            r.centroid = CentroidConstraints{{true, {}}, 1.0, {}, CentroidDenominator::Paper};
            r.normal = NormalConstraints{{false, {}}, 0.7, NormalSource::Initial, {}};
            for (Index f = 0; f < m.face_count(); f += 2)
                r.normal->faces.indices.push_back(f);
            recipes.push_back(r);
        }
        for (const Recipe& recipe : recipes)
        {
            CAPTURE(recipe.soft.has_value());
            CAPTURE(recipe.centroid.has_value());
            CAPTURE(recipe.normal.has_value());
            CAPTURE(recipe.region.has_value());
            CAPTURE((recipe.soft && !recipe.soft->weights.empty()) ||
                    (recipe.centroid && !recipe.centroid->weights.empty()) ||
                    (recipe.normal && !recipe.normal->weights.empty()));
            Session a(m, t, recipe), b(m, t, recipe);
            std::vector<Scalar> x = m.positions;
            a.apply_hard_targets(x);
            b.set_positions(x);
            CHECK(b.normal_shares() == recipe.normal.has_value());
            for (int k = 0; k < 5; ++k)
            {
                a.step(x);
                b.step();
                test::check_fused_as_general(b, b.positions(), x);
                const Scalar ea = a.energy(x).total(), eb = b.energy().total();
                if (b.normal_shares())
                    CHECK(std::abs(ea - eb) <= 1e-12 * ea);
                else
                    CHECK(ea == eb);
            }
            CHECK(!same_bits(x, m.positions)); // something moved
            // step(before): the same positions, and before is E(x_k) of the positions the
            // step starts from, computed in the step's sweep (fixed parts and all).
            Session d(m, t, recipe);
            std::vector<Scalar> z = m.positions;
            d.apply_hard_targets(z);
            d.set_positions(z);
            REQUIRE(d.fuses_energy());
            for (int k = 0; k < 5; ++k)
            {
                const std::span<const Scalar> kept = d.positions();
                const std::vector<Scalar> start(kept.begin(), kept.end());
                const TermEnergies expected = d.energy();
                TermEnergies before;
                d.step(before);
                for (const auto& [got, want] :
                     {std::pair{before.edge, expected.edge}, std::pair{before.soft, expected.soft},
                      std::pair{before.centroid, expected.centroid},
                      std::pair{before.normal, expected.normal}})
                    CHECK(std::abs(got - want) <= 1e-12 * std::max<Scalar>(1, std::abs(want)));
                CHECK(expected.total() > 0);
                if (k == 4)
                {
                    // Undone: the kept positions are those the step started from.
                    d.revert_step();
                    const std::span<const Scalar> back = d.positions();
                    CHECK(same_bits(std::vector<Scalar>(back.begin(), back.end()), start));
                    CHECK_THROWS_AS(d.revert_step(), SolverError); // once
                    d.step(before);
                }
            }
            test::check_fused_as_general(d, d.positions(), x);
            test::check_fused_as_general(d, run_five(m, t, recipe), x);
        }
        // Taubin's method: two fused sweeps a step (lambda, then mu from the new
        // positions), the general path's two passes (as above), with every combination
        // of terms; its energy comes from energy(), and a step cannot be undone.
        for (Recipe recipe : recipes)
        {
            recipe.method = Method::Taubin;
            recipe.taubin_mu = -0.53;
            CAPTURE(recipe.soft.has_value());
            CAPTURE(recipe.centroid.has_value());
            CAPTURE(recipe.normal.has_value());
            CAPTURE(recipe.region.has_value());
            Session a(m, t, recipe), b(m, t, recipe);
            std::vector<Scalar> x = m.positions;
            a.apply_hard_targets(x);
            b.set_positions(x);
            CHECK_FALSE(b.fuses_energy());
            for (int k = 0; k < 5; ++k)
            {
                a.step(x);
                const TermEnergies expected = b.energy();
                TermEnergies before;
                b.step(before);
                CHECK(before.total() == expected.total());
                CHECK_THROWS_AS(b.revert_step(), SolverError);
                test::check_fused_as_general(b, b.positions(), x);
            }
            CHECK(!same_bits(x, m.positions));
            test::check_fused_as_general(b, run_five(m, t, recipe), x);
        }
        // A scan in millimetres far from the origin: the vertex parts are taken about the
        // mesh's middle, so the energy keeps its digits.
        {
            Mesh far = m;
            for (size_t k = 0; k < far.positions.size(); k += 3)
            {
                far.positions[k] = 1000 * far.positions[k] + 2.5e5;
                far.positions[k + 1] = 1000 * far.positions[k + 1] - 4e5;
                far.positions[k + 2] = 1000 * far.positions[k + 2] + 1e5;
            }
            Recipe r;
            r.normal = NormalConstraints{{true, {}}, 0.7, NormalSource::Initial, {}};
            r.region = Region{test::all_indices(far.vertex_count() / 2), {}};
            Session session(far, t, r);
            session.set_positions(far.positions);
            for (int k = 0; k < 3; ++k)
            {
                const TermEnergies expected = session.energy();
                TermEnergies before;
                session.step(before);
                CHECK(std::abs(before.edge - expected.edge) <= 1e-12 * expected.edge);
                CHECK(std::abs(before.normal - expected.normal) <= 1e-12 * expected.normal);
            }
        }
        const Recipe plain;
        Session s(m, t, plain);
        CHECK_THROWS_AS(s.step(), SolverError);
        TermEnergies e;
        CHECK_THROWS_AS(s.step(e), SolverError);
        s.set_positions(m.positions);
        CHECK_THROWS_AS(s.revert_step(), SolverError); // no step yet
        s.step(m.positions); // the general step on outside positions: nothing to undo
        CHECK_THROWS_AS(s.revert_step(), SolverError);
        Recipe optimal;
        optimal.optimal_step = true; // not fused: the energy from energy(), no undo
        Session o(m, t, optimal);
        o.set_positions(m.positions);
        CHECK_FALSE(o.fuses_energy());
        o.step(e);
        CHECK(e.total() == Session(m, t, optimal).energy(m.positions).total());
        CHECK_THROWS_AS(o.revert_step(), SolverError);
        CHECK_THROWS_AS(s.set_positions(std::vector<Scalar>(5)), SolverError);
    }
}
