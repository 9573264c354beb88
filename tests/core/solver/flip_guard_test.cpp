// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/flip_guard.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/geometry/face_geometry.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

//! A flat fan of six triangles around vertex 0, facing +z.
Mesh hexagon_fan()
{
    std::vector<Vec3> points = {{0, 0, 0}};
    std::vector<std::vector<Index>> faces;
    for (int k = 0; k < 6; ++k)
    {
        const Scalar a = k * std::numbers::pi / 3;
        points.push_back({std::cos(a), std::sin(a), 0});
        faces.push_back({0, Index(1 + k), Index(1 + (k + 1) % 6)});
    }
    return test::make_mesh(points, faces);
}

using test::dot;

//! The faces that break, at y, a reference they kept at x (the header's rule, computed
//! here apart: own normals at x0 for faces within 60 degrees of the faces around them, the
//! faces around them at x).
int turned_by(const Mesh& m, std::span<const Scalar> x0, std::span<const Scalar> x,
              std::span<const Scalar> y)
{
    const auto around = [&](std::span<const Scalar> at, Index f) {
        Vec3 sum{0, 0, 0};
        for (const Index v : m.face(f))
            for (Index g = 0; g < m.face_count(); ++g)
                for (const Index w : m.face(g))
                    if (w == v)
                        for (int a = 0; a < 3; ++a)
                            sum[a] += face_area_vector(m, at, g)[a];
        return sum;
    };
    int count = 0;
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const Vec3 own = face_area_vector(m, x0, f), a0 = around(x0, f), a = around(x, f);
        const bool held = dot(own, a0) > 0.5 * std::sqrt(dot(own, own) * dot(a0, a0));
        const Vec3 nx = face_area_vector(m, x, f), ny = face_area_vector(m, y, f);
        const bool broke_own = held && dot(nx, own) > 0 && dot(ny, own) <= 0;
        const bool broke_around = dot(nx, a) > 0 && dot(ny, a) <= 0;
        count += broke_own || broke_around;
    }
    return count;
}

} // namespace

TEST_SUITE("FlipGuard")
{
    TEST_CASE("a step across the fan's rim is halved until no face turns over, the rest kept")
    {
        const Mesh m = hexagon_fan();
        const Topology t = build_topology(m);
        FlipGuard guard(m, t, m.positions, std::vector<char>(m.vertex_count(), 0));
        std::vector<Scalar> y = m.positions;
        y[0] = 3;   // the centre moved far past the rim: the faces on that side turn over
        y[3] = 1.1; // vertex 1 moved outwards a little: no face turns for it
        REQUIRE(turned_by(m, m.positions, m.positions, y) > 0);
        guard.begin_step(m.positions);
        CHECK(guard.limit(m.positions, y) == 1);
        REQUIRE(guard.shortened().size() == 1);
        CHECK(guard.shortened()[0] == 0);
        // 3 -> 1.5 still past the rim (1), 0.75 inside it: two halvings, exactly.
        CHECK(y[0] == 0.75);
        CHECK(y[1] == 0);
        CHECK(y[3] == 1.1);
        CHECK(turned_by(m, m.positions, m.positions, y) == 0);
        // A step that turns nothing is left as it is.
        std::vector<Scalar> small = m.positions;
        small[0] = 0.3;
        const std::vector<Scalar> before = small;
        guard.begin_step(m.positions);
        CHECK(guard.limit(m.positions, small) == 0);
        CHECK(small == before);
    }

    TEST_CASE("a fold of the input may turn back, and fixed vertices are never moved")
    {
        const Mesh m = hexagon_fan();
        const Topology t = build_topology(m);
        std::vector<Scalar> folded = m.positions;
        folded[0] = 1.5; // the input's centre past its rim: two faces point down
        Mesh input = m;
        input.positions = folded;
        std::vector<char> fixed(m.vertex_count(), 0);
        fixed[0] = 1;
        {
            FlipGuard guard(input, t, folded, std::vector<char>(m.vertex_count(), 0));
            std::vector<Scalar> back = folded;
            back[0] = 0; // back into the middle: every face faces up again
            guard.begin_step(folded);
            CHECK(guard.limit(folded, back) == 0);
            CHECK(back[0] == 0);
        }
        {
            // The centre fixed: a step that would turn faces over through the rim vertices
            // shortens theirs, never the centre's.
            FlipGuard guard(m, t, m.positions, fixed);
            std::vector<Scalar> y = m.positions;
            for (Index v = 1; v <= 6; ++v)
                y[3 * v] = -y[3 * v] - 2; // the rim mirrored past the centre
            guard.begin_step(m.positions);
            CHECK(guard.limit(m.positions, y) > 0);
            CHECK(y[0] == 0);
            CHECK(turned_by(m, m.positions, m.positions, y) == 0);
        }
    }

    TEST_CASE(
        "on a noisy sphere's wild step: nothing turned over, the same bits on 1 and 2 "
        "threads")
    {
        test::ThreadCountGuard restore;
        Mesh m = test::icosphere(2);
        const Topology t = build_topology(m);
        std::mt19937_64 random(5);
        std::normal_distribution<Scalar> gauss(0, 0.15);
        std::vector<Scalar> step(m.positions.size());
        for (Scalar& s : step)
            s = gauss(random);
        std::vector<std::vector<Scalar>> results;
        for (const int threads : {1, 2})
        {
            set_thread_count(threads);
            FlipGuard guard(m, t, m.positions, std::vector<char>(m.vertex_count(), 0));
            std::vector<Scalar> y = m.positions;
            for (size_t k = 0; k < y.size(); ++k)
                y[k] += step[k];
            REQUIRE(turned_by(m, m.positions, m.positions, y) > 0);
            guard.begin_step(m.positions);
            CHECK(guard.limit(m.positions, y) > 0);
            CHECK(turned_by(m, m.positions, m.positions, y) == 0);
            results.push_back(y);
        }
        CHECK(results[0] == results[1]);
    }
}
