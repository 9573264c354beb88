// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/joint_term.h"

#include <doctest/doctest.h>

#include "core/geometry/face_geometry.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

struct JointFixture
{
    Mesh mesh;
    Topology topology;
    std::vector<Scalar> u;
    std::vector<Index> faces;
    std::vector<Index> soft_faces{2, 4};
    std::vector<Scalar> soft_normal{0.0, 0.6, 0.8, 0.6, 0.0, 0.8};
    FaceNormalTerm normal_term;
    NormalSmoothingTerm smoothing;
    JointTerm joint;

    //! Without weights, or with a weight per face of both the normal term and the soft
    //! normals (so mu_f and mu_S,f differ from face to face).
    explicit JointFixture(Mesh m, bool weighted = false)
        : mesh(std::move(m)),
          topology(build_topology(mesh)),
          u(face_normals(mesh, mesh.positions)),
          faces(test::all_indices(mesh.face_count())),
          normal_term(mesh, topology, faces, 1.5,
                      weighted ? face_weights() : std::vector<Scalar>{}),
          smoothing(topology, {}, {}, soft_faces, 0.8, soft_normal,
                    weighted ? std::vector<Scalar>{2.5, 0.0} : std::vector<Scalar>{}),
          joint(normal_term, smoothing, topology, 0.7)
    {
    }

    std::vector<Scalar> face_weights() const
    {
        std::vector<Scalar> w;
        for (Index f = 0; f < mesh.face_count(); ++f)
            w.push_back(0.5 + 0.75 * (f % 3));
        return w;
    }

    Scalar energy_in_u(std::span<const Scalar> normals) const
    {
        return normal_term.energy(mesh.positions, normals) + joint.dual_energy(normals) +
               smoothing.soft_energy(normals);
    }
};

Mesh noisy_patch()
{
    Mesh m = test::mixed_polygons();
    test::perturb(m, 0.1, 31);
    return m;
}

// -1/2 dE/du_f of the joint term against central differences of E in u, every face.
void check_u_rhs_is_half_negative_gradient(const JointFixture& fx)
{
    for (Index f = 0; f < fx.mesh.face_count(); ++f)
    {
        Scalar r[3];
        fx.joint.normal_rhs(fx.mesh.positions, fx.u, f, r);
        for (int a = 0; a < 3; ++a)
        {
            std::vector<Scalar> up = fx.u, down = fx.u;
            up[3 * f + a] += 1e-5;
            down[3 * f + a] -= 1e-5;
            const Scalar g = (fx.energy_in_u(up) - fx.energy_in_u(down)) / 2e-5;
            CHECK(-0.5 * g == doctest::Approx(r[a]).epsilon(1e-6).scale(1));
        }
    }
}

// The 3x3 solution zeroes the u right-hand side of its face and lowers E, every face.
void check_minimizer_zeroes_u_rhs(const JointFixture& fx)
{
    for (Index f = 0; f < fx.mesh.face_count(); ++f)
    {
        std::vector<Scalar> u = fx.u;
        REQUIRE(fx.joint.minimizer(fx.mesh.positions, u, f, &u[3 * f]));
        Scalar r[3];
        fx.joint.normal_rhs(fx.mesh.positions, u, f, r);
        for (int a = 0; a < 3; ++a)
            CHECK(r[a] == doctest::Approx(0).epsilon(1e-12).scale(1));
        CHECK(fx.energy_in_u(u) <= fx.energy_in_u(fx.u));
    }
}

} // namespace

TEST_SUITE("JointTerm")
{
    TEST_CASE("the u right-hand side is minus half the gradient in u (central differences)")
    {
        check_u_rhs_is_half_negative_gradient(JointFixture(noisy_patch()));
    }

    TEST_CASE("the derived 3x3 update is the exact minimizer in u_f before renormalization")
    {
        check_minimizer_zeroes_u_rhs(JointFixture(noisy_patch()));
    }

    TEST_CASE("with a weight per face: the u gradient and the 3x3 update use mu_f and mu_S,f")
    {
        const JointFixture fx(noisy_patch(), true);
        check_u_rhs_is_half_negative_gradient(fx);
        check_minimizer_zeroes_u_rhs(fx);
    }

    TEST_CASE("joint smoothing of x and u lowers the total energy of a noisy mesh")
    {
        Mesh m = test::icosphere(2);
        test::perturb(m, 0.03, 5);
        const Topology t = build_topology(m);
        Recipe recipe;
        recipe.iterations = 30;
        recipe.normal = NormalConstraints{};
        recipe.normal->faces.all = true;
        recipe.normal->mu = 1.0;
        recipe.joint = Joint{2.0};
        const SmoothResult r = smooth(m, t, recipe);
        CHECK(r.energies.back().total() < 0.5 * r.energies.front().total());
        CHECK(r.energies.back().normal_smoothing < r.energies.front().normal_smoothing);
    }
}
