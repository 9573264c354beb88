// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/mesh_generator.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "core/topology/topology.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::test;

namespace {

double total_area(const Mesh& m)
{
    double area = 0;
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const auto face = m.face(f);
        const Vec3 a = m.position(face[0]), b = m.position(face[1]), c = m.position(face[2]);
        const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
            v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const Vec3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                     u[0] * v[1] - u[1] * v[0]};
        area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    return area;
}

// Counts, topology, shape and orientation of the k-fold subdivision of `m`.
void check_subdivision(const Mesh& m, int k)
{
    CAPTURE(k);
    const Topology t = build_topology(m);
    const Mesh s = bench::subdivide_triangles(m, k);
    validate_mesh(s);
    const Topology st = build_topology(s);
    CHECK(s.vertex_count() ==
          m.vertex_count() + (k - 1) * t.edge_count() + (k - 1) * (k - 2) / 2 * m.face_count());
    CHECK(s.face_count() == k * k * m.face_count());
    // Same surface: Euler characteristic, boundary length in edges, singular edges scale,
    // the original vertices first and unmoved, the area unchanged.
    CHECK(st.vertex_count - st.edge_count() + s.face_count() ==
          t.vertex_count - t.edge_count() + m.face_count());
    CHECK(st.boundary_edge_count == k * t.boundary_edge_count);
    CHECK(st.singular_edge_count == k * t.singular_edge_count);
    for (Index i = 0; i < m.vertex_count(); ++i)
        CHECK(s.position(i) == m.position(i));
    CHECK(total_area(s) == doctest::Approx(total_area(m)).epsilon(1e-12));
    // Children keep their parent's orientation: their normals point the same way.
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const Vec3 parent = face_normal(m, m.positions, f);
        for (Index c = f * k * k; c < (f + 1) * k * k; ++c)
        {
            const Vec3 child = face_normal(s, s.positions, c);
            CHECK(parent[0] * child[0] + parent[1] * child[1] + parent[2] * child[2] ==
                  doctest::Approx(1).epsilon(1e-9));
        }
    }
}

} // namespace

TEST_CASE("subdivide_triangles: counts, shape and orientation on small meshes")
{
    for (int k = 1; k <= 5; ++k)
    {
        check_subdivision(tetrahedron(), k);
        check_subdivision(nonmanifold_fan(), k);
        check_subdivision(icosphere(1), k);
    }
    check_subdivision(bench::subdivide_triangles(icosphere(0), 2), 3);
}

TEST_CASE("subdivide_triangles refuses polygons and k < 1")
{
    CHECK_THROWS_AS(bench::subdivide_triangles(quad_cube(), 2), std::invalid_argument);
    CHECK_THROWS_AS(bench::subdivide_triangles(tetrahedron(), 0), std::invalid_argument);
}

TEST_CASE("subdivision_factor_for gives the smallest sufficient k")
{
    const Mesh m = io::read_mesh((assets_dir() / "bunny.obj").string());
    for (const long target : {1L, 100'000L, 1'000'000L})
    {
        const int k = bench::subdivision_factor_for(m, target);
        CHECK(bench::subdivide_triangles(m, k).vertex_count() >= target);
        if (k > 1)
            CHECK(bench::subdivide_triangles(m, k - 1).vertex_count() < target);
    }
}

TEST_CASE("random_order: a permutation, fixed by the seed")
{
    const std::vector<Index> a = bench::random_order(1000, 7);
    std::vector<Index> sorted = a;
    std::sort(sorted.begin(), sorted.end());
    CHECK(sorted == all_indices(1000));
    CHECK(bench::random_order(1000, 7) == a);
    CHECK(bench::random_order(1000, 8) != a);
    CHECK(a != all_indices(1000));
    CHECK(bench::random_order(0, 1).empty());
    CHECK(bench::random_order(1, 1) == std::vector<Index>{0});
}
