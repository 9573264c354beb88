// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Normal smoothing whose iterations follow the noise in the mesh ("iterations": "auto").
#include <doctest/doctest.h>

#include <cmath>

#include "core/errors.h"
#include "core/geometry/noise_estimate.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

const char* kAuto = R"({"iterations": 3,
  "centroid": {"faces": "all"},
  "normal": {"faces": "all", "mu": 10, "normals": "smoothed"},
  "normal_smoothing": {"iterations": "auto", "strength": STRENGTH,
                       "bilateral": {"guidance": "patch", "neighbors": "vertex"}}})";

Recipe auto_recipe(Scalar strength)
{
    std::string text = kAuto;
    const std::string value = std::to_string(strength);
    text.replace(text.find("STRENGTH"), 8, value);
    return parse_recipe(text, "auto.json");
}

Mesh noisy_sphere(Scalar sigma)
{
    Mesh m = test::icosphere(4);
    test::perturb(m, sigma, 9);
    return m;
}

} // namespace

TEST_SUITE("adaptive normal smoothing")
{
    TEST_CASE(
        "iterations auto reads and writes back, strength without it is refused with the reason")
    {
        const Recipe r = auto_recipe(1.5);
        REQUIRE(r.normal_smoothing->adaptive);
        CHECK(r.normal_smoothing->adaptive->strength == 1.5);
        CHECK(r.normal_smoothing->adaptive->per_noise == 50);
        CHECK(r.normal_smoothing->bilateral->guided);
        const Recipe again = parse_recipe(recipe_to_json(r).dump(), "again.json");
        CHECK(again.normal_smoothing->adaptive == r.normal_smoothing->adaptive);
        CHECK(again.normal_smoothing->bilateral == r.normal_smoothing->bilateral);

        CHECK_THROWS_WITH_AS(
            parse_recipe(R"({"normal": {"faces": "all", "normals": "smoothed"},
                             "normal_smoothing": {"iterations": 4, "strength": 2}})",
                         "r.json"),
            doctest::Contains("normal_smoothing.strength: needs \"iterations\": \"auto\""),
            RecipeError);
        CHECK_THROWS_WITH_AS(parse_recipe(R"({"normal": {"faces": "all", "normals": "smoothed"},
                             "normal_smoothing": {"iterations": "lots"}})",
                                          "r.json"),
                             doctest::Contains("must be a count or \"auto\" (got \"lots\")"),
                             RecipeError);
        CHECK_THROWS_WITH_AS(
            check_recipe(parse_recipe(R"({"normal": {"faces": "all", "normals": "smoothed"},
                             "normal_smoothing": {"iterations": "auto", "strength": 11}})",
                                      "r.json"),
                         test::quad_cube()),
            doctest::Contains("normal_smoothing.strength: must be between 0 and 10"), RecipeError);
        CHECK_THROWS_WITH_AS(parse_recipe(R"({"normal": {"faces": "all", "normals": "smoothed"},
                             "normal_smoothing": {"bilateral": {"guidance": "best"}}})",
                                          "r.json"),
                             doctest::Contains("normal_smoothing.bilateral.guidance"), RecipeError);
    }

    TEST_CASE("the iterations follow the noise found and the strength scales them")
    {
        for (const Scalar sigma : {0.004, 0.01})
        {
            CAPTURE(sigma);
            const Mesh m = noisy_sphere(sigma);
            const Topology t = build_topology(m);
            const Session one(m, t, auto_recipe(1));
            REQUIRE(one.noise_estimate());
            const NoiseEstimate& e = *one.noise_estimate();
            CHECK(e.sigma == estimate_noise(m, t, m.positions).sigma);
            CHECK(e.sigma > 0);
            CHECK(one.normal_smoothing_iterations() == std::lround(50 * e.sigma));
            // One trace entry before the smoothing and one per iteration.
            CHECK(one.normal_smoothing_trace().size() ==
                  static_cast<size_t>(one.normal_smoothing_iterations()) + 1);
            const Session two(m, t, auto_recipe(2));
            CHECK(two.normal_smoothing_iterations() == std::lround(100 * e.sigma));
        }
        // Stronger noise, more iterations.
        const Mesh weak = noisy_sphere(0.004), strong = noisy_sphere(0.01);
        const Session a(weak, build_topology(weak), auto_recipe(1));
        const Session b(strong, build_topology(strong), auto_recipe(1));
        CHECK(b.normal_smoothing_iterations() > 2 * a.normal_smoothing_iterations());
    }

    TEST_CASE("a mesh without noise takes one iteration, a recipe with a count none estimated")
    {
        const Mesh m = test::open_grid(8, 8);
        const Topology t = build_topology(m);
        const Session s(m, t, auto_recipe(1));
        REQUIRE(s.noise_estimate());
        CHECK(s.noise_estimate()->sigma == 0);
        CHECK(s.normal_smoothing_iterations() == 1);
        Recipe fixed = auto_recipe(1);
        fixed.normal_smoothing->adaptive.reset();
        fixed.normal_smoothing->iterations = 6;
        const Session f(m, t, fixed);
        CHECK(!f.noise_estimate());
        CHECK(f.normal_smoothing_iterations() == 6);
    }
}
