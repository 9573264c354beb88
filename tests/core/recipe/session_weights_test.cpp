// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Sessions whose soft, centroid and normal terms weigh each element on its own
// (mu * weights[k]): descent, the direct minimizer, the fused step, and what weights of 1
// and 0 must give.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"
#include "tests/session_checks.h"

using namespace meshfair;

namespace {

using test::noisy;
using test::RecipeCase;

// Weights in [0, 3], about one in eight of them 0.
std::vector<Scalar> random_weights(size_t count, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<Scalar> weight(0, 3);
    std::vector<Scalar> w(count);
    for (Scalar& v : w)
        v = random() % 8 == 0 ? 0 : weight(random);
    return w;
}

// Every weighted term alone and combined, with random weights (normals held fixed but
// for "smoothed", whose soft normals are weighted too).
std::vector<RecipeCase> weighted_configurations(const Mesh& m)
{
    const Index nv = m.vertex_count(), nf = m.face_count();
    std::vector<RecipeCase> cases;
    Recipe base;
    base.iterations = 20;

    Recipe soft = base;
    soft.soft = SoftVertices{{false, test::stride_indices(nv, 2)}, 0.5, {}};
    soft.soft->weights = random_weights(soft.soft->vertices.indices.size(), 1);
    cases.push_back({"soft list", soft});

    Recipe soft_all = base;
    soft_all.hard = HardVertices{{0, nv - 1}, {}};
    soft_all.soft = SoftVertices{{true, {}}, 0.8, {}};
    soft_all.soft->weights = random_weights(static_cast<size_t>(nv), 2);
    cases.push_back({"soft all", soft_all});

    for (const auto d : {CentroidDenominator::Paper, CentroidDenominator::Exact})
    {
        Recipe centroid = base;
        centroid.centroid = CentroidConstraints{{true, {}}, 1.5, {}, d};
        centroid.centroid->weights = random_weights(static_cast<size_t>(nf), 3);
        cases.push_back(
            {d == CentroidDenominator::Paper ? "centroid paper" : "centroid exact", centroid});
    }

    Recipe normal = base;
    normal.normal =
        NormalConstraints{{false, test::stride_indices(nf, 2, 1)}, 2.0, NormalSource::Initial, {}};
    normal.normal->weights = random_weights(normal.normal->faces.indices.size(), 4);
    cases.push_back({"normal", normal});

    Recipe smoothed = base;
    smoothed.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Smoothed, {}};
    smoothed.normal->weights = random_weights(static_cast<size_t>(nf), 5);
    smoothed.normal_smoothing = NormalSmoothing{};
    smoothed.normal_smoothing->soft.faces = test::stride_indices(nf, 3);
    smoothed.normal_smoothing->soft.mu = 0.7;
    smoothed.normal_smoothing->soft.weights =
        random_weights(smoothed.normal_smoothing->soft.faces.size(), 6);
    cases.push_back({"smoothed normals", smoothed});

    Recipe all = base;
    all.region = Region{test::stride_indices(nv, 1, 1), {}};
    all.hard = HardVertices{{nv / 3}, {}};
    all.soft = SoftVertices{{false, {2, nv - 2}}, 0.3, {}};
    all.soft->weights = {2.0, 0.5};
    all.centroid = CentroidConstraints{
        {false, test::stride_indices(nf, 3)}, 1.0, {}, CentroidDenominator::Paper};
    all.centroid->weights = random_weights(all.centroid->faces.indices.size(), 7);
    all.normal =
        NormalConstraints{{false, test::stride_indices(nf, 2)}, 1.5, NormalSource::Initial, {}};
    all.normal->weights = random_weights(all.normal->faces.indices.size(), 8);
    cases.push_back({"combined", all});
    return cases;
}

// Sets with a weight per element, member by member (GCC 12 warns falsely on nested
// aggregate temporaries).
SoftVertices soft_set(std::vector<Index> vertices, Scalar mu, std::vector<Scalar> weights)
{
    SoftVertices s;
    s.vertices.indices = std::move(vertices);
    s.mu = mu;
    s.weights = std::move(weights);
    return s;
}

CentroidConstraints centroid_set(std::vector<Index> faces, Scalar mu, std::vector<Scalar> weights)
{
    CentroidConstraints c;
    c.faces.indices = std::move(faces);
    c.mu = mu;
    c.denominator = CentroidDenominator::Exact;
    c.weights = std::move(weights);
    return c;
}

NormalConstraints normal_set(std::vector<Index> faces, Scalar mu, std::vector<Scalar> weights)
{
    NormalConstraints n;
    n.faces.indices = std::move(faces);
    n.mu = mu;
    n.weights = std::move(weights);
    return n;
}

std::vector<Scalar> smoothed_positions(const Mesh& m, const Topology& t, const Recipe& r)
{
    Mesh x = m;
    smooth(x, t, r);
    return x.positions;
}

} // namespace

TEST_SUITE("Session")
{
    TEST_CASE("with random weights the energy never increases, lambda = 0.5 or the line search")
    {
        for (const Mesh& clean : {test::icosphere(2), test::mixed_polygons(),
                                  test::quad_torus(10, 6, 2, 0.6), test::nonmanifold_fan()})
        {
            const Mesh m = noisy(clean);
            const Topology t = build_topology(m);
            test::check_energy_never_increases(m, t, weighted_configurations(m), true);
        }
    }

    TEST_CASE("with weights, many Jacobi iterations reach the direct minimizer of the quadratic")
    {
        const Mesh m = noisy(test::mixed_polygons(), 0.1);
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count(), nf = m.face_count();
        Recipe base;
        base.iterations = 20000;
        base.hard = HardVertices{{0, 11}, {}};
        std::vector<RecipeCase> cases;
        Recipe soft = base;
        soft.soft = SoftVertices{{false, test::stride_indices(nv, 1, 1)}, 0.5, {}};
        soft.soft->vertices.indices.erase(soft.soft->vertices.indices.begin() + 10);
        soft.soft->weights = random_weights(soft.soft->vertices.indices.size(), 11);
        soft.soft->targets.assign(soft.soft->weights.size(), Vec3{0.1, -0.2, 0.3});
        cases.push_back({"soft", soft});
        for (const auto d : {CentroidDenominator::Paper, CentroidDenominator::Exact})
        {
            Recipe c = base;
            c.centroid = CentroidConstraints{{false, test::stride_indices(nf, 1)}, 2.0, {}, d};
            c.centroid->weights = random_weights(static_cast<size_t>(nf), 12);
            cases.push_back({"centroid", c});
        }
        Recipe normal = base;
        normal.normal =
            NormalConstraints{{false, test::stride_indices(nf, 1)}, 3.0, NormalSource::Initial, {}};
        normal.normal->weights = random_weights(static_cast<size_t>(nf), 13);
        cases.push_back({"normal", normal});
        Recipe all = normal;
        all.soft = SoftVertices{{false, {3, 8, 12}}, 0.5, {}};
        all.soft->weights = {4.0, 0.0, 1.5};
        all.centroid = CentroidConstraints{{false, {1, 5}}, 2.0, {}, CentroidDenominator::Paper};
        all.centroid->weights = {0.25, 3.0};
        cases.push_back({"combined", all});
        test::check_reaches_direct_minimizer(m, t, cases);
    }

    TEST_CASE("with weights the fused step gives the general step's positions")
    {
        // The same bits, or the same to rounding with normals (Session::normal_shares).
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        for (const RecipeCase& c : weighted_configurations(m))
        {
            CAPTURE(c.name);
            Mesh a = m;
            Session session(a, t, c.recipe);
            session.apply_hard_targets(a.positions);
            for (int k = 0; k < 7; ++k)
                session.step(a.positions); // the general step, on the caller's positions
            Recipe seven = c.recipe;
            seven.iterations = 7;
            test::check_fused_as_general(session, smoothed_positions(m, t, seven), // run()
                                         a.positions);
        }
    }

    TEST_CASE("weights of 1 give the positions of no weights, bit for bit")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        for (RecipeCase c : weighted_configurations(m))
        {
            CAPTURE(c.name);
            Recipe ones = c.recipe, none = c.recipe;
            for (Recipe* r : {&ones, &none})
            {
                const bool unit = r == &ones;
                const auto set = [unit](std::vector<Scalar>& w) {
                    if (unit)
                        std::fill(w.begin(), w.end(), 1.0);
                    else
                        w.clear();
                };
                if (r->soft)
                    set(r->soft->weights);
                if (r->centroid)
                    set(r->centroid->weights);
                if (r->normal)
                    set(r->normal->weights);
                if (r->normal_smoothing)
                    set(r->normal_smoothing->soft.weights);
            }
            CHECK(smoothed_positions(m, t, ones) == smoothed_positions(m, t, none));
        }
    }

    TEST_CASE("a weight of 0 is no constraint on that element")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count(), nf = m.face_count();
        // Elements of weight 0 among others: the same bits as those elements left out.
        Recipe with_zeros;
        with_zeros.soft = soft_set({4, 9, 13}, 0.5, {2.0, 0.0, 1.0});
        with_zeros.centroid = centroid_set({3, 8, 20}, 1.0, {0.0, 1.5, 0.5});
        with_zeros.normal = normal_set({1, 2, 30}, 2.0, {1.0, 1.0, 0.0});
        Recipe left_out;
        left_out.soft = soft_set({4, 13}, 0.5, {2.0, 1.0});
        left_out.centroid = centroid_set({8, 20}, 1.0, {1.5, 0.5});
        left_out.normal = normal_set({1, 2}, 2.0, {1.0, 1.0});
        CHECK(smoothed_positions(m, t, with_zeros) == smoothed_positions(m, t, left_out));
        // Every weight 0: the terms vanish. The normal term still makes the system 3x3 (a
        // Cholesky solve instead of a division), so this holds to rounding.
        Recipe zero;
        zero.soft = soft_set({}, 0.5, std::vector<Scalar>(nv, 0.0));
        zero.soft->vertices.all = true;
        zero.centroid = centroid_set({}, 1.0, std::vector<Scalar>(nf, 0.0));
        zero.centroid->faces.all = true;
        zero.normal = normal_set({}, 2.0, std::vector<Scalar>(nf, 0.0));
        zero.normal->faces.all = true;
        const std::vector<Scalar> plain = smoothed_positions(m, t, Recipe{});
        const std::vector<Scalar> zeros = smoothed_positions(m, t, zero);
        for (size_t k = 0; k < plain.size(); ++k)
            CHECK(zeros[k] == doctest::Approx(plain[k]).scale(1).epsilon(1e-14));
    }

    TEST_CASE("\"all\" with weights is the list of the vertices that are not hard")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count();
        Recipe all;
        all.hard = HardVertices{{0, 5, nv - 1}, {}};
        all.soft = SoftVertices{{true, {}}, 0.6, {}};
        all.soft->weights = random_weights(static_cast<size_t>(nv), 21);
        Recipe list = all;
        list.soft->vertices = {false, {}};
        list.soft->weights.clear();
        for (Index v = 0; v < nv; ++v)
            if (v != 0 && v != 5 && v != nv - 1)
            {
                list.soft->vertices.indices.push_back(v);
                list.soft->weights.push_back(all.soft->weights[v]);
            }
        CHECK(smoothed_positions(m, t, all) == smoothed_positions(m, t, list));
    }

    TEST_CASE("two anchor sets with their own mu are one set weighing each vertex")
    {
        const Mesh m = noisy(test::icosphere(2));
        const Topology t = build_topology(m);
        const Recipe two = parse_recipe(R"({"soft": [
            {"vertices": [1, 4, 9], "mu": 0.3},
            {"vertices": [20, 2], "mu": 2, "weights": [0.5, 3]}]})",
                                        "two.json");
        // mu = 1: the weights are the products themselves, so the same bits.
        const Recipe one = parse_recipe(R"({"soft": {"vertices": [1, 4, 9, 20, 2], "mu": 1,
            "weights": [0.3, 0.3, 0.3, 1, 6]}})",
                                        "one.json");
        CHECK(smoothed_positions(m, t, two) == smoothed_positions(m, t, one));
        // Another mu: mu * (w / mu) rounds differently from w, by an ulp or so.
        Recipe scaled = one;
        scaled.soft->mu = 0.7;
        for (Scalar& w : scaled.soft->weights)
            w /= 0.7;
        const std::vector<Scalar> a = smoothed_positions(m, t, two);
        const std::vector<Scalar> b = smoothed_positions(m, t, scaled);
        for (size_t k = 0; k < a.size(); ++k)
            CHECK(std::abs(a[k] - b[k]) <= 1e-15 * std::max<Scalar>(1, std::abs(a[k])));
    }
}
