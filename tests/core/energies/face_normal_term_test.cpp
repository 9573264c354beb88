// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/face_normal_term.h"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include "core/energies/edge_term.h"
#include "core/geometry/face_geometry.h"
#include "core/recipe/session.h"
#include "core/solver/jacobi_system.h"
#include "tests/energy_checks.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

} // namespace

TEST_SUITE("FaceNormalTerm")
{
    TEST_CASE("right-hand side is minus half the gradient (central differences)")
    {
        Mesh m = test::mixed_polygons();
        const std::vector<Scalar> normals = face_normals(m, m.positions);
        test::perturb(m, 0.1, 12);
        const Topology t = build_topology(m);
        const std::vector<Index> faces{0, 3, 5};
        const FaceNormalTerm term(m, t, faces, 1.3);
        std::vector<Scalar> rhs(m.positions.size(), 0);
        term.add_rhs(m.positions, normals, test::all_indices(m.vertex_count()), rhs);
        test::check_rhs_is_half_negative_gradient(
            [&](std::span<const Scalar> x) { return term.energy(x, normals); }, m.positions, rhs);
    }

    TEST_CASE("satisfied on a planar face with its own normal")
    {
        const Mesh m = test::open_grid(3, 3);
        const Topology t = build_topology(m);
        const FaceNormalTerm term(m, t, test::all_indices(m.face_count()), 5.0);
        CHECK(term.energy(m.positions, face_normals(m, m.positions)) == 0.0);
    }

    TEST_CASE("one vertex's 3x3 solve zeroes its partial gradient")
    {
        Mesh m = test::mixed_polygons();
        const std::vector<Scalar> normals = face_normals(m, m.positions);
        test::perturb(m, 0.15, 13);
        const Topology t = build_topology(m);
        const EdgeTerm edge(t);
        const FaceNormalTerm term(m, t, test::all_indices(m.face_count()), 4.0);
        const Index i = 5; // corner of a pentagon: V(f, i) must be its two boundary neighbours
        const std::vector<Index> one{i};
        std::vector<Scalar> diagonal(m.vertex_count(), 0), block(6 * m.vertex_count(), 0),
            rhs(m.positions.size(), 0);
        edge.add_diagonal(diagonal);
        term.add_block(normals, one, block);
        edge.add_rhs(m.positions, one, rhs);
        term.add_rhs(m.positions, normals, one, rhs);
        Scalar L[6] = {}, dx[3] = {};
        REQUIRE(cholesky3(diagonal[i], &block[6 * i], L));
        cholesky3_solve(L, &rhs[3 * i], dx);
        for (int a = 0; a < 3; ++a)
            m.positions[3 * i + a] += dx[a];
        std::vector<Scalar> after(m.positions.size(), 0);
        edge.add_rhs(m.positions, one, after);
        term.add_rhs(m.positions, normals, one, after);
        for (int a = 0; a < 3; ++a)
            CHECK(after[3 * i + a] == doctest::Approx(0).epsilon(1e-12).scale(1));
    }

    TEST_CASE("the step is the paper's equation solved by a dense 3x3 inverse")
    {
        // (n_i I + mu sum_f sum_{j in V(f,i)} u_f u_f^T) dx_i
        //     = sum_j (x_j - x_i) + mu sum_f sum_{j in V(f,i)} u_f u_f^T (x_j - x_i)
        Mesh m = test::mixed_polygons();
        test::perturb(m, 0.1, 21);
        const Topology t = build_topology(m);
        const std::vector<Scalar> u = face_normals(m, m.positions);
        const Scalar mu = 2.0;
        Recipe recipe;
        recipe.iterations = 1;
        recipe.lambda = 1.0;
        recipe.normal = NormalConstraints{};
        recipe.normal->faces.all = true;
        recipe.normal->mu = mu;
        const Mesh before = m;
        smooth(m, t, recipe);
        for (Index i = 0; i < m.vertex_count(); ++i)
        {
            Eigen::Matrix3d A = t.valence(i) * Eigen::Matrix3d::Identity();
            Eigen::Vector3d b = Eigen::Vector3d::Zero();
            const Eigen::Vector3d xi(&before.positions[3 * i]);
            for (const Index j : t.neighbors(i))
                b += Eigen::Vector3d(&before.positions[3 * j]) - xi;
            for (Index f = 0; f < m.face_count(); ++f)
            {
                const auto face = m.face(f);
                for (size_t k = 0; k < face.size(); ++k)
                {
                    if (face[k] != i)
                        continue;
                    const Eigen::Vector3d uf(&u[3 * f]);
                    const Eigen::Matrix3d P = uf * uf.transpose();
                    for (const Index j :
                         {face[(k + 1) % face.size()], face[(k + face.size() - 1) % face.size()]})
                    {
                        A += mu * P;
                        b += mu * P * (Eigen::Vector3d(&before.positions[3 * j]) - xi);
                    }
                }
            }
            const Eigen::Vector3d expected = xi + A.inverse() * b;
            for (int a = 0; a < 3; ++a)
                CHECK(m.positions[3 * i + a] == doctest::Approx(expected[a]).epsilon(1e-12));
        }
    }

    TEST_CASE("with a weight per face: gradient, 3x3 block and the one-vertex minimizer")
    {
        Mesh m = test::mixed_polygons();
        const std::vector<Scalar> normals = face_normals(m, m.positions);
        test::perturb(m, 0.15, 13);
        const Topology t = build_topology(m);
        const std::vector<Index> faces = test::all_indices(m.face_count());
        std::vector<Scalar> weights;
        for (size_t k = 0; k < faces.size(); ++k)
            weights.push_back(static_cast<Scalar>((3 * k) % 5)); // 0, 3, 1, 4, 2, ...
        const Scalar mu = 1.3;
        const FaceNormalTerm term(m, t, faces, mu, weights);
        std::vector<Scalar> rhs(m.positions.size(), 0);
        term.add_rhs(m.positions, normals, test::all_indices(m.vertex_count()), rhs);
        test::check_rhs_is_half_negative_gradient(
            [&](std::span<const Scalar> x) { return term.energy(x, normals); }, m.positions, rhs);
        // Each face's part is that of a face alone with mu_f as its mu.
        for (Index f = 0; f < m.face_count(); ++f)
        {
            const FaceNormalTerm one_face(m, t, {f}, mu * weights[f]);
            const FaceNormalTerm one_weighted(m, t, {f}, mu, std::vector<Scalar>{weights[f]});
            CHECK(one_weighted.energy(m.positions, normals) ==
                  doctest::Approx(one_face.energy(m.positions, normals)).epsilon(1e-15));
        }
        // The weighted 3x3 solve zeroes the vertex's partial gradient.
        const EdgeTerm edge(t);
        const Index i = 5;
        const std::vector<Index> one{i};
        std::vector<Scalar> diagonal(m.vertex_count(), 0), block(6 * m.vertex_count(), 0),
            r(m.positions.size(), 0);
        edge.add_diagonal(diagonal);
        term.add_block(normals, one, block);
        edge.add_rhs(m.positions, one, r);
        term.add_rhs(m.positions, normals, one, r);
        Scalar L[6] = {}, dx[3] = {};
        REQUIRE(cholesky3(diagonal[i], &block[6 * i], L));
        cholesky3_solve(L, &r[3 * i], dx);
        for (int a = 0; a < 3; ++a)
            m.positions[3 * i + a] += dx[a];
        std::vector<Scalar> after(m.positions.size(), 0);
        edge.add_rhs(m.positions, one, after);
        term.add_rhs(m.positions, normals, one, after);
        for (int a = 0; a < 3; ++a)
            CHECK(after[3 * i + a] == doctest::Approx(0).epsilon(1e-12).scale(1));
    }
}
