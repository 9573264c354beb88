// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Weight maps: what a dab reaches, painting them (add, subtract, smooth), their colours, and
// what a region's or an anchor set's map makes of the recipe.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "app/editor/weight_paint.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

ConstraintSet vertex_set(ConstraintKind kind, std::vector<Index> vertices,
                         std::vector<Scalar> weights = {})
{
    ConstraintSet s;
    s.name = std::string(kind_name(kind));
    s.kind = kind;
    s.vertices = std::move(vertices);
    s.weights = std::move(weights);
    return s;
}

} // namespace

TEST_SUITE("Weight maps")
{
    TEST_CASE("a dab reaches the vertices within its radius, less with distance")
    {
        const Mesh grid = test::open_grid(10, 10); // unit spacing
        const DabReach reach = dab_reach(grid.positions, {5, 5, 0}, 2.5, 0.8, FalloffCurve::Smooth);
        REQUIRE_FALSE(reach.vertices.empty());
        CHECK(std::is_sorted(reach.vertices.begin(), reach.vertices.end()));
        for (size_t k = 0; k < reach.vertices.size(); ++k)
        {
            const size_t v = static_cast<size_t>(reach.vertices[k]);
            const Scalar d = std::hypot(grid.positions[3 * v] - 5, grid.positions[3 * v + 1] - 5);
            CHECK(d < 2.5);
            CHECK(reach.amounts[k] ==
                  doctest::Approx(0.8 * falloff_weight(FalloffCurve::Smooth, d, 2.5)));
            CHECK(reach.amounts[k] <= 0.8);
        }
        // The centre gets the full strength; 21 grid points lie within 2.5 of it (the 5 x 5
        // block around it but its 4 corners, at 2.83).
        CHECK(reach.amounts[std::find(reach.vertices.begin(), reach.vertices.end(), 5 * 11 + 5) -
                            reach.vertices.begin()] == 0.8);
        CHECK(reach.vertices.size() == 21);
    }

    TEST_CASE("add, subtract and smooth keep weights in [0, 1], smoothing keeps a constant map")
    {
        const Mesh grid = test::open_grid(6, 6);
        const Topology t = build_topology(grid, TopologyParts::Neighbors);
        const DabReach reach = dab_reach(grid.positions, {3, 3, 0}, 2, 1, FalloffCurve::Constant);
        ConstraintSet brush = vertex_set(ConstraintKind::Region, {});
        // Add brings the reached vertices in at the amount, then saturates at 1.
        CHECK(paint_weights(brush, nullptr, t, reach, PaintMode::Add) == reach.vertices.size());
        CHECK(brush.vertices.size() == reach.vertices.size());
        CHECK(std::all_of(brush.weights.begin(), brush.weights.end(),
                          [](Scalar w) { return w == 1; }));
        CHECK(paint_weights(brush, nullptr, t, reach, PaintMode::Add) == 0);
        // A constant map far from its edge stays as it is under smoothing: the centre.
        const DabReach centre =
            dab_reach(grid.positions, {3, 3, 0}, 0.5, 1, FalloffCurve::Constant);
        REQUIRE(centre.vertices.size() == 1);
        CHECK(paint_weights(brush, nullptr, t, centre, PaintMode::Smooth) == 0);
        // Subtracting half twice empties the reached weights, never below 0.
        const DabReach half = dab_reach(grid.positions, {3, 3, 0}, 2, 0.5, FalloffCurve::Constant);
        paint_weights(brush, nullptr, t, half, PaintMode::Subtract);
        CHECK(std::all_of(brush.weights.begin(), brush.weights.end(),
                          [](Scalar w) { return w == 0.5; }));
        paint_weights(brush, nullptr, t, half, PaintMode::Subtract);
        paint_weights(brush, nullptr, t, half, PaintMode::Subtract);
        CHECK(std::all_of(brush.weights.begin(), brush.weights.end(),
                          [](Scalar w) { return w == 0; }));
        CHECK(brush.vertices.size() == reach.vertices.size()); // members stay, at 0

        // Within one stroke overlapping dabs move a weight by the strength at most.
        const ConstraintSet start = brush;
        const DabReach third = dab_reach(grid.positions, {3, 3, 0}, 2, 0.3, FalloffCurve::Constant);
        paint_weights(brush, &start, t, third, PaintMode::Add);
        paint_weights(brush, &start, t, third, PaintMode::Add);
        CHECK(std::all_of(brush.weights.begin(), brush.weights.end(),
                          [](Scalar w) { return w == 0.3; }));
        // A set new in the stroke starts from 0 (stroke_start null means "as it is now").
        ConstraintSet fresh = vertex_set(ConstraintKind::Region, {});
        const ConstraintSet empty = fresh;
        paint_weights(fresh, &empty, t, third, PaintMode::Add);
        paint_weights(fresh, &empty, t, third, PaintMode::Add);
        CHECK(std::all_of(fresh.weights.begin(), fresh.weights.end(),
                          [](Scalar w) { return w == 0.3; }));

        // Smooth on an edge: a set of weight 1 next to outside vertices (0) loses some at
        // its edge, toward its neighbours' mean, from the old values (one Jacobi sweep).
        ConstraintSet anchors = vertex_set(ConstraintKind::Anchor, {24, 25}); // no map: 1s
        const DabReach both =
            dab_reach(grid.positions, {3.5, 3, 0}, 0.6, 1, FalloffCurve::Constant);
        REQUIRE(both.vertices == std::vector<Index>{24, 25});
        CHECK(paint_weights(anchors, nullptr, t, both, PaintMode::Smooth) == 2);
        // Vertex 24 (3, 3) has 4 neighbours, one of them (25) in the set: mean 1/4.
        CHECK(anchors.weights[0] == doctest::Approx(0.25));
        CHECK(anchors.weights[1] == doctest::Approx(0.25));
    }

    TEST_CASE(
        "the colours: the surface's own at 0 and outside the set, the ramp from green to red "
        "over it, translucent")
    {
        const ConstraintSet s = vertex_set(ConstraintKind::Anchor, {1, 2, 3}, {0, 0.5, 1});
        const std::array<float, 3> surface{0.8f, 0.6f, 0.4f};
        const std::vector<float> rgb = weight_colors(s, 5, surface, 0.5f);
        REQUIRE(rgb.size() == 15);
        const auto at = [&](size_t v) {
            return std::vector<float>(rgb.begin() + 3 * v, rgb.begin() + 3 * v + 3);
        };
        const std::vector<float> own{0.8f, 0.6f, 0.4f};
        CHECK(at(0) == own);
        CHECK(at(1) == own);                                  // weight 0
        CHECK(at(2) == std::vector<float>{0.4f, 0.8f, 0.2f}); // half green
        CHECK(at(3) == std::vector<float>{0.9f, 0.3f, 0.2f}); // half red
        CHECK(at(4) == own);
        // Opaque, the ramp itself.
        const std::vector<float> solid = weight_colors(s, 5, surface, 1.0f);
        CHECK(std::vector<float>(solid.begin() + 9, solid.begin() + 12) ==
              std::vector<float>{1, 0, 0});
    }

    TEST_CASE("a region's map: freedom 0 stays out, between 0 and 1 held by (1 - w) / w")
    {
        Mesh grid = test::open_grid(4, 4);
        test::perturb(grid, 0.1, 3);
        const SolverSettings settings;
        ConstraintSet region = vertex_set(ConstraintKind::Region, {6, 7, 8, 12}, {1, 0.25, 0, 0.5});
        const Recipe r = build_recipe({region}, settings, grid, grid.positions, 5);
        REQUIRE(r.region);
        CHECK(r.region->vertices == std::vector<Index>{6, 7, 12});
        REQUIRE(r.soft);
        CHECK(r.soft->vertices.indices == std::vector<Index>{7, 12});
        CHECK(r.soft->weights == std::vector<Scalar>{3, 1});
        CHECK(constraint_problems({region}, settings).empty());

        // An anchor set and a pin win over the fading: theirs are the weights.
        ConstraintSet anchors = vertex_set(ConstraintKind::Anchor, {7}, {0.5});
        anchors.mu = 4;
        ConstraintSet pin = vertex_set(ConstraintKind::Pin, {12});
        const Recipe both = build_recipe({region, anchors, pin}, settings, grid, grid.positions, 5);
        REQUIRE(both.soft);
        CHECK(both.soft->vertices.indices == std::vector<Index>{7});
        CHECK(both.soft->mu == 2); // one weight: mu * map
        CHECK(both.soft->weights.empty());

        // A map of the wrong size is a problem named with its set.
        region.weights.pop_back();
        const std::vector<std::string> problems = constraint_problems({region}, settings);
        REQUIRE(problems.size() == 1);
        CHECK(problems[0] == "set 'region' has 3 weights for 4 vertices");
    }

    TEST_CASE("a painted anchor map goes out as per-vertex weights and comes back as one set")
    {
        Mesh grid = test::open_grid(6, 6);
        std::vector<Index> vertices;
        std::vector<Scalar> weights;
        for (Index v = 0; v < 30; ++v)
        {
            vertices.push_back(v);
            weights.push_back(Scalar(v % 7) / 8); // 30 runs
        }
        ConstraintSet anchors = vertex_set(ConstraintKind::Anchor, vertices, weights);
        anchors.mu = 2;
        const SolverSettings settings;
        const Recipe r = build_recipe({anchors}, settings, grid, grid.positions, 3);
        REQUIRE(r.soft);
        REQUIRE(r.soft->weights.size() == 30);
        CHECK(r.soft->weights[3] == 2 * weights[3]);
        const ImportedRecipe back = sets_from_recipe(r, grid);
        REQUIRE(back.sets.size() == 1);
        CHECK(back.sets[0].weights.size() == 30);
        const Recipe again = build_recipe(back.sets, back.settings, grid, grid.positions, 3);
        CHECK(again.soft->weights == r.soft->weights);
        CHECK(again.soft->mu == r.soft->mu);
    }
}
