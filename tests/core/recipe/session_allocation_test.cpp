// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Replaces the global allocation functions of the test program with counting ones, so a
// test can assert that a region of code allocates nothing: C++'s operator new and, outside
// the sanitizer build (where AddressSanitizer owns malloc), the C library's malloc family
// too, which is what the OpenMP runtime and every other library call.
#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "app/common/sanitizer_malloc.h"
#include "core/recipe/session.h"
#include "core/solver/parallel.h"
#include "tests/helpers.h"

namespace {

std::atomic<long> g_allocations{0};

} // namespace

#define MESHFAIR_COUNT_MALLOC (!MESHFAIR_SANITIZER_OWNS_MALLOC)

#if MESHFAIR_COUNT_MALLOC
// glibc's own entry points; defining malloc here interposes it for every shared library.
extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);

extern "C" void* malloc(std::size_t size)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_malloc(size);
}

extern "C" void* calloc(std::size_t count, std::size_t size)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_calloc(count, size);
}

extern "C" void* realloc(void* p, std::size_t size)
{
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    return __libc_realloc(p, size);
}
#endif

void* operator new(std::size_t size)
{
    if (!MESHFAIR_COUNT_MALLOC) // else malloc counts it
        g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size))
        return p;
    throw std::bad_alloc();
}

void* operator new[](std::size_t size)
{
    return operator new(size);
}

void operator delete(void* p) noexcept
{
    std::free(p);
}

void operator delete[](void* p) noexcept
{
    std::free(p);
}

void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete[](void* p, std::size_t) noexcept
{
    std::free(p);
}

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
                    const long before = g_allocations.load();
                    Scalar total = 0;
                    for (int k = 0; k < 5; ++k)
                    {
                        session.step(x.positions);
                        total += session.energy(x.positions).total();
                    }
                    CHECK(g_allocations.load() == before);
                    CHECK(total > 0);
                }
        // The counter itself works: a vector allocates, and so does the C library.
        const long before = g_allocations.load();
        std::vector<int> v(10);
        CHECK(g_allocations.load() > before);
        if (MESHFAIR_COUNT_MALLOC)
        {
            const long c_before = g_allocations.load();
            void* volatile p = std::malloc(100);
            std::free(p);
            CHECK(g_allocations.load() > c_before);
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
            const long before = g_allocations.load();
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
            CHECK(g_allocations.load() == before);
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
            const long before = g_allocations.load();
            for (int k = 0; k < 5; ++k)
            {
                session.step(x.positions);
                session.energy(x.positions);
            }
            CHECK(g_allocations.load() == before);
            // The same with the session's kept positions (what run() and the editor use).
            session.set_positions(x.positions);
            session.step();
            const long kept_before = g_allocations.load();
            TermEnergies energy;
            for (int k = 0; k < 5; ++k)
            {
                session.step();
                session.energy();
                session.step(energy); // the energy in the step's sweep
            }
            CHECK(g_allocations.load() == kept_before);
            set_thread_count(0);
        }
    }
}
