// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/patch_guidance.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "core/energies/bilateral_face_weights.h"
#include "core/energies/normal_smoothing_term.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

Scalar distance3(const Scalar* a, const Scalar* b)
{
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

//! H(P_f) from its definition, written plainly: every pair of the patch for D, every dual
//! edge with both faces in it for R.
Scalar brute_consistency(const Mesh& m, const Topology& t, std::span<const Scalar> u, Index f)
{
    std::vector<Index> patch;
    for (Index g = 0; g < m.face_count(); ++g)
    {
        bool shares = g == f;
        for (const Index a : m.face(f))
            for (const Index b : m.face(g))
                shares = shares || a == b;
        if (shares)
            patch.push_back(g);
    }
    Scalar spread = 0, jump_max = 0, jump_sum = 0;
    for (const Index i : patch)
        for (const Index j : patch)
            spread = std::max(spread, distance3(&u[3 * i], &u[3 * j]));
    for (size_t k = 0; k < t.dual_edge_faces.size(); k += 2)
    {
        const Index i = t.dual_edge_faces[k], j = t.dual_edge_faces[k + 1];
        if (std::count(patch.begin(), patch.end(), i) && std::count(patch.begin(), patch.end(), j))
        {
            jump_max = std::max(jump_max, distance3(&u[3 * i], &u[3 * j]));
            jump_sum += distance3(&u[3 * i], &u[3 * j]);
        }
    }
    return spread * jump_max / (jump_sum + 1e-9);
}

} // namespace

TEST_SUITE("PatchGuidance")
{
    TEST_CASE(
        "on the small meshes each patch's consistency is D(P) R(P) of its definition, "
        "the guidance unit length and the same bits on one and two threads")
    {
        const test::ThreadCountGuard restore;
        for (const auto& kind : test::small_mesh_kinds())
        {
            CAPTURE(kind.first); // (clang: CAPTURE cannot name a structured binding)
            Mesh m = kind.second;
            test::perturb(m, 0.05, 3);
            const Topology t = build_topology(m);
            const std::vector<Scalar> u = face_normals(m, m.positions);
            PatchGuidance guidance(m, t);
            std::vector<Scalar> one(u.size()), two(u.size());
            set_thread_count(1);
            guidance.compute(m.positions, u, one);
            for (Index f = 0; f < m.face_count(); ++f)
                CHECK(guidance.consistency(f) ==
                      doctest::Approx(brute_consistency(m, t, u, f)).epsilon(1e-12));
            set_thread_count(2);
            guidance.compute(m.positions, u, two);
            CHECK(one == two);
            for (Index f = 0; f < m.face_count(); ++f)
            {
                const Scalar length =
                    std::sqrt(one[3 * f] * one[3 * f] + one[3 * f + 1] * one[3 * f + 1] +
                              one[3 * f + 2] * one[3 * f + 2]);
                // A face of no area anywhere near keeps its own (possibly zero) normal.
                CHECK((std::abs(length - 1) < 1e-12 || length == 0));
            }
        }
    }

    TEST_CASE("beside a crease every face is guided by a patch on its own side")
    {
        const Mesh m = test::folded_grid();
        const Topology t = build_topology(m);
        const std::vector<Scalar> u = face_normals(m, m.positions);
        PatchGuidance guidance(m, t);
        std::vector<Scalar> g(u.size());
        guidance.compute(m.positions, u, g);
        Index straddling = 0;
        for (Index f = 0; f < m.face_count(); ++f)
        {
            CAPTURE(f);
            // The faces touching the crease have a patch across it (H > 0) and are still
            // guided by their side's normal, exactly.
            straddling += guidance.consistency(f) > 0;
            CHECK(distance3(&g[3 * f], &u[3 * f]) < 1e-12);
        }
        CHECK(straddling == 2 * 6); // a column of faces on either side, six rows
    }

    TEST_CASE("guided weights keep a noisy crease sharper than the normals' own weights")
    {
        const Mesh clean = test::folded_grid();
        Mesh m = clean;
        test::perturb(m, 0.3, 11);
        const Topology t = build_topology(m);
        const std::vector<Scalar> clean_u = face_normals(clean, clean.positions);
        const std::vector<Scalar> noisy_u = face_normals(m, m.positions);
        const auto smooth = [&](bool guided) {
            BilateralWeights settings{1, 0.35, 1, FaceNeighborhood::Vertex, 0};
            settings.guided = guided;
            BilateralFaceWeights w(m, t, settings, m.positions);
            NormalSmoothingTerm term(t, {}, {}, {}, 0, {});
            term.set_weights(&w);
            std::vector<Scalar> u = noisy_u, scratch(u.size());
            for (int k = 0; k < 20; ++k)
            {
                w.reweight(m.positions, u);
                term.step(u, 0.5, scratch);
            }
            return u;
        };
        const Scalar noisy = test::mean_angle_degrees(noisy_u, clean_u);
        const Scalar plain = test::mean_angle_degrees(smooth(false), clean_u);
        const Scalar guided = test::mean_angle_degrees(smooth(true), clean_u);
        CAPTURE(noisy);
        CAPTURE(plain);
        CAPTURE(guided);
        CHECK(guided < 0.85 * plain);
        CHECK(guided < 0.2 * noisy);
    }
}
