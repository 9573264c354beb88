// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/normal_smoothing_term.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "core/geometry/face_geometry.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

Scalar length(std::span<const Scalar> u, Index f)
{
    return std::sqrt(u[3 * f] * u[3 * f] + u[3 * f + 1] * u[3 * f + 1] +
                     u[3 * f + 2] * u[3 * f + 2]);
}

} // namespace

TEST_SUITE("NormalSmoothingTerm")
{
    TEST_CASE("smoothing lowers the dual energy, keeps unit length and hard normals")
    {
        Mesh m = test::icosphere(2);
        test::perturb(m, 0.02, 3);
        const Topology t = build_topology(m);
        std::vector<Scalar> u = face_normals(m, m.positions);
        const std::vector<Index> hard{0, 7};
        const std::vector<Scalar> hard_normals{0, 0, 1, 1, 0, 0};
        const NormalSmoothingTerm term(t, hard, hard_normals, {}, 0, {});
        term.apply_hard(u);
        std::vector<Scalar> scratch(u.size());
        Scalar energy = term.dual_energy(u);
        for (int k = 0; k < 10; ++k)
        {
            term.step(u, 0.5, scratch);
            const Scalar next = term.dual_energy(u);
            CHECK(next < energy);
            energy = next;
        }
        for (Index f = 0; f < m.face_count(); ++f)
            CHECK(length(u, f) == doctest::Approx(1).epsilon(1e-14));
        CHECK(std::memcmp(&u[0], &hard_normals[0], 3 * sizeof(Scalar)) == 0);
        CHECK(std::memcmp(&u[21], &hard_normals[3], 3 * sizeof(Scalar)) == 0);
    }

    TEST_CASE("with lambda = 1 a face takes the normalized mean of its dual neighbours")
    {
        const Mesh m = test::open_grid(3, 3);
        const Topology t = build_topology(m);
        std::vector<Scalar> u(3 * m.face_count());
        for (Index f = 0; f < m.face_count(); ++f)
        {
            u[3 * f] = 0.1 * f;
            u[3 * f + 2] = 1;
            normalize3(&u[3 * f]);
        }
        const std::vector<Scalar> old = u;
        const NormalSmoothingTerm term(t, {}, {}, {}, 0, {});
        std::vector<Scalar> scratch(u.size());
        term.step(u, 1.0, scratch);
        const Index f = 4; // the centre face has four dual neighbours: 1, 3, 5, 7
        Scalar mean[3] = {0, 0, 0};
        for (const Index g : t.face_neighbors_of(f))
            for (int a = 0; a < 3; ++a)
                mean[a] += old[3 * g + a];
        normalize3(mean);
        CHECK(t.dual_valence(f) == 4);
        for (int a = 0; a < 3; ++a)
            CHECK(u[3 * f + a] == doctest::Approx(mean[a]).epsilon(1e-14));
    }

    TEST_CASE("a soft normal constraint pulls toward its target")
    {
        const Mesh m = test::open_grid(2, 1); // two faces, one dual edge
        const Topology t = build_topology(m);
        std::vector<Scalar> u{0, 0, 1, 0, 0, 1};
        const std::vector<Index> soft{0};
        const std::vector<Scalar> target{1, 0, 0};
        const NormalSmoothingTerm term(t, {}, {}, soft, 1.0, target);
        CHECK(term.soft_energy(u) == 2.0);
        std::vector<Scalar> scratch(u.size());
        term.step(u, 1.0, scratch);
        // Face 0: ((u1 - u0) + (t - u0)) / 2 + u0 = (u1 + t) / 2 -> normalized (1, 0, 1)/sqrt2.
        CHECK(u[0] == doctest::Approx(std::sqrt(0.5)));
        CHECK(u[2] == doctest::Approx(std::sqrt(0.5)));
        CHECK(term.soft_energy(u) < 2.0);
    }

    TEST_CASE("soft normals with their own weights: each face's step uses mu w_f")
    {
        const Mesh m = test::open_grid(3, 1); // three faces in a row, two dual edges
        const Topology t = build_topology(m);
        const std::vector<Scalar> start{0, 0, 1, 0, 0, 1, 0, 0, 1};
        const std::vector<Index> soft{0, 2};
        const std::vector<Scalar> target{1, 0, 0, 0, 1, 0};
        const std::vector<Scalar> weights{3.0, 0.5};
        const Scalar mu = 2.0;
        const NormalSmoothingTerm term(t, {}, {}, soft, mu, target, weights);
        CHECK(term.soft_weight(0) == 6.0);
        CHECK(term.soft_weight(1) == 0.0);
        CHECK(term.soft_weight(2) == 1.0);
        // |u_f - u0_f|^2 = 2 for both soft faces.
        CHECK(term.soft_energy(start) == doctest::Approx(2 * 6.0 + 2 * 1.0));
        std::vector<Scalar> u = start, scratch(u.size());
        term.step(u, 1.0, scratch);
        // Face 0: (u_1 - u_0 + mu_0 (t_0 - u_0)) / (1 + mu_0) + u_0 = (u_1 + 6 t_0) / 7.
        Scalar expected0[3] = {6.0 / 7, 0, 1.0 / 7};
        normalize3(expected0);
        // Face 2: (u_1 + 1 t_2) / 2.
        Scalar expected2[3] = {0, 0.5, 0.5};
        normalize3(expected2);
        for (int a = 0; a < 3; ++a)
        {
            CHECK(u[a] == doctest::Approx(expected0[a]).epsilon(1e-14));
            CHECK(u[6 + a] == doctest::Approx(expected2[a]).epsilon(1e-14));
        }
        // A weight of 0 is no soft constraint: the same step as without face 0 in F_S.
        const NormalSmoothingTerm zero(t, {}, {}, soft, mu, target, std::vector<Scalar>{0.0, 0.5});
        const std::vector<Index> only2{2};
        const std::vector<Scalar> target2{0, 1, 0};
        const NormalSmoothingTerm without(t, {}, {}, only2, mu * 0.5, target2);
        std::vector<Scalar> a = start, b = start;
        zero.step(a, 0.5, scratch);
        without.step(b, 0.5, scratch);
        for (size_t k = 0; k < a.size(); ++k)
            CHECK(a[k] == doctest::Approx(b[k]).epsilon(1e-15));
    }
}
