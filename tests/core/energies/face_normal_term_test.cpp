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

    TEST_CASE("on triangles the faces' shares and the block give each corner's part")
    {
        // add_vertex_rhs sums u u^T ((x_prev - x_i) + (x_next - x_i)) corner by corner;
        // the fused step sums face_share's g_f over i's corners and takes -(3/2) B_i
        // (x_i - c) through the solve. Both, for every vertex, weighted or not, on a mesh
        // far from the origin (c keeps the sums the size of the mesh).
        Mesh m = test::icosphere(2);
        for (size_t k = 0; k < m.positions.size(); k += 3)
            m.positions[k] += 3e4;
        const std::vector<Scalar> normals = face_normals(m, m.positions);
        test::perturb(m, 0.05, 21);
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count(), nf = m.face_count();
        std::vector<Index> faces;
        std::vector<Scalar> weights;
        for (Index f = 0; f < nf; f += 3)
        {
            faces.push_back(f);
            weights.push_back(0.5 + (f % 7) * 0.25);
        }
        for (const bool weighted : {false, true})
        {
            CAPTURE(weighted);
            const FaceNormalTerm term(
                m, t, faces, 1.7,
                weighted ? std::span<const Scalar>(weights) : std::span<const Scalar>());
            REQUIRE(term.triangles());
            std::vector<Scalar> share(3 * static_cast<size_t>(nf), -1);
            term.face_shares<false>(m.positions.data(), normals.data(), faces.data(), 0,
                                    static_cast<Index>(faces.size()), share.data(), false, nullptr);
            std::vector<Scalar> block(6 * static_cast<size_t>(nv), 0);
            term.add_block(normals, test::all_indices(nv), block);
            const Vec3 c = term.centre();
            Scalar largest = 0;
            for (Index i = 0; i < nv; ++i)
            {
                Scalar direct[3] = {0, 0, 0}, shared[3] = {0, 0, 0};
                term.add_vertex_rhs(i, m.positions.data(), normals.data(), direct);
                add_corner_shares(t, CornerWalk(m, t), term.flags(), share.data(), i, shared);
                const Scalar* B = &block[6 * i];
                const Scalar e[3] = {m.positions[3 * i] - c[0], m.positions[3 * i + 1] - c[1],
                                     m.positions[3 * i + 2] - c[2]};
                const Scalar Be[3] = {B[0] * e[0] + B[1] * e[1] + B[2] * e[2],
                                      B[1] * e[0] + B[3] * e[1] + B[4] * e[2],
                                      B[2] * e[0] + B[4] * e[1] + B[5] * e[2]};
                for (int a = 0; a < 3; ++a)
                    largest = std::max(largest, std::abs(shared[a] - 1.5 * Be[a] - direct[a]));
            }
            // Against the parts' own size (the mesh is 2 across, 3e4 from the origin).
            CHECK(largest <= 1e-12);
            // Written where listed, left alone elsewhere.
            CHECK(share[3] == -1); // face 1 is not listed
        }
    }

    TEST_CASE("the 3x3 inverse, and the solve without the block's part")
    {
        // (d I + B) dx = r - (3/2) B e, solved from the factor of d I + B alone.
        const Scalar d = 6.25;
        const Scalar B[6] = {2.0, 0.3, -0.4, 1.5, 0.2, 0.9}; // xx xy xz yy yz zz, SPD
        const Scalar e[3] = {0.7, -1.3, 0.4}, r0[3] = {0.05, -0.02, 0.11};
        Scalar inverse[6];
        REQUIRE(spd_inverse3(d, B, inverse));
        Scalar r[3] = {r0[0], r0[1], r0[2]}, dx[3];
        solve_less_block(inverse, d, e, r, dx);
        Eigen::Matrix3d A;
        A << d + B[0], B[1], B[2], B[1], d + B[3], B[4], B[2], B[4], d + B[5];
        const Eigen::Vector3d E(e[0], e[1], e[2]), R(r0[0], r0[1], r0[2]);
        const Eigen::Vector3d Bm = (A - d * Eigen::Matrix3d::Identity()) * E;
        const Eigen::Vector3d want = A.ldlt().solve(R - 1.5 * Bm);
        for (int a = 0; a < 3; ++a)
            CHECK(dx[a] == doctest::Approx(want[a]).epsilon(1e-14).scale(1));
        // The inverse times A is I; a matrix that is not positive definite is refused.
        const Eigen::Matrix3d Ainv{{inverse[0], inverse[1], inverse[2]},
                                   {inverse[1], inverse[3], inverse[4]},
                                   {inverse[2], inverse[4], inverse[5]}};
        CHECK((Ainv * A - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-15);
        const Scalar indefinite[6] = {-9.0, 0.0, 0.0, 1.0, 0.0, 1.0};
        CHECK_FALSE(spd_inverse3(d, indefinite, inverse));
    }
}
