// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/soft_vertex_term.h"

#include <doctest/doctest.h>

#include "core/energies/edge_term.h"
#include "core/recipe/session.h"
#include "tests/energy_checks.h"
#include "tests/helpers.h"

using namespace meshfair;

TEST_SUITE("SoftVertexTerm")
{
    TEST_CASE("right-hand side is minus half the gradient (central differences)")
    {
        Mesh m = test::icosphere(1);
        const std::vector<Index> vertices{0, 4, 9, 30};
        std::vector<Scalar> targets;
        for (const Index v : vertices)
            for (int a = 0; a < 3; ++a)
                targets.push_back(m.positions[3 * v + a] + 0.1 * (a + 1));
        test::perturb(m, 0.1, 8);
        const SoftVertexTerm term(m.vertex_count(), vertices, 2.5, targets);
        std::vector<Index> all(m.vertex_count());
        for (Index i = 0; i < m.vertex_count(); ++i)
            all[i] = i;
        std::vector<Scalar> rhs(m.positions.size(), 0);
        term.add_rhs(m.positions, all, rhs);
        test::check_rhs_is_half_negative_gradient(
            [&](std::span<const Scalar> x) { return term.energy(x); }, m.positions, rhs);
    }

    TEST_CASE("with the edge term the step is the paper's formula")
    {
        // dx_i = (sum_j (x_j - x_i) + mu (x0_i - x_i)) / (n_i + mu) on constrained vertices.
        Mesh m = test::icosphere(1);
        test::perturb(m, 0.1, 2);
        const Topology t = build_topology(m);
        const Scalar mu = 0.7;
        Recipe recipe;
        recipe.iterations = 1;
        recipe.lambda = 1.0;
        recipe.soft = SoftVertices{{false, {3, 5}}, mu, {}};
        recipe.soft->targets = {{0.1, 0.2, 0.3}, {-0.4, 0.5, -0.6}};
        const Mesh before = m;
        smooth(m, t, recipe);
        for (const Index i : {3, 5})
        {
            const Vec3 target = recipe.soft->targets[i == 3 ? 0 : 1];
            for (int a = 0; a < 3; ++a)
            {
                Scalar sum = 0;
                for (const Index j : t.neighbors(i))
                    sum += before.positions[3 * j + a] - before.positions[3 * i + a];
                const Scalar dx =
                    (sum + mu * (target[a] - before.positions[3 * i + a])) / (t.valence(i) + mu);
                CHECK(m.positions[3 * i + a] ==
                      doctest::Approx(before.positions[3 * i + a] + dx).epsilon(1e-14));
            }
        }
    }

    TEST_CASE("one vertex's Jacobi displacement zeroes its partial gradient")
    {
        Mesh m = test::mixed_polygons();
        const Topology t = build_topology(m);
        const std::vector<Index> vertices{5};
        const std::vector<Scalar> target{1.5, 0.5, 2.0};
        const EdgeTerm edge(t);
        const SoftVertexTerm soft(m.vertex_count(), vertices, 3.0, target);
        std::vector<Scalar> diagonal(m.vertex_count(), 0), rhs(m.positions.size(), 0);
        edge.add_diagonal(diagonal);
        soft.add_diagonal(diagonal);
        edge.add_rhs(m.positions, vertices, rhs);
        soft.add_rhs(m.positions, vertices, rhs);
        for (int a = 0; a < 3; ++a)
            m.positions[15 + a] += rhs[15 + a] / diagonal[5];
        std::vector<Scalar> after(m.positions.size(), 0);
        edge.add_rhs(m.positions, vertices, after);
        soft.add_rhs(m.positions, vertices, after);
        for (int a = 0; a < 3; ++a)
            CHECK(after[15 + a] == doctest::Approx(0).epsilon(1e-12).scale(1));
    }

    TEST_CASE("with a weight per vertex: right-hand side, diagonal and energy use mu w_i")
    {
        Mesh m = test::icosphere(1);
        const std::vector<Index> vertices{0, 4, 9, 30};
        const std::vector<Scalar> weights{0.5, 0.0, 3.0, 1.25};
        std::vector<Scalar> targets;
        for (const Index v : vertices)
            for (int a = 0; a < 3; ++a)
                targets.push_back(m.positions[3 * v + a] + 0.1 * (a + 1));
        test::perturb(m, 0.1, 8);
        const Scalar mu = 2.5;
        const SoftVertexTerm term(m.vertex_count(), vertices, mu, targets, weights);
        CHECK(term.has_weights());
        std::vector<Scalar> rhs(m.positions.size(), 0), diagonal(m.vertex_count(), 0);
        term.add_rhs(m.positions, test::all_indices(m.vertex_count()), rhs);
        test::check_rhs_is_half_negative_gradient(
            [&](std::span<const Scalar> x) { return term.energy(x); }, m.positions, rhs);
        term.add_diagonal(diagonal);
        Scalar expected = 0;
        for (size_t k = 0; k < vertices.size(); ++k)
        {
            const Index i = vertices[k];
            CHECK(diagonal[i] == mu * weights[k]);
            for (int a = 0; a < 3; ++a)
            {
                const Scalar d = m.positions[3 * i + a] - targets[3 * k + a];
                expected += mu * weights[k] * d * d;
                CHECK(rhs[3 * i + a] == mu * weights[k] * -d);
            }
        }
        CHECK(term.energy(m.positions) == doctest::Approx(expected).epsilon(1e-14));
        std::vector<Scalar> share(m.vertex_count(), 0);
        term.add_vertex_energy(m.positions, share);
        CHECK(share[4] == 0.0); // weight 0: no energy
        CHECK(term.quadratic(m.positions) ==
              doctest::Approx(
                  SoftVertexTerm(m.vertex_count(), vertices, mu, {}, weights).energy(m.positions))
                  .epsilon(1e-14));
    }

    TEST_CASE("weights of 1 are the single mu, bit for bit, except the energy's summation order")
    {
        Mesh m = test::icosphere(1);
        test::perturb(m, 0.1, 3);
        const std::vector<Index> vertices{1, 2, 7};
        const std::vector<Scalar> ones(vertices.size(), 1.0);
        const SoftVertexTerm plain(m.vertex_count(), vertices, 0.7);
        const SoftVertexTerm weighted(m.vertex_count(), vertices, 0.7, {}, ones);
        std::vector<Scalar> a(m.positions.size(), 0), b(m.positions.size(), 0);
        plain.add_rhs(m.positions, vertices, a);
        weighted.add_rhs(m.positions, vertices, b);
        CHECK(a == b);
        CHECK(weighted.energy(m.positions) ==
              doctest::Approx(plain.energy(m.positions)).epsilon(1e-15));
    }
}

TEST_SUITE("SoftVertexTerm")
{
    TEST_CASE(
        "targets viewed from positions: the same bits as copied ones, copied before a "
        "change")
    {
        Mesh m = test::icosphere(1);
        const std::vector<Scalar> x0 = m.positions;
        const std::vector<Index> vertices{1, 4, 9, 30, 41};
        const std::vector<Scalar> weights{1.0, 0.5, 2.0, 0.0, 3.0};
        for (const bool weighted : {false, true})
        {
            const std::span<const Scalar> w =
                weighted ? std::span<const Scalar>(weights) : std::span<const Scalar>{};
            SoftVertexTerm copied(m.vertex_count(), vertices, 0.7, {}, w);
            copied.set_targets_at(x0);
            SoftVertexTerm viewed(m.vertex_count(), vertices, 0.7, {}, w);
            viewed.view_targets(x0);
            Mesh moved = m;
            test::perturb(moved, 0.1, 5);
            CHECK(viewed.energy(moved.positions) == copied.energy(moved.positions));
            const std::vector<Index> all = test::all_indices(m.vertex_count());
            std::vector<Scalar> a(x0.size(), 0), b(x0.size(), 0);
            copied.add_rhs(moved.positions, all, a);
            viewed.add_rhs(moved.positions, all, b);
            CHECK(a == b);
            CHECK(viewed.energy(x0) == 0);

            // set_targets writes the term's own copy, never the viewed positions.
            const std::vector<Scalar> elsewhere(3 * vertices.size(), 0.25);
            viewed.set_targets(elsewhere);
            copied.set_targets(elsewhere);
            CHECK(x0 == m.positions);
            CHECK(viewed.energy(moved.positions) == copied.energy(moved.positions));
            CHECK(viewed.energy(x0) > 0);
        }
    }
}
