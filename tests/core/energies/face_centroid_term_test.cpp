// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/face_centroid_term.h"

#include <doctest/doctest.h>

#include "core/energies/edge_term.h"
#include "core/geometry/face_geometry.h"
#include "core/recipe/session.h"
#include "tests/energy_checks.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

std::vector<Scalar> centroids(const Mesh& m, std::span<const Index> faces)
{
    std::vector<Scalar> c;
    for (const Index f : faces)
    {
        const Vec3 p = face_centroid(m, m.positions, f);
        c.insert(c.end(), p.begin(), p.end());
    }
    return c;
}

// Solves vertex i's one-variable problem with the given denominator, moving only x_i;
// returns the edge + centroid right-hand side at i afterwards.
Vec3 rhs_after_single_vertex_step(Mesh m, const Topology& t, Index i,
                                  CentroidDenominator denominator)
{
    const std::vector<Index> faces = test::all_indices(m.face_count());
    const std::vector<Scalar> targets = centroids(m, faces);
    test::perturb(m, 0.2, 4);
    const EdgeTerm edge(t);
    FaceCentroidTerm term(m, t, faces, 2.0, targets, denominator);
    std::vector<Scalar> diagonal(m.vertex_count(), 0), rhs(m.positions.size(), 0);
    edge.add_diagonal(diagonal);
    term.add_diagonal(diagonal);
    const std::vector<Index> one{i};
    edge.add_rhs(m.positions, one, rhs);
    term.add_rhs(m.positions, one, rhs);
    const Vec3 before{rhs[3 * i], rhs[3 * i + 1], rhs[3 * i + 2]};
    for (int a = 0; a < 3; ++a)
        m.positions[3 * i + a] += rhs[3 * i + a] / diagonal[i];
    std::fill(rhs.begin(), rhs.end(), 0);
    edge.add_rhs(m.positions, one, rhs);
    term.add_rhs(m.positions, one, rhs);
    // Report the residual relative to the residual before the step.
    return {rhs[3 * i] / before[0], rhs[3 * i + 1] / before[1], rhs[3 * i + 2] / before[2]};
}

} // namespace

TEST_SUITE("FaceCentroidTerm")
{
    TEST_CASE("right-hand side is minus half the gradient (central differences)")
    {
        Mesh m = test::mixed_polygons();
        const std::vector<Index> faces{0, 2, 5, 6};
        const std::vector<Scalar> targets = centroids(m, faces);
        test::perturb(m, 0.1, 9);
        const Topology t = build_topology(m);
        for (const auto d : {CentroidDenominator::Paper, CentroidDenominator::Exact})
        {
            FaceCentroidTerm term(m, t, faces, 1.7, targets, d);
            std::vector<Scalar> rhs(m.positions.size(), 0);
            term.add_rhs(m.positions, test::all_indices(m.vertex_count()), rhs);
            test::check_rhs_is_half_negative_gradient(
                [&](std::span<const Scalar> x) { return term.energy(x); }, m.positions, rhs);
        }
    }

    TEST_CASE("the exact denominator zeroes the vertex's partial gradient")
    {
        const Mesh m = test::mixed_polygons();
        const Topology t = build_topology(m);
        const Vec3 r = rhs_after_single_vertex_step(m, t, 5, CentroidDenominator::Exact);
        for (int a = 0; a < 3; ++a)
            CHECK(r[a] == doctest::Approx(0).epsilon(1e-10).scale(1));
    }

    TEST_CASE("the printed denominator takes a shorter step in the same direction")
    {
        // r after = r before (1 - D_exact / D_paper): same sign, strictly smaller.
        const Mesh m = test::mixed_polygons();
        const Topology t = build_topology(m);
        const Index i = 5; // in two quads and the pentagon
        Scalar exact = t.valence(i), paper = t.valence(i);
        for (const Index c : t.corners_of_vertex(i))
        {
            const Scalar n = m.face_size(t.face_of_corner(c));
            exact += 2.0 / (n * n);
            paper += 2.0 / n;
        }
        const Vec3 r = rhs_after_single_vertex_step(m, t, i, CentroidDenominator::Paper);
        for (int a = 0; a < 3; ++a)
        {
            CHECK(r[a] > 0);
            CHECK(r[a] == doctest::Approx(1 - exact / paper).epsilon(1e-9));
        }
    }

    TEST_CASE("with the edge term the step is the paper's printed formula")
    {
        Mesh m = test::mixed_polygons();
        test::perturb(m, 0.1, 6);
        const Topology t = build_topology(m);
        Recipe recipe;
        recipe.iterations = 1;
        recipe.lambda = 1.0;
        recipe.centroid = CentroidConstraints{};
        recipe.centroid->faces.all = true;
        recipe.centroid->mu = 3.0;
        // Targets: the unperturbed centroids shifted, so x0_f - x_f is not small.
        for (Index f = 0; f < m.face_count(); ++f)
        {
            Vec3 c = face_centroid(m, m.positions, f);
            c[2] += 0.25;
            recipe.centroid->targets.push_back(c);
        }
        const Mesh before = m;
        smooth(m, t, recipe);
        for (Index i = 0; i < m.vertex_count(); ++i)
        {
            Scalar denominator = t.valence(i);
            Vec3 sum{0, 0, 0};
            for (const Index j : t.neighbors(i))
                for (int a = 0; a < 3; ++a)
                    sum[a] += before.positions[3 * j + a] - before.positions[3 * i + a];
            for (const Index c : t.corners_of_vertex(i))
            {
                const Index f = t.face_of_corner(c);
                const Scalar n = m.face_size(f);
                denominator += 3.0 / n;
                const Vec3 xf = face_centroid(before, before.positions, f);
                for (int a = 0; a < 3; ++a)
                    sum[a] += 3.0 / n * (recipe.centroid->targets[f][a] - xf[a]);
            }
            for (int a = 0; a < 3; ++a)
                CHECK(m.positions[3 * i + a] ==
                      doctest::Approx(before.positions[3 * i + a] + sum[a] / denominator)
                          .epsilon(1e-13));
        }
    }

    TEST_CASE("the printed denominator is safe where the exact one overshoots")
    {
        // Quads with a heavy centroid weight: the exact Jacobi step's spectral radius
        // approaches n_f = 4, so lambda = 0.9 raises the energy; the printed one stays
        // below 2 and decreases it (docs/math.md).
        Mesh m = test::quad_torus(12, 8, 2, 0.7);
        const Topology t = build_topology(m);
        Recipe recipe;
        recipe.iterations = 1;
        recipe.lambda = 0.9;
        recipe.centroid = CentroidConstraints{};
        recipe.centroid->faces.all = true;
        recipe.centroid->mu = 1000;
        for (Index f = 0; f < m.face_count(); ++f)
            recipe.centroid->targets.push_back(face_centroid(m, m.positions, f));
        test::perturb(m, 0.05, 1);
        for (const auto d : {CentroidDenominator::Paper, CentroidDenominator::Exact})
        {
            recipe.centroid->denominator = d;
            Mesh copy = m;
            recipe.iterations = 5;
            const SmoothResult r = smooth(copy, t, recipe);
            const Scalar before = r.energies.front().total(), after = r.energies.back().total();
            if (d == CentroidDenominator::Paper)
                CHECK(after < before);
            else
                CHECK(after > before);
        }
    }

    TEST_CASE("with a weight per face: gradient, both denominators and the one-vertex minimizer")
    {
        Mesh m = test::mixed_polygons();
        const std::vector<Index> faces = test::all_indices(m.face_count());
        std::vector<Scalar> weights;
        for (size_t k = 0; k < faces.size(); ++k)
            weights.push_back(0.25 + 0.5 * static_cast<Scalar>(k % 4)); // 0.25 .. 1.75
        weights[1] = 0;                                                 // a weight of 0 is allowed
        const std::vector<Scalar> targets = centroids(m, faces);
        test::perturb(m, 0.1, 9);
        const Topology t = build_topology(m);
        const Scalar mu = 1.7;
        for (const auto d : {CentroidDenominator::Paper, CentroidDenominator::Exact})
        {
            CAPTURE(d == CentroidDenominator::Paper);
            const FaceCentroidTerm term(m, t, faces, mu, targets, d, weights);
            std::vector<Scalar> rhs(m.positions.size(), 0), diagonal(m.vertex_count(), 0);
            term.add_rhs(m.positions, test::all_indices(m.vertex_count()), rhs);
            test::check_rhs_is_half_negative_gradient(
                [&](std::span<const Scalar> x) { return term.energy(x); }, m.positions, rhs);
            // D_i = sum_f mu_f / n_f (paper) or mu_f / n_f^2 (exact).
            term.add_diagonal(diagonal);
            for (Index i = 0; i < m.vertex_count(); ++i)
            {
                Scalar expected = 0;
                for (const Index c : t.corners_of_vertex(i))
                {
                    const Index f = t.face_of_corner(c);
                    const Scalar n = m.face_size(f);
                    expected += mu * weights[f] / (d == CentroidDenominator::Paper ? n : n * n);
                }
                CHECK(diagonal[i] == doctest::Approx(expected).epsilon(1e-14));
            }
            // The energy is sum_f mu_f |x_f - x0_f|^2.
            Scalar energy = 0;
            for (Index f = 0; f < m.face_count(); ++f)
            {
                const Vec3 c = face_centroid(m, m.positions, f);
                for (int a = 0; a < 3; ++a)
                    energy +=
                        mu * weights[f] * (c[a] - targets[3 * f + a]) * (c[a] - targets[3 * f + a]);
            }
            CHECK(term.energy(m.positions) == doctest::Approx(energy).epsilon(1e-14));
            // The fused step's per-face residuals are the general step's, bit for bit.
            std::vector<Scalar> residual(3 * m.face_count(), 0), fused(m.positions.size(), 0);
            term.face_residuals(m.positions.data(), faces.data(), 0,
                                static_cast<Index>(faces.size()), residual.data());
            for (Index i = 0; i < m.vertex_count(); ++i)
                add_corner_shares(t, CornerWalk(m, t), term.flags(), residual.data(), i,
                                  &fused[3 * i]);
            CHECK(fused == rhs);
        }
        // The exact denominator still zeroes the partial gradient of one vertex.
        const EdgeTerm edge(t);
        const FaceCentroidTerm exact(m, t, faces, mu, targets, CentroidDenominator::Exact, weights);
        const Index i = 5;
        const std::vector<Index> one{i};
        std::vector<Scalar> diagonal(m.vertex_count(), 0), rhs(m.positions.size(), 0);
        edge.add_diagonal(diagonal);
        exact.add_diagonal(diagonal);
        edge.add_rhs(m.positions, one, rhs);
        exact.add_rhs(m.positions, one, rhs);
        Mesh moved = m;
        for (int a = 0; a < 3; ++a)
            moved.positions[3 * i + a] += rhs[3 * i + a] / diagonal[i];
        std::vector<Scalar> after(m.positions.size(), 0);
        edge.add_rhs(moved.positions, one, after);
        exact.add_rhs(moved.positions, one, after);
        for (int a = 0; a < 3; ++a)
            CHECK(after[3 * i + a] == doctest::Approx(0).epsilon(1e-12).scale(1));
    }
}

TEST_SUITE("FaceCentroidTerm")
{
    TEST_CASE(
        "targets computed from the initial positions: the same bits as stored ones, "
        "stored before a change")
    {
        const Mesh m = test::mixed_polygons(); // triangles, quads and a pentagon
        const Topology t = build_topology(m);
        const std::vector<Scalar> x0 = m.positions;
        const std::vector<Index> faces = test::all_indices(m.face_count());
        std::vector<Scalar> weights(faces.size());
        for (size_t k = 0; k < weights.size(); ++k)
            weights[k] = 0.5 + 0.25 * static_cast<Scalar>(k % 3);
        Mesh moved = m;
        test::perturb(moved, 0.2, 9);
        for (const bool weighted : {false, true})
        {
            const std::span<const Scalar> w =
                weighted ? std::span<const Scalar>(weights) : std::span<const Scalar>{};
            FaceCentroidTerm stored(m, t, faces, 1.5, CentroidDenominator::Paper, w);
            stored.set_targets_to_centroids(x0);
            FaceCentroidTerm computed(m, t, faces, 1.5, CentroidDenominator::Paper, w);
            computed.use_centroids_of(x0);
            CHECK(computed.energy(moved.positions) == stored.energy(moved.positions));
            CHECK(computed.energy(x0) == 0);
            const std::vector<Index> all = test::all_indices(m.vertex_count());
            std::vector<Scalar> a(x0.size(), 0), b(x0.size(), 0);
            stored.add_rhs(moved.positions, all, a);
            computed.add_rhs(moved.positions, all, b);
            CHECK(a == b);
            std::vector<Scalar> ra(3 * faces.size(), 0), rb(3 * faces.size(), 0);
            const Scalar ea = stored.face_residuals(moved.positions.data(), faces.data(), 0,
                                                    m.face_count(), ra.data());
            const Scalar eb = computed.face_residuals(moved.positions.data(), faces.data(), 0,
                                                      m.face_count(), rb.data());
            CHECK(ea == eb);
            CHECK(ra == rb);
            std::vector<Scalar> pa(m.vertex_count(), 0), pb(m.vertex_count(), 0);
            stored.add_vertex_energy(moved.positions, pa);
            computed.add_vertex_energy(moved.positions, pb);
            CHECK(pa == pb);

            // set_targets stores targets of its own and leaves the positions alone.
            const std::vector<Scalar> elsewhere(3 * faces.size(), -0.5);
            computed.set_targets(elsewhere);
            stored.set_targets(elsewhere);
            CHECK(x0 == m.positions);
            CHECK(computed.energy(moved.positions) == stored.energy(moved.positions));
            CHECK(computed.energy(x0) > 0);
        }
    }
}
