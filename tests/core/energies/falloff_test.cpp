// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/falloff.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"
#include "tests/session_checks.h"

using namespace meshfair;

namespace {

constexpr int kGrid = 20; // an open grid of 20 x 20 unit quads
constexpr Index kCenter = 10 * (kGrid + 1) + 10;

//! The grid's vertices off its outer ring: the region that may move.
std::vector<Index> grid_interior()
{
    std::vector<Index> v;
    for (int j = 1; j < kGrid; ++j)
        for (int i = 1; i < kGrid; ++i)
            v.push_back(j * (kGrid + 1) + i);
    return v;
}

//! The grid after 40 steps with the centre pinned 3 units up, with or without falloff.
Mesh pulled_grid(bool falloff)
{
    Mesh m = test::open_grid(kGrid, kGrid);
    const Topology t = build_topology(m);
    Recipe r;
    r.iterations = 40;
    r.region = Region{grid_interior(), {}};
    r.hard = HardVertices{{kCenter}, {{10.0, 10.0, 3.0}}};
    if (falloff)
        r.falloff = Falloff{5, true, FalloffCurve::Smooth, 1.0, true, true};
    smooth(m, t, r);
    return m;
}

} // namespace

TEST_SUITE("Falloff")
{
    TEST_CASE("the curves are Blender's: 1 at the source, 0 from the radius on")
    {
        const FalloffCurve curves[] = {FalloffCurve::Smooth, FalloffCurve::Sphere,
                                       FalloffCurve::Root,   FalloffCurve::Linear,
                                       FalloffCurve::Sharp,  FalloffCurve::Constant};
        for (const FalloffCurve c : curves)
        {
            CHECK(falloff_weight(c, 0, 2) == 1);
            CHECK(falloff_weight(c, 2, 2) == 0);
            CHECK(falloff_weight(c, 5, 2) == 0);
            Scalar previous = 1;
            for (int k = 1; k < 20; ++k)
            {
                const Scalar w = falloff_weight(c, 0.1 * k, 2);
                CHECK(w <= previous);
                CHECK(w > 0);
                previous = w;
            }
        }
        CHECK(falloff_weight(FalloffCurve::Smooth, 1, 2) == doctest::Approx(0.5));
        CHECK(falloff_weight(FalloffCurve::Sphere, 1.2, 2) == doctest::Approx(0.8));
        CHECK(falloff_weight(FalloffCurve::Root, 1.5, 2) == doctest::Approx(0.5));
        CHECK(falloff_weight(FalloffCurve::Linear, 0.5, 2) == doctest::Approx(0.75));
        CHECK(falloff_weight(FalloffCurve::Sharp, 1, 2) == doctest::Approx(0.25));
        CHECK(falloff_weight(FalloffCurve::Constant, 1.9, 2) == 1);
        CHECK(falloff_weight(FalloffCurve::Linear, 0, 0) == 1); // radius 0: the sources only
        CHECK(falloff_weight(FalloffCurve::Linear, 0.1, 0) == 0);
    }

    TEST_CASE("surface distances are shortest paths along the edges, with the nearest source")
    {
        const Mesh m = test::open_grid(6, 4);
        const Topology t = build_topology(m);
        // Sources: the corners (0, 0) and (6, 4); on a grid of unit squares the edge-graph
        // distance is the Manhattan distance.
        const std::vector<Index> sources{0, 4 * 7 + 6};
        const SurfaceDistances d = surface_distances(t, m.positions, sources, 100);
        for (int j = 0; j <= 4; ++j)
            for (int i = 0; i <= 6; ++i)
            {
                const Index v = j * 7 + i;
                const int a = i + j, b = (6 - i) + (4 - j);
                CAPTURE(v);
                CHECK(d.distance[v] == std::min(a, b));
                CHECK(d.source[v] == (a <= b ? 0 : 1)); // ties: the source listed first
            }
        const SurfaceDistances near = surface_distances(t, m.positions, sources, 2.5);
        CHECK(near.distance[2] == 2);
        CHECK(near.distance[3] == std::numeric_limits<Scalar>::infinity());
        CHECK(near.source[3] == kInvalidIndex);
        // The falloff's unit from V(i) alone (a solver's topology has no edge list).
        const Topology neighbors = build_topology(m, TopologyParts::Neighbors);
        CHECK(mean_edge_length(neighbors, m.positions) == 1);
        CHECK(mean_edge_length(t, m.positions) == 1);
    }

    TEST_CASE("a moved pin raises a smooth bump of the falloff's radius, not a spike")
    {
        const Mesh spike = pulled_grid(false), bump = pulled_grid(true);
        const auto height = [](const Mesh& m, int i) {
            return m.positions[3 * (10 * (kGrid + 1) + i) + 2];
        };
        // Without falloff the pin's neighbours stay far below it: a spike.
        CHECK(height(spike, 11) < 0.5 * 3);
        // With it they follow most of the way, and the profile falls steadily outward.
        CHECK(height(bump, 11) > 0.6 * 3);
        CHECK(height(bump, 11) > height(spike, 11) + 0.5);
        for (int i = 11; i < kGrid; ++i)
        {
            CAPTURE(i);
            CHECK(height(bump, i) < height(bump, i - 1));
        }
        // Every face still faces up: nothing turned inside out, with or without.
        const std::vector<Scalar> n = face_normals(bump, bump.positions);
        for (size_t f = 0; 3 * f < n.size(); ++f)
            CHECK(n[3 * f + 2] > 0.2);
    }

    TEST_CASE(
        "dragging a pin moves the anchors around it (set_hard_targets), as a new recipe "
        "with the pin's new target would, bit for bit")
    {
        Mesh m = test::open_grid(kGrid, kGrid);
        const Topology t = build_topology(m);
        Recipe r;
        r.iterations = 5;
        r.region = Region{grid_interior(), {}};
        r.hard = HardVertices{{kCenter, 45}, {{10.0, 10.0, 0.0}, {3.0, 2.0, 0.0}}};
        r.falloff = Falloff{4, true, FalloffCurve::Sphere, 2.0, true, true};
        Session dragged(m, t, r);
        const std::vector<Scalar> moved{10.0, 10.0, 2.5, 3.0, 2.0, -1.0};
        dragged.set_hard_targets(moved);
        Mesh a = m;
        dragged.apply_hard_targets(a.positions);
        run(dragged, a.positions);
        Recipe direct = r;
        direct.hard->targets = {{10.0, 10.0, 2.5}, {3.0, 2.0, -1.0}};
        Mesh b = m;
        smooth(b, t, direct);
        CHECK(std::memcmp(a.positions.data(), b.positions.data(),
                          a.positions.size() * sizeof(Scalar)) == 0);
        CHECK(a.positions[3 * (kCenter + 1) + 2] > 1);
    }

    TEST_CASE(
        "border anchors hold the vertices near the fixed rest, not the ones further in, "
        "the same bits on one and two threads")
    {
        Mesh m = test::open_grid(kGrid, kGrid);
        test::perturb(m, 0.2, 4);
        const Topology t = build_topology(m);
        Recipe r;
        r.iterations = 30;
        r.region = Region{grid_interior(), {}};
        r.falloff = Falloff{3, false, FalloffCurve::Linear, 1e6, true, false};
        Recipe plain = r;
        plain.falloff.reset();
        test::check_same_bits_on_one_and_two_threads(m, t, r);
        Mesh held = m;
        smooth(held, t, r);
        const std::vector<Scalar>& anchored = held.positions;
        Mesh free = m;
        smooth(free, t, plain);
        const auto moved = [&](const std::vector<Scalar>& x, Index v) {
            Scalar d = 0;
            for (int a = 0; a < 3; ++a)
                d += std::abs(x[3 * v + a] - m.positions[3 * v + a]);
            return d;
        };
        // Vertex (1, 10) is 1 from the rest: held. (10, 10) is 9 in, beyond the radius:
        // smoothed as without falloff.
        CHECK(moved(anchored, 10 * (kGrid + 1) + 1) < 1e-4);
        CHECK(moved(free.positions, 10 * (kGrid + 1) + 1) > 1e-2);
        CHECK(moved(anchored, kCenter) > 0.5 * moved(free.positions, kCenter));
    }

    TEST_CASE(
        "a falloff with nothing to fade from anchors nothing and says so, a negative "
        "radius is refused naming the key")
    {
        Mesh m = test::open_grid(3, 3);
        test::perturb(m, 0.1, 2);
        const Topology t = build_topology(m);
        Recipe r;
        r.falloff = Falloff{};
        Recipe plain;
        for (Recipe* recipe : {&r, &plain})
            recipe->iterations = 5;
        // The whole mesh free, no anchor: the plain recipe's steps, with a note.
        Mesh a = m, b = m;
        const Session faded(a, t, r);
        REQUIRE(faded.notes().size() == 1);
        CHECK(faded.notes()[0] ==
              "falloff: no region border or pins to fade from: no anchors "
              "fade in (the whole mesh is free)");
        smooth(a, t, r);
        smooth(b, t, plain);
        CHECK(a.positions == b.positions);
        CHECK(a.positions != m.positions);
        // Only pins to fade from, and no pins: the same.
        r.region = Region{{5}, {}};
        r.falloff->border = false;
        CHECK(Session(m, t, r).notes().size() == 1);
        r.falloff->border = true;
        CHECK(Session(m, t, r).notes().empty());
        r.falloff->radius = -1;
        CHECK_THROWS_WITH_AS(check_recipe(r, m), "recipe: falloff.radius: must be finite and >= 0",
                             RecipeError);
    }
}
