// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/bilateral_face_weights.h"

#include <doctest/doctest.h>

#include <Eigen/Sparse>

#include <cmath>
#include <cstring>

#include "core/energies/normal_smoothing_term.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "core/recipe/session.h"
#include "tests/energy_checks.h"
#include "tests/helpers.h"
#include "tests/session_checks.h"

using namespace meshfair;

namespace {

Scalar squared_distance(const Vec3& a, const Vec3& b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

} // namespace

TEST_SUITE("BilateralFaceWeights")
{
    TEST_CASE("edge neighbours are the dual graph's, vertex neighbours share any corner")
    {
        const BilateralWeights edge{}, vertex{1, 0.35, 1, FaceNeighborhood::Vertex};
        {
            const Mesh m = test::open_grid(3, 3); // face 4 is the middle one
            const Topology t = build_topology(m);
            const BilateralFaceWeights e(m, t, edge, m.positions), v(m, t, vertex, m.positions);
            CHECK(std::vector<Index>(e.neighbors_of(4).begin(), e.neighbors_of(4).end()) ==
                  std::vector<Index>{1, 3, 5, 7});
            CHECK(std::vector<Index>(v.neighbors_of(4).begin(), v.neighbors_of(4).end()) ==
                  std::vector<Index>{0, 1, 2, 3, 5, 6, 7, 8});
            CHECK(v.neighbors_of(0).size() == 3); // a corner face
            CHECK(v.weight_sum(4) == 8);          // all 1 before any reweight
        }
        {
            // Three triangles on one singular edge: no dual edge, but they share vertices.
            const Mesh m = test::nonmanifold_fan();
            const Topology t = build_topology(m);
            const BilateralFaceWeights e(m, t, edge, m.positions), v(m, t, vertex, m.positions);
            for (Index f = 0; f < 3; ++f)
            {
                CHECK(e.neighbors_of(f).empty());
                CHECK(v.neighbors_of(f).size() == 2);
            }
            CHECK(e.sigma_s() == 0); // no dual edge to measure: spatial factor 1
        }
        {
            const Mesh m = test::tetrahedron();
            const Topology t = build_topology(m);
            const BilateralFaceWeights v(m, t, vertex, m.positions);
            for (Index f = 0; f < 4; ++f)
                CHECK(v.neighbors_of(f).size() == 3);
        }
    }

    TEST_CASE("each weight is the product of the two Gaussians, a crease cuts the weights")
    {
        const Mesh m = test::folded_grid();
        const Topology t = build_topology(m);
        const BilateralWeights settings{1.5, 0.35, 1, FaceNeighborhood::Vertex};
        BilateralFaceWeights w(m, t, settings, m.positions);
        // Unit quads: centroids 1 apart, and 1/sqrt(2) across the crease.
        const Scalar flat_pairs = 11 * 6 - 6 + 12 * 5, crease_pairs = 6;
        const Scalar mean =
            (flat_pairs + crease_pairs * std::sqrt(0.5)) / (flat_pairs + crease_pairs);
        CHECK(mean_dual_edge_length(m, t, m.positions) == doctest::Approx(mean).epsilon(1e-14));
        CHECK(w.sigma_s() == doctest::Approx(1.5 * mean).epsilon(1e-14));
        const Scalar s = w.sigma_s();
        const std::vector<Scalar> u = face_normals(m, m.positions);
        w.reweight(m.positions, u);
        Scalar across = 0, along = 1;
        for (Index f = 0; f < m.face_count(); ++f)
        {
            Scalar sum = 0;
            for (size_t k = 0; k < w.neighbors_of(f).size(); ++k)
            {
                const Index g = w.neighbors_of(f)[k];
                const Scalar dc = squared_distance(face_centroid(m, m.positions, f),
                                                   face_centroid(m, m.positions, g));
                const Scalar du = squared_distance({u[3 * f], u[3 * f + 1], u[3 * f + 2]},
                                                   {u[3 * g], u[3 * g + 1], u[3 * g + 2]});
                const Scalar expected =
                    std::exp(-dc / (2 * s * s)) * std::exp(-du / (2 * 0.35 * 0.35));
                CHECK(w.weights_of(f)[k] == doctest::Approx(expected).epsilon(1e-14));
                sum += w.weights_of(f)[k];
                if (du > 1)
                    across = std::max(across, w.weights_of(f)[k]);
                else
                    along = std::min(along, w.weights_of(f)[k]);
            }
            CHECK(w.weight_sum(f) == doctest::Approx(sum).epsilon(1e-14));
        }
        CHECK(across < 1e-3);
        CHECK(along > 0.4);
    }

    TEST_CASE("reweighting keeps the spatial factors while the centroids stay, and only then")
    {
        // The spatial factors are kept between reweightings at unchanged positions (the
        // two-stage process) and taken again when a centroid moves (joint mode): either
        // way the weights are a fresh object's, bit for bit.
        const Mesh m = test::folded_grid();
        const Topology t = build_topology(m);
        const BilateralWeights settings{1.5, 0.35, 1, FaceNeighborhood::Vertex};
        const std::vector<Scalar> u = face_normals(m, m.positions);
        std::vector<Scalar> moved = m.positions;
        for (size_t k = 0; k < moved.size(); k += 3)
            moved[k + 2] += 0.1 * std::sin(static_cast<Scalar>(k));
        const std::vector<Scalar> u_moved = face_normals(m, moved);
        const auto same_weights = [&](const BilateralFaceWeights& a,
                                      const BilateralFaceWeights& b) {
            for (Index f = 0; f < m.face_count(); ++f)
            {
                const auto wa = a.weights_of(f), wb = b.weights_of(f);
                if (!std::equal(wa.begin(), wa.end(), wb.begin(), wb.end()) ||
                    a.weight_sum(f) != b.weight_sum(f))
                    return false;
            }
            return true;
        };
        BilateralFaceWeights kept(m, t, settings, m.positions);
        kept.reweight(m.positions, u);
        kept.reweight(m.positions, u_moved); // the same positions, other normals
        BilateralFaceWeights fresh(m, t, settings, m.positions);
        fresh.reweight(m.positions, u_moved);
        CHECK(same_weights(kept, fresh));
        kept.reweight(moved, u_moved); // the centroids moved
        BilateralFaceWeights fresh_moved(m, t, settings, m.positions);
        fresh_moved.reweight(moved, u_moved);
        CHECK(same_weights(kept, fresh_moved));
        CHECK_FALSE(same_weights(kept, fresh)); // the move changed them
    }

    TEST_CASE(
        "the weighted step's numerator is -1/2 dE_U/du (central differences), its "
        "denominator the weights' sum plus mu_f")
    {
        Mesh m = test::folded_grid();
        test::perturb(m, 0.1, 5);
        const Topology t = build_topology(m);
        BilateralFaceWeights w(m, t, BilateralWeights{}, m.positions);
        const std::vector<Scalar> u = face_normals(m, m.positions);
        w.reweight(m.positions, u);
        const std::vector<Index> hard{3}, soft{0, 9, 40};
        const std::vector<Scalar> hard_normals{0, 0, 1}, soft_normals{0, 0, 1, 0, 1, 0, 1, 0, 0},
            soft_weights{1, 0.5, 2};
        NormalSmoothingTerm term(t, hard, hard_normals, soft, 0.7, soft_normals, soft_weights);
        term.set_weights(&w);
        std::vector<Scalar> du(u.size());
        term.displacements(u, du);
        std::vector<Scalar> rhs(u.size(), 0);
        for (Index f = 0; f < m.face_count(); ++f)
            if (!term.is_hard(f))
                for (int a = 0; a < 3; ++a)
                    rhs[3 * f + a] = du[3 * f + a] * (w.weight_sum(f) + term.soft_weight(f));
        // Hard faces do not move: their coordinates are left out of the energy's variables.
        const auto energy = [&](std::span<const Scalar> v) {
            std::vector<Scalar> held(v.begin(), v.end());
            std::copy_n(&u[9], 3, &held[9]);
            return term.dual_energy(held) + term.soft_energy(held);
        };
        std::vector<Scalar> variables = u;
        test::check_rhs_is_half_negative_gradient(energy, variables, rhs);
    }

    TEST_CASE(
        "without renormalization a stage's Jacobi iteration reaches Eigen's minimizer "
        "of its quadratic")
    {
        Mesh m = test::folded_grid();
        test::perturb(m, 0.1, 6);
        const Topology t = build_topology(m);
        const Index nf = m.face_count();
        BilateralFaceWeights w(m, t, BilateralWeights{1, 0.35, 1, FaceNeighborhood::Vertex},
                               m.positions);
        std::vector<Scalar> u = face_normals(m, m.positions);
        w.reweight(m.positions, u);
        // Every face soft (mu 0.2) toward its initial normal: a positive definite quadratic.
        const std::vector<Index> soft = test::all_indices(nf);
        NormalSmoothingTerm term(t, {}, {}, soft, 0.2, u);
        term.set_weights(&w);
        // Reference: (L_w + 0.2 I) u = 0.2 u0, assembled here from the weights' lists.
        std::vector<Eigen::Triplet<double>> entries;
        for (Index f = 0; f < nf; ++f)
        {
            entries.emplace_back(f, f, w.weight_sum(f) + 0.2);
            for (size_t k = 0; k < w.neighbors_of(f).size(); ++k)
                entries.emplace_back(f, w.neighbors_of(f)[k], -w.weights_of(f)[k]);
        }
        Eigen::SparseMatrix<double> A(nf, nf);
        A.setFromTriplets(entries.begin(), entries.end());
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
        REQUIRE(solver.info() == Eigen::Success);
        Eigen::MatrixXd b(nf, 3);
        for (Index f = 0; f < nf; ++f)
            for (int a = 0; a < 3; ++a)
                b(f, a) = 0.2 * u[3 * f + a];
        const Eigen::MatrixXd expected = solver.solve(b);
        std::vector<Scalar> du(u.size());
        for (int k = 0; k < 3000; ++k)
        {
            term.displacements(u, du);
            for (size_t i = 0; i < u.size(); ++i)
                u[i] += du[i];
        }
        Scalar worst = 0;
        for (Index f = 0; f < nf; ++f)
            for (int a = 0; a < 3; ++a)
                worst = std::max(worst, std::abs(u[3 * f + a] - expected(f, a)));
        CHECK(worst < 1e-9);
    }

    TEST_CASE(
        "reweighted smoothing keeps a crease that the paper's uniform smoothing rounds, "
        "the robust energy never increases")
    {
        const Mesh clean = test::folded_grid();
        Mesh m = clean;
        test::perturb(m, 0.08, 7);
        const Topology t = build_topology(m);
        const std::vector<Scalar> clean_u = face_normals(clean, clean.positions);
        const std::vector<Scalar> noisy_u = face_normals(m, m.positions);
        std::vector<Scalar> scratch(noisy_u.size());

        std::vector<Scalar> uniform = noisy_u;
        const NormalSmoothingTerm plain(t, {}, {}, {}, 0, {});
        for (int k = 0; k < 20; ++k)
            plain.step(uniform, 0.5, scratch);

        std::vector<Scalar> bilateral = noisy_u;
        // A fixed sigma_r: each stage majorizes the same robust energy.
        BilateralFaceWeights w(m, t, BilateralWeights{1, 0.35, 1, FaceNeighborhood::Edge, 0},
                               m.positions);
        NormalSmoothingTerm term(t, {}, {}, {}, 0, {});
        term.set_weights(&w);
        Scalar robust = std::numeric_limits<Scalar>::infinity();
        for (int k = 0; k < 20; ++k)
        {
            w.reweight(m.positions, bilateral);
            const Scalar now = w.robust_energy(bilateral);
            CHECK(now <= robust);
            robust = now;
            term.step(bilateral, 0.5, scratch);
        }
        const Scalar noisy = test::mean_angle_degrees(noisy_u, clean_u);
        const Scalar theta_uniform = test::mean_angle_degrees(uniform, clean_u);
        const Scalar theta_bilateral = test::mean_angle_degrees(bilateral, clean_u);
        CAPTURE(noisy);
        CAPTURE(theta_uniform);
        CAPTURE(theta_bilateral);
        CHECK(theta_bilateral < 0.5 * theta_uniform);
        CHECK(theta_bilateral < 0.25 * noisy);
    }

    TEST_CASE(
        "strong noise widens sigma_r by the normals' median difference, and then the "
        "smoothing removes it where a fixed sigma_r keeps it as features")
    {
        const Mesh clean = test::folded_grid();
        Mesh m = clean;
        test::perturb(m, 0.7, 8);
        const Topology t = build_topology(m);
        const std::vector<Scalar> clean_u = face_normals(clean, clean.positions);
        const std::vector<Scalar> noisy_u = face_normals(m, m.positions);
        std::vector<Scalar> scratch(noisy_u.size());
        const auto smoothed = [&](Scalar noise_scale, Scalar* first_sigma) {
            std::vector<Scalar> u = noisy_u;
            BilateralFaceWeights w(
                m, t, BilateralWeights{1, 0.35, 1, FaceNeighborhood::Edge, noise_scale},
                m.positions);
            NormalSmoothingTerm term(t, {}, {}, {}, 0, {});
            term.set_weights(&w);
            for (int k = 0; k < 30; ++k)
            {
                w.reweight(m.positions, u);
                if (k == 0)
                    *first_sigma = w.effective_sigma_r();
                term.step(u, 0.5, scratch);
            }
            if (noise_scale > 0)
                CHECK(w.effective_sigma_r() < *first_sigma); // it narrows as the noise goes
            return test::mean_angle_degrees(u, clean_u);
        };
        Scalar fixed_sigma = 0, adaptive_sigma = 0;
        const Scalar fixed = smoothed(0, &fixed_sigma);
        (void)fixed_sigma;
        const Scalar adaptive = smoothed(1.5, &adaptive_sigma);
        // The median difference of the noisy normals, computed apart.
        std::vector<Scalar> d;
        for (Index f = 0; f < m.face_count(); ++f)
            for (const Index g : t.face_neighbors_of(f))
            {
                Scalar s = 0;
                for (int a = 0; a < 3; ++a)
                    s += (noisy_u[3 * f + a] - noisy_u[3 * g + a]) *
                         (noisy_u[3 * f + a] - noisy_u[3 * g + a]);
                d.push_back(std::sqrt(s));
            }
        std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
        CHECK(adaptive_sigma == doctest::Approx(1.5 * d[d.size() / 2]).epsilon(1e-12));
        CAPTURE(fixed);
        CAPTURE(adaptive);
        CHECK(adaptive < 0.7 * fixed);
    }

    TEST_CASE("sessions with bilateral weights give the same bits on one and two threads")
    {
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.02, 9);
        const Topology t = build_topology(m);
        Recipe r;
        r.iterations = 4;
        r.normal = NormalConstraints{{true, {}}, 5.0, NormalSource::Smoothed, {}};
        r.normal_smoothing = NormalSmoothing{6, 0.5, {}, {}};
        for (const FaceNeighborhood n : {FaceNeighborhood::Edge, FaceNeighborhood::Vertex})
            for (const bool joint : {false, true})
            {
                CAPTURE(joint);
                r.normal_smoothing->bilateral = BilateralWeights{1.0, 0.35, 2, n};
                r.joint = joint ? std::optional<Joint>(Joint{1.0}) : std::nullopt;
                test::check_same_bits_on_one_and_two_threads(m, t, r);
            }
    }
}
