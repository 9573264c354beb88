// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/volume_constraint.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "core/recipe/session.h"
#include "tests/energy_checks.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

//! A closed quad torus and, apart from it, an open grid: one closed component of two.
Mesh torus_and_grid()
{
    return test::joined(test::quad_torus(16, 10, 2.0, 0.7), test::open_grid(3, 3), {10, 0, 0});
}

Scalar relative(Scalar a, Scalar b)
{
    return std::abs(a - b) / std::abs(b);
}

} // namespace

TEST_SUITE("VolumeConstraint")
{
    TEST_CASE("the volume of a quad cube, a tetrahedron and a torus by the divergence theorem")
    {
        const std::vector<char> none(8, 0);
        {
            const Mesh m = test::quad_cube();
            const Topology t = build_topology(m);
            const VolumeConstraint v(m, t, m.positions, none);
            REQUIRE(v.component_count() == 1);
            CHECK(v.volume(0, m.positions) == doctest::Approx(1).epsilon(1e-15));
        }
        {
            const Mesh m = test::tetrahedron();
            const Topology t = build_topology(m);
            const VolumeConstraint v(m, t, m.positions, std::vector<char>(4, 0));
            // 1/6 |det(b - a, c - a, d - a)|, computed apart.
            const Vec3 a = m.position(0), b = m.position(1), c = m.position(2), d = m.position(3);
            const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                w{c[0] - a[0], c[1] - a[1], c[2] - a[2]}, z{d[0] - a[0], d[1] - a[1], d[2] - a[2]};
            const Scalar det = u[0] * (w[1] * z[2] - w[2] * z[1]) -
                               u[1] * (w[0] * z[2] - w[2] * z[0]) +
                               u[2] * (w[0] * z[1] - w[1] * z[0]);
            CHECK(std::abs(v.volume(0, m.positions)) ==
                  doctest::Approx(std::abs(det) / 6).epsilon(1e-14));
        }
        {
            // A polyhedral torus of 64 x 40 quads is within 1 % of 2 pi^2 R r^2 (its
            // inscribed polygons lose about (2 pi / n)^2 / 6 each way: 0.4 % and 0.07 %).
            const Mesh m = test::quad_torus(64, 40, 2.0, 0.7);
            const Topology t = build_topology(m);
            const VolumeConstraint v(m, t, m.positions, std::vector<char>(m.vertex_count(), 0));
            CHECK(relative(v.volume(0, m.positions), 2 * M_PI * M_PI * 2.0 * 0.49) < 1e-2);
        }
    }

    TEST_CASE("the gradient is 6 dV/dx (central differences), on triangles and polygons")
    {
        for (Mesh m : {test::icosphere(1), test::quad_torus(8, 6, 2.0, 0.7)})
        {
            test::perturb(m, 0.05, 3);
            const Topology t = build_topology(m);
            const VolumeConstraint v(m, t, m.positions, std::vector<char>(m.vertex_count(), 0));
            std::vector<Scalar> rhs(m.positions.size());
            for (Index i = 0; i < m.vertex_count(); ++i)
                volume_gradient6(m, t, m.positions, i, &rhs[3 * i]);
            // check_rhs_is_half_negative_gradient compares -1/2 dE/dx: E = -12 V.
            test::check_rhs_is_half_negative_gradient(
                [&](std::span<const Scalar> x) { return -12 * v.volume(0, x); }, m.positions, rhs);
        }
    }

    TEST_CASE(
        "projecting restores each closed component's volume and moves only free vertices "
        "(open components left alone)")
    {
        Mesh m = torus_and_grid();
        const Topology t = build_topology(m);
        std::vector<char> fixed(m.vertex_count(), 0);
        fixed[0] = fixed[17] = 1;
        VolumeConstraint v(m, t, m.positions, fixed, OpenVolume::None);
        CHECK(v.component_count() == 2);
        CHECK(v.closed_component_count() == 1);
        CHECK(v.loop_count() == 0);
        REQUIRE(v.notes().size() == 1);
        CHECK(v.notes()[0] ==
              "volume: 1 of 2 components are open (a boundary, an edge of three or more faces, or "
              "faces of opposite orientations; first faces 160): their volumes are not kept");
        const Scalar kept = v.target_volumes()[0];
        std::vector<Scalar> x = m.positions;
        for (Scalar& c : x)
            c *= 0.9; // shrink everything (the fixed vertices are moved back below)
        for (const size_t k : {size_t(0), size_t(3 * 17)})
            for (size_t a = 0; a < 3; ++a)
                x[k + a] = m.positions[k + a];
        const std::vector<Scalar> before = x;
        v.project(x);
        CHECK(relative(v.volume(0, x), kept) < 1e-14);
        for (const Index i : {0, 17})
            CHECK(std::memcmp(&x[3 * i], &before[3 * i], 3 * sizeof(Scalar)) == 0);
        // The open grid's vertices (after the torus's) are left alone.
        CHECK(std::memcmp(&x[3 * 160], &before[3 * 160], (x.size() - 3 * 160) * sizeof(Scalar)) ==
              0);
    }

    TEST_CASE("with \"open\": \"none\" a mesh with no closed component is refused naming the key")
    {
        for (const Mesh& m : {test::open_grid(3, 3), test::nonmanifold_fan()})
        {
            const Topology t = build_topology(m);
            Recipe r;
            r.volume = KeepVolume{OpenVolume::None};
            CHECK_THROWS_WITH_AS(Session(m, t, r),
                                 "recipe: volume: the mesh has no closed component (each has a "
                                 "boundary, an edge of three or more faces, or faces of opposite "
                                 "orientations): it encloses no volume to keep (\"open\": "
                                 "\"capped\" keeps the volume enclosed with the boundary loops "
                                 "capped)",
                                 RecipeError);
            r.volume = KeepVolume{}; // capped: accepted
            CHECK_NOTHROW(Session(m, t, r));
        }
        // Faces of opposite orientations: a cube with one face flipped.
        Mesh m = test::quad_cube();
        std::reverse(m.face_vertices.begin(), m.face_vertices.begin() + 4);
        const Topology t = build_topology(m);
        Recipe r;
        r.volume = KeepVolume{OpenVolume::None};
        CHECK_THROWS_AS(Session(m, t, r), RecipeError);
    }

    TEST_CASE("an open box capped by its rim's centroid encloses the closed box's volume")
    {
        // The quad cube without its top face: one loop of 4 edges, capped by the fan from
        // the top square's centre, which is the top square itself.
        const Mesh cube = test::quad_cube();
        Mesh box;
        for (Index v = 0; v < cube.vertex_count(); ++v)
            box.add_vertex(cube.positions[3 * v], cube.positions[3 * v + 1],
                           cube.positions[3 * v + 2]);
        Index removed = kInvalidIndex;
        for (Index f = 0; f < cube.face_count(); ++f)
        {
            const Vec3 c = face_centroid(cube, cube.positions, f);
            if (c[2] > 0.9 && removed == kInvalidIndex)
            {
                removed = f;
                continue;
            }
            box.add_face(std::vector<Index>(cube.face(f).begin(), cube.face(f).end()));
        }
        REQUIRE(removed != kInvalidIndex);
        const Topology t = build_topology(box);
        const VolumeConstraint v(box, t, box.positions, std::vector<char>(8, 0));
        CHECK(v.closed_component_count() == 0);
        CHECK(v.loop_count() == 1);
        CHECK(v.volume(0, box.positions) == doctest::Approx(1).epsilon(1e-15));
        // Moved anywhere, it keeps that volume (the caps follow the loop).
        std::vector<Scalar> x = box.positions;
        for (size_t k = 0; k < x.size(); ++k)
            x[k] += k % 3 == 0 ? 10.5 : -3.25;
        CHECK(v.volume(0, x) == doctest::Approx(1).epsilon(1e-13));
        REQUIRE(v.notes().size() == 1);
        CHECK(v.notes()[0] ==
              "volume: 1 of 1 components are open (a boundary, an edge of three or more faces, or "
              "faces of opposite orientations; first faces 0): the volume kept there is the one "
              "enclosed with their 1 boundary loops capped by fans from the loops' centroids");
    }

    TEST_CASE("the capped volume's gradient, through a moving boundary, is 6 dV/dx")
    {
        // A perturbed wavy grid (one loop) and a non-manifold fan (loops through its edge of
        // three faces): project() along the gradient restores the volume, which it can only
        // do to 1e-13 when its direction is the gradient: compared with central differences.
        for (Mesh m : {test::open_grid(4, 3), test::nonmanifold_fan(), test::mixed_polygons()})
        {
            test::perturb(m, 0.1, 7);
            const Topology t = build_topology(m);
            const Index n = m.vertex_count();
            VolumeConstraint v(m, t, m.positions, std::vector<char>(n, 0));
            REQUIRE(v.loop_count() >= 1);
            // The projection's direction from a shrunken copy: x' - x = t g at every vertex.
            std::vector<Scalar> x = m.positions;
            for (Scalar& c : x)
                c *= 0.8;
            const std::vector<Scalar> shrunk = x;
            v.project(x);
            CHECK(relative(v.volume(0, x), v.target_volumes()[0]) < 1e-12);
            // The finite-difference gradient of V at the shrunken positions.
            std::vector<Scalar> g(x.size());
            const Scalar h = 1e-6;
            for (size_t k = 0; k < x.size(); ++k)
            {
                std::vector<Scalar> a = shrunk, b = shrunk;
                a[k] += h;
                b[k] -= h;
                g[k] = (v.volume(0, a) - v.volume(0, b)) / (2 * h);
            }
            // x - shrunk is parallel to g (the step is t g for one scalar t, of either sign).
            Scalar dot = 0, gg = 0, dd = 0;
            for (size_t k = 0; k < x.size(); ++k)
            {
                const Scalar d = x[k] - shrunk[k];
                dot += d * g[k];
                gg += g[k] * g[k];
                dd += d * d;
            }
            REQUIRE(dd > 0);
            CHECK(std::abs(dot) / std::sqrt(gg * dd) == doctest::Approx(1).epsilon(1e-6));
        }
    }

    TEST_CASE("\"components\": \"free\" keeps only the components that hold no fixed vertex")
    {
        Mesh m = torus_and_grid();
        for (Index v = 160; v < m.vertex_count(); ++v) // the grid made wavy: a capped volume
            m.positions[3 * v + 2] = 0.3 * std::sin(1.3 * m.positions[3 * v] + v);
        const Topology t = build_topology(m);
        std::vector<char> fixed(m.vertex_count(), 0);
        fixed[3] = 1; // a vertex of the torus
        VolumeConstraint v(m, t, m.positions, fixed, OpenVolume::Capped, true);
        CHECK_FALSE(v.is_kept(0));
        CHECK(v.is_kept(1));
        std::vector<Scalar> x = m.positions;
        for (Scalar& c : x)
            c *= 0.9;
        const std::vector<Scalar> before = x;
        v.project(x);
        // The torus is left alone, the grid's capped volume restored.
        CHECK(std::memcmp(x.data(), before.data(), 3 * 160 * sizeof(Scalar)) == 0);
        REQUIRE(std::abs(v.target_volumes()[1]) > 1e-3);
        CHECK(relative(v.volume(1, x), v.target_volumes()[1]) < 1e-12);
        CHECK(v.notes()[0].find("1 of 2 components hold fixed vertices") != std::string::npos);
    }

    TEST_CASE(
        "every step keeps the volume to 1e-9, for each method, with pins and regions, "
        "with the same bits on one and two threads")
    {
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.03, 11);
        const Topology t = build_topology(m);
        const Scalar v0 = [&] {
            const VolumeConstraint v(m, t, m.positions, std::vector<char>(m.vertex_count(), 0));
            return v.volume(0, m.positions);
        }();
        struct Case
        {
            const char* name;
            Recipe recipe;
        };
        std::vector<Case> cases;
        Recipe plain;
        plain.iterations = 30;
        plain.volume = KeepVolume{};
        cases.push_back({"plain", plain});
        Recipe pinned = plain;
        pinned.hard = HardVertices{{0, 5, 9}, {}};
        pinned.region = Region{test::all_indices(m.vertex_count() / 2), {}};
        cases.push_back({"pins and a region", pinned});
        Recipe combined = plain;
        combined.centroid = CentroidConstraints{{true, {}}, 1.0, {}, CentroidDenominator::Paper};
        combined.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Smoothed, {}};
        combined.normal_smoothing = NormalSmoothing{5, 0.5, {}, {}};
        cases.push_back({"combined", combined});
        Recipe optimal = combined;
        optimal.optimal_step = true;
        cases.push_back({"line search", optimal});
        Recipe joint = combined;
        joint.joint = Joint{1.0};
        cases.push_back({"joint", joint});
        Recipe taubin = plain;
        taubin.method = Method::Taubin;
        cases.push_back({"taubin", taubin});
        Recipe gradient = plain;
        gradient.method = Method::GradientDescent;
        gradient.lambda = 0.05; // unpreconditioned: a Jacobi-sized step would diverge
        cases.push_back({"gradient descent", gradient});
        for (const Case& c : cases)
        {
            const std::string name = c.name;
            CAPTURE(name);
            std::vector<std::vector<Scalar>> results;
            for (const int threads : {1, 2})
            {
                set_thread_count(threads);
                Mesh x = m;
                Session session(x, t, c.recipe);
                session.set_positions(x.positions);
                const VolumeConstraint& v = *session.volume();
                Scalar worst = 0;
                for (int k = 0; k < c.recipe.iterations; ++k)
                {
                    session.step();
                    worst = std::max(worst, relative(v.volume(0, session.positions()), v0));
                }
                CHECK(worst < 1e-9);
                results.emplace_back(session.positions().begin(), session.positions().end());
            }
            set_thread_count(0);
            CHECK(std::memcmp(results[0].data(), results[1].data(),
                              results[0].size() * sizeof(Scalar)) == 0);
            CHECK(results[0] != m.positions);
        }
    }
}

TEST_SUITE("Taubin")
{
    TEST_CASE("lambda|mu shrinks a noisy sphere far less than lambda alone, and smooths it")
    {
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.02, 12);
        const Topology t = build_topology(m);
        const VolumeConstraint measure(m, t, m.positions, std::vector<char>(m.vertex_count(), 0));
        const Scalar v0 = measure.volume(0, m.positions);
        Recipe jacobi;
        jacobi.iterations = 20;
        Recipe taubin = jacobi;
        taubin.method = Method::Taubin;
        Mesh a = m, b = m;
        const SmoothResult ra = smooth(a, t, jacobi);
        const SmoothResult rb = smooth(b, t, taubin);
        const Scalar loss_jacobi = 1 - measure.volume(0, a.positions) / v0;
        const Scalar loss_taubin = 1 - measure.volume(0, b.positions) / v0;
        CAPTURE(loss_jacobi);
        CAPTURE(loss_taubin);
        CHECK(loss_jacobi > 0.02);
        CHECK(std::abs(loss_taubin) < 0.2 * loss_jacobi);
        // Both smooth the noise: the face normals approach the clean sphere's, Taubin's without
        // the shrinking.
        const Mesh clean = test::icosphere(3);
        const auto theta = [&](const Mesh& x) {
            const std::vector<Scalar> u = face_normals(x, x.positions),
                                      c = face_normals(clean, clean.positions);
            Scalar sum = 0;
            for (size_t k = 0; k < u.size(); k += 3)
                sum += std::acos(std::clamp<Scalar>(
                    u[k] * c[k] + u[k + 1] * c[k + 1] + u[k + 2] * c[k + 2], -1, 1));
            return sum / static_cast<Scalar>(u.size() / 3);
        };
        CHECK(theta(b) < 0.5 * theta(m));
        CHECK(rb.energies.back().edge < rb.energies.front().edge);
        CHECK(ra.iterations == 20);
    }
}
