// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/geometry/noise_estimate.h"

#include <doctest/doctest.h>

#include <cmath>

#include "core/geometry/noise.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

//! A flat grid of nx x ny unit squares, each split into two triangles, in z = 0.
Mesh triangle_grid(int nx, int ny)
{
    std::vector<Vec3> points;
    std::vector<std::vector<Index>> faces;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            points.push_back({Scalar(i), Scalar(j), 0});
    const auto at = [&](int i, int j) { return static_cast<Index>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return test::make_mesh(points, faces);
}

//! Gaussian noise of deviation `height` along each vertex's outward unit direction from
//! the origin (the sphere's normal) or along z (the grid's).
void noise_along_normals(Mesh& m, Scalar height, unsigned seed, bool radial)
{
    Mesh deviates = m;
    std::fill(deviates.positions.begin(), deviates.positions.end(), 0);
    add_gaussian_noise(deviates, height, seed);
    for (Index v = 0; v < m.vertex_count(); ++v)
    {
        Scalar* p = &m.positions[3 * v];
        Vec3 n{0, 0, 1};
        if (radial)
        {
            const Scalar r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            n = {p[0] / r, p[1] / r, p[2] / r};
        }
        for (int a = 0; a < 3; ++a)
            p[a] += deviates.positions[3 * v] * n[a];
    }
}

} // namespace

TEST_SUITE("estimate_noise")
{
    TEST_CASE("a flat mesh has none and its border's vertices are not measured")
    {
        const Mesh m = triangle_grid(20, 20);
        const Topology t = build_topology(m);
        const NoiseEstimate e = estimate_noise(m, t, m.positions);
        CHECK(e.sigma == 0);
        CHECK(e.vertices == 19 * 19);
        CHECK(e.edge_length == doctest::Approx(std::sqrt((40.0 * 21 + 400 * 2) / (40 * 21 + 400))));
    }

    TEST_CASE("noise along the normals is found at its level, on a plane and on a sphere")
    {
        for (const Scalar sigma : {0.1, 0.3, 0.7})
        {
            CAPTURE(sigma);
            Mesh plane = triangle_grid(80, 80);
            // The grid's mean edge is (2 + sqrt 2) / 3 units long.
            const Scalar edge = (2 + std::sqrt(2.0)) / 3;
            noise_along_normals(plane, sigma * edge, 17, false);
            const NoiseEstimate a = estimate_noise(plane, build_topology(plane), plane.positions);
            CHECK(a.sigma == doctest::Approx(sigma).epsilon(0.1));

            Mesh sphere = test::icosphere(5); // 10,242 vertices, edges of 0.038
            const Topology t = build_topology(sphere);
            const Scalar sphere_edge = mean_edge_length(t, sphere.positions);
            noise_along_normals(sphere, sigma * sphere_edge, 18, true);
            const NoiseEstimate b = estimate_noise(sphere, t, sphere.positions);
            CHECK(b.sigma == doctest::Approx(sigma).epsilon(0.1));
            CHECK(b.edge_length == doctest::Approx(sphere_edge).epsilon(0.05));
        }
    }

    TEST_CASE("impulsive noise, a tenth of the vertices thrown off, is found")
    {
        Mesh plane = triangle_grid(60, 60);
        const Scalar edge = (2 + std::sqrt(2.0)) / 3;
        for (Index v = 0; v < plane.vertex_count(); v += 10)
            plane.positions[3 * v + 2] = (v % 20 == 0 ? 0.7 : -0.7) * edge;
        const NoiseEstimate e = estimate_noise(plane, build_topology(plane), plane.positions);
        CHECK(e.sigma > 0.1);
        CHECK(e.sigma < 0.3);
    }

    TEST_CASE(
        "the estimate is in edge lengths: a scaled mesh has the same, the counted "
        "vertices only")
    {
        Mesh m = test::icosphere(4);
        noise_along_normals(m, 0.02, 4, true);
        const Topology t = build_topology(m);
        const NoiseEstimate e = estimate_noise(m, t, m.positions);
        Mesh big = m;
        for (Scalar& c : big.positions)
            c *= 10;
        const NoiseEstimate f = estimate_noise(big, t, big.positions);
        CHECK(f.sigma == doctest::Approx(e.sigma).epsilon(1e-9));
        CHECK(f.height == doctest::Approx(10 * e.height).epsilon(1e-9));
        // Counting the upper half only measures those vertices.
        std::vector<char> upper(m.vertex_count(), 0);
        for (Index v = 0; v < m.vertex_count(); ++v)
            upper[v] = m.positions[3 * v + 2] > 0;
        const NoiseEstimate h = estimate_noise(m, t, m.positions, upper);
        CHECK(h.vertices < e.vertices);
        CHECK(h.vertices > e.vertices / 3);
        CHECK(h.sigma == doctest::Approx(e.sigma).epsilon(0.2));
    }

    TEST_CASE("meshes with nothing to measure give 0")
    {
        for (const auto& kind : test::small_mesh_kinds())
        {
            CAPTURE(kind.first); // (clang: CAPTURE cannot name a structured binding)
            const Mesh& m = kind.second;
            const Topology t = build_topology(m);
            const NoiseEstimate e = estimate_noise(m, t, m.positions);
            CHECK(std::isfinite(e.sigma));
            CHECK(e.sigma >= 0);
        }
        const Mesh triangle = test::make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        const NoiseEstimate e =
            estimate_noise(triangle, build_topology(triangle), triangle.positions);
        CHECK(e.vertices == 0);
        CHECK(e.sigma == 0);
    }
}
