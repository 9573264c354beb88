// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/plain_sweep.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "core/topology/topology.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

struct SweepCase
{
    Topology topology;
    std::vector<Index> free;
    std::vector<Scalar> diagonal;
};

SweepCase make_case(const Mesh& mesh, bool every_other)
{
    SweepCase c{build_topology(mesh, TopologyParts::Neighbors), {}, {}};
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        c.diagonal.push_back(static_cast<Scalar>(c.topology.valence(i)));
        if (c.topology.valence(i) > 0 && (!every_other || i % 2 == 0))
            c.free.push_back(i);
    }
    return c;
}

PlainSweep sweep_of(const SweepCase& c, const std::vector<Scalar>& x, std::vector<Scalar>& y)
{
    return PlainSweep{c.free.data(),
                      c.topology.vertex_offsets.data(),
                      c.topology.vertex_neighbors.data(),
                      c.diagonal.data(),
                      0.5,
                      x.data(),
                      y.data()};
}

std::vector<Mesh> meshes()
{
    std::vector<Mesh> out;
    Mesh sphere = test::icosphere(3);
    test::perturb(sphere, 0.03, 11);
    out.push_back(sphere);
    // Far from the origin, as scans in millimetres are: differences first keeps digits.
    Mesh far = sphere;
    for (size_t k = 0; k < far.positions.size(); ++k)
        far.positions[k] = far.positions[k] * 1e-3 + 1e3 * static_cast<Scalar>(k % 3 + 1);
    out.push_back(far);
    // Signed zeros and exact cancellations on a flat grid (boundary vertices included).
    Mesh grid = test::open_grid(6, 5);
    for (size_t k = 0; k < grid.positions.size(); k += 3)
        grid.positions[k + 2] = -0.0;
    out.push_back(grid);
    out.push_back(test::mixed_polygons());
    out.push_back(test::nonmanifold_fan());
    return out;
}

} // namespace

TEST_SUITE("Solver")
{
    TEST_CASE(
        "plain sweep: y_i = x_i + lambda mean_j (x_j - x_i) at free vertices, others untouched")
    {
        for (const Mesh& mesh : meshes())
            for (const bool every_other : {false, true})
            {
                const SweepCase c = make_case(mesh, every_other);
                const std::vector<Scalar>& x = mesh.positions;
                std::vector<Scalar> y(x.size(), 7.0);
                plain_sweep(sweep_of(c, x, y), 0, static_cast<Index>(c.free.size()));
                std::vector<char> is_free(static_cast<size_t>(mesh.vertex_count()), 0);
                for (const Index i : c.free)
                    is_free[static_cast<size_t>(i)] = 1;
                for (Index i = 0; i < mesh.vertex_count(); ++i)
                    for (int a = 0; a < 3; ++a)
                    {
                        const size_t at = 3 * static_cast<size_t>(i) + static_cast<size_t>(a);
                        if (!is_free[static_cast<size_t>(i)])
                        {
                            CHECK(y[at] == 7.0);
                            continue;
                        }
                        long double mean = 0;
                        for (const Index j : c.topology.neighbors(i))
                            mean += x[3 * static_cast<size_t>(j) + static_cast<size_t>(a)] - x[at];
                        mean /= c.topology.valence(i);
                        const long double expected = x[at] + 0.5L * mean;
                        CHECK(std::abs(static_cast<long double>(y[at]) - expected) <=
                              1e-13L * (1 + std::abs(expected)));
                    }
            }
    }

    TEST_CASE("plain sweep: the AVX2 kernel gives the portable kernel's bits")
    {
        std::vector<Scalar> probe_x(3, 0), probe_y(3, 0);
        const SweepCase probe = make_case(test::tetrahedron(), false);
        if (!detail::plain_sweep_avx2(sweep_of(probe, probe_x, probe_y), 0, 0))
        {
            MESSAGE("this processor has no AVX2: only the portable kernel runs here");
            return;
        }
        for (const Mesh& mesh : meshes())
            for (const bool every_other : {false, true})
            {
                const SweepCase c = make_case(mesh, every_other);
                const std::vector<Scalar>& x = mesh.positions;
                std::vector<Scalar> a(x.size(), 7.0), b(x.size(), 7.0);
                const Index n = static_cast<Index>(c.free.size());
                detail::plain_sweep_scalar(sweep_of(c, x, a), 0, n);
                CHECK(detail::plain_sweep_avx2(sweep_of(c, x, b), 0, n));
                CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(Scalar)) == 0);
                // Split ranges write the same as one range.
                std::vector<Scalar> d(x.size(), 7.0);
                detail::plain_sweep_avx2(sweep_of(c, x, d), 0, n / 3);
                detail::plain_sweep_avx2(sweep_of(c, x, d), n / 3, n);
                CHECK(std::memcmp(a.data(), d.data(), a.size() * sizeof(Scalar)) == 0);
            }
    }
}
