// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/edge_term.h"

#include <doctest/doctest.h>

#include <cstring>

#include "core/recipe/session.h"
#include "tests/energy_checks.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

// The paper's three-step algorithm, written from its text: zero the displacements and
// counts, traverse the array of edges adding x_j - x_i to dx_i and x_i - x_j to dx_j,
// then divide by n_i where n_i != 0; finally x'_i = x_i + lambda dx_i.
std::vector<Scalar> paper_laplacian_step(const Mesh& m, const Topology& t, Scalar lambda)
{
    const Index nv = m.vertex_count();
    std::vector<Scalar> dx(3 * nv, 0), n(nv, 0);
    for (Index e = 0; e < t.edge_count(); ++e)
    {
        const Index i = t.edge_vertices[2 * e], j = t.edge_vertices[2 * e + 1];
        for (int a = 0; a < 3; ++a)
        {
            dx[3 * i + a] += m.positions[3 * j + a] - m.positions[3 * i + a];
            dx[3 * j + a] += m.positions[3 * i + a] - m.positions[3 * j + a];
        }
        n[i] += 1;
        n[j] += 1;
    }
    std::vector<Scalar> x = m.positions;
    for (Index i = 0; i < nv; ++i)
        if (n[i] != 0)
            for (int a = 0; a < 3; ++a)
                x[3 * i + a] += lambda * dx[3 * i + a] / n[i];
    return x;
}

} // namespace

TEST_SUITE("EdgeTerm")
{
    TEST_CASE("right-hand side is minus half the gradient (central differences)")
    {
        Mesh m = test::mixed_polygons();
        test::perturb(m, 0.1, 3);
        const Topology t = build_topology(m);
        const EdgeTerm term(t);
        std::vector<Scalar> rhs(m.positions.size(), 0);
        term.add_rhs(m.positions, test::all_indices(m.vertex_count()), rhs);
        test::check_rhs_is_half_negative_gradient(
            [&](std::span<const Scalar> x) { return term.energy(x); }, m.positions, rhs);
    }

    TEST_CASE("the Jacobi step is the paper's Laplacian smoothing")
    {
        for (Mesh m : {test::icosphere(2), test::mixed_polygons(), test::nonmanifold_fan(),
                       test::with_isolated_vertex()})
        {
            test::perturb(m, 0.05, 11);
            const Topology t = build_topology(m);
            const std::vector<Scalar> expected = paper_laplacian_step(m, t, 0.5);
            Recipe recipe;
            recipe.iterations = 1;
            smooth(m, t, recipe);
            for (size_t k = 0; k < expected.size(); ++k)
                CHECK(m.positions[k] == doctest::Approx(expected[k]).epsilon(1e-13));
        }
    }

    TEST_CASE("one vertex's Jacobi displacement zeroes its partial gradient")
    {
        Mesh m = test::icosphere(1);
        test::perturb(m, 0.1, 5);
        const Topology t = build_topology(m);
        const EdgeTerm term(t);
        std::vector<Scalar> diagonal(m.vertex_count(), 0), rhs(m.positions.size(), 0);
        term.add_diagonal(diagonal);
        const std::vector<Index> one{17};
        term.add_rhs(m.positions, one, rhs);
        for (int a = 0; a < 3; ++a)
            m.positions[3 * 17 + a] += rhs[3 * 17 + a] / diagonal[17];
        std::vector<Scalar> after(m.positions.size(), 0);
        term.add_rhs(m.positions, one, after);
        for (int a = 0; a < 3; ++a)
            CHECK(after[3 * 17 + a] == doctest::Approx(0).epsilon(1e-12).scale(1));
    }

    TEST_CASE("vertices with no neighbours do not move")
    {
        Mesh m = test::with_isolated_vertex();
        const Topology t = build_topology(m);
        const Vec3 before = m.position(3);
        Recipe recipe;
        recipe.iterations = 5;
        smooth(m, t, recipe);
        CHECK(std::memcmp(&m.positions[9], before.data(), sizeof before) == 0);
    }

    TEST_CASE("the energy is the sum of squared edge lengths, each edge once")
    {
        const Mesh m = test::quad_cube();
        const Topology t = build_topology(m);
        CHECK(EdgeTerm(t).energy(m.positions) == 12.0);
    }
}
