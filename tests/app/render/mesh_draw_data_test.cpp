// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/mesh_draw_data.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "core/parallel/parallel.h"
#include "core/topology/topology.h"
#include "core/topology/vertex_order.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

MeshDrawData draw_data(const Mesh& m)
{
    return mesh_draw_data(m, build_topology(m, TopologyParts::Edges | TopologyParts::Corners));
}

std::set<std::pair<std::uint32_t, std::uint32_t>> edge_set(const std::vector<std::uint32_t>& e)
{
    std::set<std::pair<std::uint32_t, std::uint32_t>> s;
    for (size_t k = 0; k < e.size(); k += 2)
        s.insert(std::minmax(e[k], e[k + 1]));
    return s;
}

// The ranges of `part` are ascending, disjoint, at most 256, counted right, and hold every
// free vertex, every face around one and every corner of those faces.
void check_changing_part(const Mesh& m, const MeshDrawData& d, const std::vector<Index>& free)
{
    CAPTURE(free.size());
    const ChangingPart part = changing_part(m, d.vertex_face_offsets, d.vertex_faces, free);
    const auto in = [](const IndexRanges& r, Index i) {
        for (size_t k = 0; k < r.begin.size(); ++k)
            if (r.begin[k] <= i && i < r.end[k])
                return true;
        return false;
    };
    for (const IndexRanges* r : {&part.vertices, &part.faces})
    {
        CHECK(r->begin.size() <= 256);
        Index count = 0;
        for (size_t k = 0; k < r->begin.size(); ++k)
        {
            CHECK(r->begin[k] < r->end[k]);
            if (k > 0)
                CHECK(r->end[k - 1] < r->begin[k]); // merged when they touch
            CHECK(r->before[k] == count);
            count += r->end[k] - r->begin[k];
        }
        CHECK(r->count() == count);
    }
    for (const Index v : free)
    {
        CHECK(in(part.vertices, v));
        for (Index k = d.vertex_face_offsets[v]; k < d.vertex_face_offsets[v + 1]; ++k)
        {
            const Index f = d.vertex_faces[k];
            CHECK(in(part.faces, f));
            for (const Index corner : m.face(f))
                CHECK(in(part.vertices, corner));
        }
    }
}

} // namespace

TEST_SUITE("MeshDrawData")
{
    TEST_CASE("a polygon of n corners is a fan of n - 2 triangles of that face")
    {
        const Mesh m = test::mixed_polygons();
        const MeshDrawData d = draw_data(m);
        size_t expected = 0;
        for (Index f = 0; f < m.face_count(); ++f)
            expected += static_cast<size_t>(m.face_size(f) - 2);
        REQUIRE(d.triangle_face.size() == expected);
        REQUIRE(d.triangles.size() == 3 * expected);
        for (size_t t = 0; t < d.triangle_face.size(); ++t)
        {
            const std::span<const Index> face = m.face(static_cast<Index>(d.triangle_face[t]));
            CHECK(d.triangles[3 * t] == static_cast<std::uint32_t>(face[0])); // the fan's apex
            for (int k = 0; k < 3; ++k)
                CHECK(std::find(face.begin(), face.end(), d.triangles[3 * t + k]) != face.end());
        }
    }

    TEST_CASE("the wireframe is the polygon edges, never a fan diagonal")
    {
        const Mesh cube = test::quad_cube();
        const MeshDrawData d = draw_data(cube);
        CHECK(d.triangles.size() == 3 * 12);
        const auto edges = edge_set(d.edges);
        CHECK(edges.size() == 12);
        CHECK(d.edges.size() == 24);
        for (Index f = 0; f < cube.face_count(); ++f)
        {
            const std::span<const Index> q = cube.face(f);
            CHECK(edges.count(std::minmax<std::uint32_t>(q[0], q[2])) == 0); // diagonals
            CHECK(edges.count(std::minmax<std::uint32_t>(q[1], q[3])) == 0);
            for (int k = 0; k < 4; ++k)
                CHECK(edges.count(std::minmax<std::uint32_t>(q[k], q[(k + 1) % 4])) == 1);
        }
        CHECK(d.boundary_edges.empty());
        CHECK(d.singular_edges.empty());
    }

    TEST_CASE("each triangle's sides that are polygon edges are those the edge list holds")
    {
        // The wireframe drawn by the surface's fragments marks these sides, and must draw
        // exactly the edges of the list: every polygon edge once, no fan diagonal.
        for (const Mesh& m : {test::mixed_polygons(), test::quad_cube(), test::open_grid(4, 3)})
        {
            const MeshDrawData d = draw_data(m);
            REQUIRE(d.triangle_edges.size() == d.triangle_face.size());
            std::set<std::pair<std::uint32_t, std::uint32_t>> marked;
            for (size_t t = 0; t < d.triangle_edges.size(); ++t)
            {
                CHECK(d.triangle_edges[t] < 8);
                for (size_t k = 0; k < 3; ++k)
                    if (d.triangle_edges[t] & (1u << k))
                        marked.insert(
                            std::minmax(d.triangles[3 * t + k], d.triangles[3 * t + (k + 1) % 3]));
            }
            CHECK(marked == edge_set(d.edges));
        }
    }

    TEST_CASE("an open grid's boundary edges are its perimeter, a fan's shared edge is singular")
    {
        const MeshDrawData grid = draw_data(test::open_grid(5, 3));
        CHECK(grid.boundary_edges.size() == 2 * (2 * 5 + 2 * 3));
        for (const std::uint32_t v : grid.boundary_edges)
        {
            const std::uint32_t i = v % 6, j = v / 6;
            CHECK((i == 0 || i == 5 || j == 0 || j == 3));
        }
        const MeshDrawData fan = draw_data(test::nonmanifold_fan());
        REQUIRE(fan.singular_edges.size() == 2);
        CHECK(std::min(fan.singular_edges[0], fan.singular_edges[1]) == 0);
        CHECK(std::max(fan.singular_edges[0], fan.singular_edges[1]) == 1);
        CHECK(fan.boundary_edges.size() == 2 * 6);
    }

    TEST_CASE("area vectors are the polygons' areas, vertex normals are unit and outward")
    {
        Mesh grid = test::open_grid(4, 4);
        const MeshDrawData d = draw_data(grid);
        std::vector<float> areas(3 * static_cast<size_t>(grid.face_count()));
        face_area_vectors(grid.positions, grid, areas);
        for (Index f = 0; f < grid.face_count(); ++f)
        {
            CHECK(areas[3 * f] == 0.0f);
            CHECK(areas[3 * f + 1] == 0.0f);
            CHECK(areas[3 * f + 2] == 1.0f); // unit squares, counter-clockwise from +z
        }
        std::vector<float> normals(grid.positions.size());
        vertex_normals(d, areas, normals);
        for (size_t i = 0; i < normals.size(); i += 3)
            CHECK(normals[i + 2] == 1.0f);

        const Mesh sphere = test::icosphere(2);
        const MeshDrawData ds = draw_data(sphere);
        std::vector<float> a(3 * static_cast<size_t>(sphere.face_count()));
        std::vector<float> n(sphere.positions.size());
        face_area_vectors(sphere.positions, sphere, a);
        vertex_normals(ds, a, n);
        for (size_t i = 0; i < n.size(); i += 3)
        {
            const double len = std::sqrt(double(n[i]) * n[i] + double(n[i + 1]) * n[i + 1] +
                                         double(n[i + 2]) * n[i + 2]);
            CHECK(len == doctest::Approx(1.0).epsilon(1e-6));
            const double outward = n[i] * sphere.positions[i] + n[i + 1] * sphere.positions[i + 1] +
                                   n[i + 2] * sphere.positions[i + 2];
            CHECK(outward > 0.99);
        }
    }

    TEST_CASE("normals are the same bits for any thread count")
    {
        Mesh sphere = test::icosphere(5); // above the parallel threshold
        test::perturb(sphere, 0.01, 7);
        const MeshDrawData d = draw_data(sphere);
        std::vector<std::vector<float>> results;
        for (const int threads : {1, 2, 3})
        {
            set_thread_count(threads);
            std::vector<float> a(3 * static_cast<size_t>(sphere.face_count()));
            std::vector<float> n(sphere.positions.size());
            face_area_vectors(sphere.positions, sphere, a);
            vertex_normals(d, a, n);
            results.push_back(n);
        }
        set_thread_count(0);
        CHECK(results[0] == results[1]);
        CHECK(results[0] == results[2]);
    }

    TEST_CASE("the triangle meshes' fast path gives the general Newell sum's bits")
    {
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.01, 3);
        std::vector<float> fast(3 * static_cast<size_t>(m.face_count()));
        face_area_vectors(m.positions, m, fast);
        // The general loop, written out: corner k with k + 1, the last with the first.
        for (Index f = 0; f < m.face_count(); ++f)
        {
            double n[3] = {0, 0, 0};
            const std::span<const Index> face = m.face(f);
            for (size_t k = 0; k < face.size(); ++k)
            {
                const double* p = &m.positions[3 * static_cast<size_t>(face[k])];
                const double* q =
                    &m.positions[3 * static_cast<size_t>(face[(k + 1) % face.size()])];
                n[0] += (p[1] - q[1]) * (p[2] + q[2]);
                n[1] += (p[2] - q[2]) * (p[0] + q[0]);
                n[2] += (p[0] - q[0]) * (p[1] + q[1]);
            }
            for (int a = 0; a < 3; ++a)
                REQUIRE(fast[3 * static_cast<size_t>(f) + a] == static_cast<float>(0.5 * n[a]));
        }
    }

    TEST_CASE("a vertex in no face gets a zero normal")
    {
        const Mesh m = test::with_isolated_vertex();
        const MeshDrawData d = draw_data(m);
        std::vector<float> a(3 * static_cast<size_t>(m.face_count()));
        std::vector<float> n(m.positions.size());
        face_area_vectors(m.positions, m, a);
        vertex_normals(d, a, n);
        const size_t last = n.size() - 3;
        CHECK(n[last] == 0.0f);
        CHECK(n[last + 1] == 0.0f);
        CHECK(n[last + 2] == 0.0f);
    }

    TEST_CASE("the changing part holds every face around a free vertex and every corner of those")
    {
        for (const Mesh& m : {test::icosphere(4), test::open_grid(40, 30), test::quad_cube(),
                              test::nonmanifold_fan()})
        {
            const MeshDrawData d = draw_data(m);
            // Runs and lone vertices (a large part: its faces marked), and a few vertices
            // (a brush's region: its faces listed as met).
            std::vector<Index> many, few;
            for (Index v = 0; v < m.vertex_count(); ++v)
            {
                if (v % 7 < 3 || v % 1000 == 999)
                    many.push_back(v);
                if (v % 50 == 7)
                    few.push_back(v);
            }
            for (const std::vector<Index>* free : {&many, &few})
                check_changing_part(m, d, *free);
        }
        // Nothing free: nothing changes.
        const Mesh grid = test::open_grid(3, 3);
        const MeshDrawData d = draw_data(grid);
        const ChangingPart none = changing_part(grid, d.vertex_face_offsets, d.vertex_faces, {});
        CHECK(none.vertices.count() == 0);
        CHECK(none.faces.count() == 0);
    }

    TEST_CASE("a run's frames recompute only the changing part, to the bits of a whole computation")
    {
        // In the locality numbering the editor keeps, where a region is a few ranges.
        Mesh sphere = test::icosphere(5); // above the parallel threshold
        test::perturb(sphere, 0.01, 11);
        const Mesh m = reorder_mesh(sphere, locality_order(sphere));
        const MeshDrawData d = draw_data(m);
        std::vector<Index> free; // a region and a scatter in it, as a region and pins leave
        for (Index v = 0; v < m.vertex_count() / 3; ++v)
            if (v < m.vertex_count() / 4 || v % 11 == 0)
                free.push_back(v);
        const auto part = std::make_shared<const ChangingPart>(
            changing_part(m, d.vertex_face_offsets, d.vertex_faces, free));
        const auto whole = [&](const std::vector<Scalar>& x) {
            DisplayGeometry g;
            update_display_geometry(x, m, d.vertex_face_offsets, d.vertex_faces, 0, nullptr, g);
            return g;
        };
        const std::uint64_t run = new_display_run();
        CHECK(run != 0);
        CHECK(new_display_run() != run);
        DisplayGeometry g;
        std::vector<Scalar> x = m.positions;
        for (int frame = 0; frame < 4; ++frame)
        {
            CAPTURE(frame);
            for (const Index v : free) // the free vertices move, nothing else
                for (int a = 0; a < 3; ++a)
                    x[3 * v + a] += 0.001 * std::sin(1.0 + frame + v + a);
            set_thread_count(frame % 2 == 0 ? 2 : 1);
            update_display_geometry(x, m, d.vertex_face_offsets, d.vertex_faces, run, part, g);
            const DisplayGeometry expected = whole(x);
            CHECK(g.run == run);
            CHECK(g.positions == expected.positions);
            CHECK(g.normals == expected.normals);
            CHECK(g.face_areas == expected.face_areas);
        }
        set_thread_count(0);
        // A vertex outside the changing part.
        Index outside = 0;
        for (size_t k = 0; k < part->vertices.begin.size() && part->vertices.begin[k] == outside;
             ++k)
            outside = part->vertices.end[k];
        REQUIRE(outside < m.vertex_count());
        const size_t at = 3 * static_cast<size_t>(outside);
        // Only the changing part is recomputed: a value outside it is left as it was.
        g.positions[at] = 1e6f;
        update_display_geometry(x, m, d.vertex_face_offsets, d.vertex_faces, run, part, g);
        CHECK(g.positions[at] == 1e6f);
        // A frame of another run is computed whole, whatever g held.
        std::vector<Scalar> moved = x;
        moved[at] += 0.01; // a pin moved: outside the changing part
        update_display_geometry(moved, m, d.vertex_face_offsets, d.vertex_faces, new_display_run(),
                                part, g);
        CHECK(g.positions == whole(moved).positions);
        CHECK(g.normals == whole(moved).normals);
    }
}
