// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// The terms behind one interface: what every solver reads from a term (its energy, r,
// its Jacobi diagonal, its Hessian columns, its per-vertex shares) checked through
// PositionTerm alone, for every term a recipe can hold, on tiny meshes of every kind.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/geometry/face_geometry.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/recipe/term_set.h"
#include "tests/energy_checks.h"
#include "tests/helpers.h"

namespace meshfair {
namespace {

// Every position term, with weights of its own where a term takes them; the exact
// centroid denominator, whose Jacobi diagonal is the Hessian's.
Recipe every_term(const Mesh& mesh)
{
    std::string weights;
    for (Index v = 0; v < mesh.vertex_count(); ++v)
        weights += (v ? ", " : "") + std::to_string(0.5 + 0.25 * static_cast<double>(v % 3));
    return parse_recipe(R"({"soft": {"vertices": "all", "mu": 0.3, "weights": [)" + weights +
                            R"(]}, "centroid": {"faces": "all", "mu": 1.5, "denominator": "exact"},
                            "normal": {"faces": "all", "mu": 2, "normals": "initial"},
                            "bending": {"mu": 0.7, "membrane": 0.5}})",
                        "every.json");
}

std::vector<Scalar> random_vector(size_t n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<Scalar> normal(0, 1);
    std::vector<Scalar> v(n);
    for (Scalar& x : v)
        x = normal(rng);
    return v;
}

struct Built
{
    Mesh mesh;
    Recipe recipe;
    Topology topology;
    std::unique_ptr<TermSet> terms;
};

Built build(Mesh mesh)
{
    Built b{std::move(mesh), {}, {}, nullptr};
    test::perturb(b.mesh, 0.1, 11);
    b.recipe = every_term(b.mesh);
    check_recipe(b.recipe, b.mesh);
    b.topology = build_topology(b.mesh, required_topology(b.recipe));
    const FixedVertices fixed = fixed_vertices(b.recipe, b.mesh);
    b.terms = std::make_unique<TermSet>(b.mesh, b.topology, b.recipe, fixed.fixed, fixed.hard,
                                        std::span<const Index>{}, std::span<const Scalar>{},
                                        bounding_box(b.mesh.positions).centre());
    return b;
}

TEST_SUITE("core")
{
    TEST_CASE("a recipe's terms are registered once each, in the order every sum takes")
    {
        const Built b = build(test::quad_cube());
        std::vector<EnergyTerm> order;
        for (const PositionTerm* t : b.terms->position_terms())
            order.push_back(t->kind());
        CHECK(order == std::vector<EnergyTerm>{EnergyTerm::Edge, EnergyTerm::Bending,
                                               EnergyTerm::Soft, EnergyTerm::Centroid,
                                               EnergyTerm::Normal});
        // Plain smoothing: the edge term alone.
        const Recipe plain = parse_recipe("{}", "plain.json");
        const FixedVertices fixed = fixed_vertices(plain, b.mesh);
        const TermSet edge_only(b.mesh, b.topology, plain, fixed.fixed, fixed.hard, {}, {},
                                bounding_box(b.mesh.positions).centre());
        REQUIRE(edge_only.position_terms().size() == 1);
        CHECK(edge_only.position_terms()[0]->kind() == EnergyTerm::Edge);
    }

    TEST_CASE(
        "through PositionTerm alone, each term's r is -1/2 its gradient, its Hessian "
        "columns give its quadratic part, its diagonal is the Hessian's, and its "
        "shares sum to its energy")
    {
        for (const auto& [label, mesh] : test::small_mesh_kinds())
        {
            const std::string name = label; // (CAPTURE's lambda cannot take a binding)
            CAPTURE(name);
            Built b = build(mesh);
            const std::vector<Scalar> x = b.mesh.positions;
            const Index nv = b.mesh.vertex_count();
            const std::vector<Index> all = test::all_indices(nv);
            b.terms->set_free(all);
            const std::vector<Scalar> dx = random_vector(x.size(), 5);
            for (const PositionTerm* term : b.terms->position_terms())
            {
                CAPTURE(static_cast<int>(term->kind()));
                const Scalar e = term->energy(x);
                // r = -1/2 dE/dx (the bending term's free vertices were given to set_free)
                std::vector<Scalar> rhs(x.size(), 0);
                term->add_rhs(x, all, rhs);
                test::check_rhs_is_half_negative_gradient(
                    [&](std::span<const Scalar> y) { return term->energy(y); }, x, rhs);
                // The half Hessian: dx^T A dx is the quadratic part, exactly (E quadratic).
                const SymmetricMatrix a = assemble_free_hessian(
                    nv, all, true,
                    [&](Index i, HessianColumn& c) { term->add_hessian_column(i, c); });
                std::vector<Scalar> adx(x.size(), 0);
                a.multiply(dx, adx);
                Scalar dx_a_dx = 0, r_dx = 0;
                for (size_t k = 0; k < x.size(); ++k)
                {
                    dx_a_dx += dx[k] * adx[k];
                    r_dx += rhs[k] * dx[k];
                }
                std::vector<Scalar> moved = x;
                for (size_t k = 0; k < x.size(); ++k)
                    moved[k] += dx[k];
                const Scalar scale = 1 + std::abs(e) + std::abs(dx_a_dx);
                CHECK(term->quadratic(dx) == doctest::Approx(dx_a_dx).epsilon(1e-10).scale(scale));
                CHECK(term->energy(moved) ==
                      doctest::Approx(e - 2 * r_dx + dx_a_dx).epsilon(1e-10).scale(scale));
                // The Jacobi diagonal: the Hessian's isotropic diagonal (the normal term's
                // part is its 3x3 block, none of it scalar).
                std::vector<Scalar> diagonal(nv, 0);
                term->add_diagonal(diagonal);
                for (Index i = 0; i < nv; ++i)
                {
                    std::vector<Scalar> unit(x.size(), 0), column(x.size(), 0);
                    unit[3 * static_cast<size_t>(i)] = 1;
                    a.multiply(unit, column);
                    const Scalar hessian = column[3 * static_cast<size_t>(i)];
                    if (term->kind() == EnergyTerm::Normal)
                        CHECK(diagonal[i] == 0);
                    else
                        CHECK(diagonal[i] == doctest::Approx(hessian).epsilon(1e-12));
                }
                // The per-vertex shares sum to the energy.
                std::vector<Scalar> shares(nv, 0);
                term->add_vertex_energy(x, shares);
                Scalar sum = 0;
                for (const Scalar s : shares)
                    sum += s;
                CHECK(sum == doctest::Approx(e).epsilon(1e-12).scale(1 + e));
            }
        }
    }

    TEST_CASE(
        "each term's held energy is none of it with every vertex free, all of it with none, "
        "does not change as the free vertices move, and grows as vertices are held")
    {
        for (const auto& [label, mesh] : test::small_mesh_kinds())
        {
            const std::string name = label; // (CAPTURE's lambda cannot take a binding)
            CAPTURE(name);
            Built b = build(mesh);
            // Away from the targets, so that every term has energy.
            std::vector<Scalar> x = b.mesh.positions;
            const std::vector<Scalar> away = random_vector(x.size(), 3);
            for (size_t k = 0; k < x.size(); ++k)
                x[k] += 0.2 * away[k];
            const Index nv = b.mesh.vertex_count();
            std::vector<char> all_free(nv, 1), none_free(nv, 0), some_free(nv, 0), fewer_free(nv);
            std::mt19937 rng(5);
            for (Index i = 0; i < nv; ++i)
                some_free[i] = static_cast<char>(rng() % 2);
            for (Index i = 0; i < nv; ++i)
                fewer_free[i] = static_cast<char>(some_free[i] && rng() % 2);
            // The free vertices moved, the others kept.
            std::vector<Scalar> moved = x;
            const std::vector<Scalar> dx = random_vector(x.size(), 17);
            for (Index i = 0; i < nv; ++i)
                if (some_free[i])
                    for (int a = 0; a < 3; ++a)
                        moved[3 * i + a] += 0.3 * dx[3 * i + a];
            for (const PositionTerm* term : b.terms->position_terms())
            {
                CAPTURE(static_cast<int>(term->kind()));
                const Scalar e = term->energy(x);
                REQUIRE(e > 0);
                CHECK(term->held_energy(x, all_free) == 0);
                CHECK(term->held_energy(x, none_free) == doctest::Approx(e).epsilon(1e-12));
                const Scalar held = term->held_energy(x, some_free);
                CHECK(term->held_energy(moved, some_free) == held);
                CHECK(term->held_energy(x, fewer_free) >= held);
                // Held elements give all their shares to held vertices.
                std::vector<Scalar> shares(nv, 0);
                term->add_vertex_energy(x, shares);
                Scalar held_shares = 0;
                for (Index i = 0; i < nv; ++i)
                    if (!some_free[i])
                        held_shares += shares[i];
                CHECK(held <= held_shares * (1 + 1e-12) + 1e-15);
                // What moves changes with the free vertices, unless nothing of it is free.
                if (held < e * (1 - 1e-9))
                    CHECK(term->energy(moved) - held != doctest::Approx(e - held));
            }
            // The set's held energy is its terms', by kind.
            const TermEnergies set = b.terms->held_energy(x, some_free);
            for (const PositionTerm* term : b.terms->position_terms())
                CHECK(TermEnergies(set).at(term->kind()) == term->held_energy(x, some_free));
        }
    }

    TEST_CASE(
        "the set's energy, r and Hessian are the sums of its terms', and a session "
        "reads the same energy")
    {
        for (const auto& [label, mesh] : test::small_mesh_kinds())
        {
            const std::string name = label; // (CAPTURE's lambda cannot take a binding)
            CAPTURE(name);
            Built b = build(mesh);
            const std::vector<Scalar>& x = b.mesh.positions;
            const Index nv = b.mesh.vertex_count();
            const std::vector<Index> all = test::all_indices(nv);
            b.terms->set_free(all);
            TermEnergies e = b.terms->energy(x);
            std::vector<Scalar> sum_rhs(x.size(), 0), set_rhs(x.size(), 0);
            Scalar sum_energy = 0;
            for (const PositionTerm* term : b.terms->position_terms())
            {
                sum_energy += term->energy(x);
                CHECK(e.at(term->kind()) == term->energy(x));
                term->add_rhs(x, all, sum_rhs);
            }
            CHECK(e.total() == doctest::Approx(sum_energy).epsilon(1e-14));
            b.terms->add_rhs(x, all, set_rhs);
            CHECK(set_rhs == sum_rhs);
            std::vector<Scalar> total_shares(nv, 0);
            b.terms->vertex_energy(x, EnergyTerm::Total, total_shares);
            Scalar share_sum = 0;
            for (const Scalar s : total_shares)
                share_sum += s;
            CHECK(share_sum == doctest::Approx(e.total()).epsilon(1e-12));

            const Session session(b.mesh, b.topology, b.recipe);
            const TermEnergies s = session.energy(x);
            CHECK(s.total() == e.total());
            CHECK(s.bending == e.bending);
            CHECK(s.normal == e.normal);
        }
    }
}

} // namespace
} // namespace meshfair
