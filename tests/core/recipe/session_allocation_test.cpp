// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// A step and an energy evaluation allocate nothing, counted by the test program's
// allocation functions (tests/allocation_counter.h).
#include <doctest/doctest.h>

#include <cstdlib>
#include <vector>

#include "core/parallel/parallel.h"
#include "core/recipe/session.h"
#include "tests/allocation_counter.h"
#include "tests/helpers.h"

using namespace meshfair;

TEST_SUITE("Session")
{
    TEST_CASE("a step and an energy evaluation allocate nothing")
    {
        Mesh m = test::icosphere(2);
        test::perturb(m, 0.03, 8);
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count(), nf = m.face_count();
        Recipe all;
        all.region = Region{{}, test::all_indices(nf - 3)};
        all.hard = HardVertices{{0}, {{0.0, 0.0, 1.5}}};
        all.soft = SoftVertices{{false, {1, 2, nv - 1}}, 0.5, {}};
        all.centroid = CentroidConstraints{{true, {}}, 1.0, {}, CentroidDenominator::Paper};
        all.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Smoothed, {}};
        all.normal_smoothing = NormalSmoothing{3, 0.5, {{4}, {}}, {{5}, 0.5, {}}};
        for (const bool joint : {false, true})
            for (const bool optimal : {false, true})
                for (const bool bilateral : {false, true})
                {
                    CAPTURE(joint);
                    CAPTURE(optimal);
                    CAPTURE(bilateral);
                    Recipe r = all;
                    r.optimal_step = optimal;
                    if (joint)
                        r.joint = Joint{1.0};
                    // Joint mode reweights the bilateral weights every other step.
                    if (bilateral)
                        r.normal_smoothing->bilateral =
                            BilateralWeights{1.0, 0.35, 2, FaceNeighborhood::Vertex};
                    Mesh x = m;
                    Session session(x, t, r);
                    session.apply_hard_targets(x.positions);
                    session.step(x.positions); // warm-up outside the measured region
                    const test::AllocationScope measured;
                    Scalar total = 0;
                    for (int k = 0; k < 5; ++k)
                    {
                        session.step(x.positions);
                        total += session.energy(x.positions).total();
                    }
                    CHECK(measured.count() == 0);
                    CHECK(total > 0);
                }
        // The counter itself works: a vector allocates, and so does the C library.
        {
            const test::AllocationScope vector;
            std::vector<int> v(10);
            CHECK(vector.count() == 1);
            CHECK(vector.bytes() == 10 * sizeof(int));
            CHECK(vector.largest() == 10 * sizeof(int));
        }
        if (test::AllocationScope::counts_malloc())
        {
            const test::AllocationScope c;
            void* volatile p = std::malloc(100);
            std::free(p);
            CHECK(c.count() == 1);
            CHECK(c.largest() == 100);
        }
    }

    TEST_CASE("with a weight per element a step and an energy evaluation allocate nothing")
    {
        Mesh m = test::icosphere(2);
        test::perturb(m, 0.03, 8);
        const Topology t = build_topology(m);
        const Index nv = m.vertex_count(), nf = m.face_count();
        Recipe all;
        all.region = Region{{}, test::all_indices(nf - 3)};
        all.hard = HardVertices{{0}, {{0.0, 0.0, 1.5}}};
        all.soft = SoftVertices{{false, {1, 2, nv - 1}}, 0.5, {}, {0.5, 2.0, 0.0}};
        all.centroid = CentroidConstraints{{true, {}},
                                           1.0,
                                           {},
                                           CentroidDenominator::Paper,
                                           std::vector<Scalar>(static_cast<size_t>(nf), 1.5)};
        all.normal = NormalConstraints{{true, {}},
                                       1.0,
                                       NormalSource::Smoothed,
                                       {},
                                       std::vector<Scalar>(static_cast<size_t>(nf), 0.75)};
        all.normal->weights[3] = 3.0;
        all.normal_smoothing = NormalSmoothing{3, 0.5, {{4}, {}}, {{5}, 0.5, {}, {2.0}}};
        for (const int variant : {0, 1, 2, 3}) // the fused step, optimal, joint, both
        {
            CAPTURE(variant);
            Recipe r = all;
            r.optimal_step = (variant & 1) != 0;
            if (variant & 2)
                r.joint = Joint{1.0};
            Mesh x = m;
            Session session(x, t, r);
            session.apply_hard_targets(x.positions);
            session.set_positions(x.positions);
            session.step(); // warm-up outside the measured region
            session.step(x.positions);
            const test::AllocationScope measured;
            Scalar total = 0;
            TermEnergies swept;
            session.step(swept); // the first sums the fixed parts: no allocation either
            for (int k = 0; k < 5; ++k)
            {
                session.step();
                session.step(swept);
                session.step(x.positions);
                total +=
                    session.energy(x.positions).total() + session.energy().total() + swept.total();
            }
            CHECK(measured.count() == 0);
            CHECK(total > 0);
        }
    }

    TEST_CASE("a multi-threaded step and energy evaluation allocate nothing")
    {
        // Large enough for every loop to run on several threads (kParallelThreshold).
        Mesh m = test::icosphere(6);
        REQUIRE(m.vertex_count() > 4 * kParallelThreshold);
        test::perturb(m, 0.003, 9);
        const Topology t = build_topology(m);
        Recipe r;
        r.soft = SoftVertices{{true, {}}, 0.1, {}};
        r.centroid = CentroidConstraints{{true, {}}, 1.0, {}, CentroidDenominator::Paper};
        r.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Initial, {}};
        Recipe plain;        // the fused step
        Recipe weighted = r; // the fused step with a weight per element
        weighted.soft->weights.assign(static_cast<size_t>(m.vertex_count()), 0.5);
        weighted.centroid->weights.assign(static_cast<size_t>(m.face_count()), 2.0);
        weighted.normal->weights.assign(static_cast<size_t>(m.face_count()), 0.25);
        for (const int variant : {0, 1, 2, 3})
        {
            CAPTURE(variant);
            r.optimal_step = variant == 1;
            if (variant == 2)
                r = plain;
            if (variant == 3)
                r = weighted;
            set_thread_count(2);
            Mesh x = m;
            Session session(x, t, r);
            session.step(x.positions); // warm-up: the OpenMP runtime starts its threads
            session.energy(x.positions);
            {
                const test::AllocationScope measured;
                for (int k = 0; k < 5; ++k)
                {
                    session.step(x.positions);
                    session.energy(x.positions);
                }
                CHECK(measured.count() == 0);
            }
            // The same with the session's kept positions (what run() and the editor use).
            session.set_positions(x.positions);
            session.step();
            const test::AllocationScope kept;
            TermEnergies energy;
            for (int k = 0; k < 5; ++k)
            {
                session.step();
                session.energy();
                session.step(energy); // the energy in the step's sweep
            }
            CHECK(kept.count() == 0);
            set_thread_count(0);
        }
    }
}
