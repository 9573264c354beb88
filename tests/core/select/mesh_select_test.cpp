// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/select/mesh_select.h"

#include <doctest/doctest.h>

#include "core/parallel/parallel.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

Topology topology_of(const Mesh& m)
{
    return build_topology(m, TopologyParts::All);
}

SelectionMask mask_of(size_t n, std::vector<Index> selected)
{
    SelectionMask m(n, 0);
    apply_selection(m, selected, SelectOp::Add);
    return m;
}

} // namespace

TEST_SUITE("MeshSelect")
{
    TEST_CASE("replace, add and subtract combine a tool's elements with the selection")
    {
        SelectionMask m(6, 0);
        apply_selection(m, std::vector<Index>{1, 2}, SelectOp::Add);
        apply_selection(m, std::vector<Index>{4}, SelectOp::Add);
        CHECK(selected_indices(m) == std::vector<Index>{1, 2, 4});
        apply_selection(m, std::vector<Index>{2, 5}, SelectOp::Subtract);
        CHECK(selected_indices(m) == std::vector<Index>{1, 4});
        apply_selection(m, std::vector<Index>{0}, SelectOp::Replace);
        CHECK(selected_indices(m) == std::vector<Index>{0});
        invert_selection(m);
        CHECK(selected_indices(m) == std::vector<Index>{1, 2, 3, 4, 5});
    }

    TEST_CASE("on a grid, grow then shrink a vertex ring returns the centre")
    {
        // 5 x 5 quads, 6 x 6 vertices; vertex 14 is (2, 2).
        const Mesh g = test::open_grid(5, 5);
        const Topology t = topology_of(g);
        const SelectionMask centre = mask_of(36, {14});
        const SelectionMask grown = grow_vertices(t, centre);
        // V(i) of a grid vertex: the 4 edge neighbours (quads share no diagonal edge).
        CHECK(selected_indices(grown) == std::vector<Index>{8, 13, 14, 15, 20});
        CHECK(selected_indices(shrink_vertices(t, grown)) == std::vector<Index>{14});
        CHECK(selected_indices(shrink_vertices(t, centre)).empty());
    }

    TEST_CASE("on a grid, faces grow by the faces sharing a vertex, and shrink back")
    {
        const Mesh g = test::open_grid(5, 5);
        const Topology t = topology_of(g);
        const SelectionMask one = mask_of(25, {12}); // the middle quad
        const SelectionMask grown = grow_faces(g, t, one);
        CHECK(selected_indices(grown) == std::vector<Index>{6, 7, 8, 11, 12, 13, 16, 17, 18});
        CHECK(selected_indices(shrink_faces(g, t, grown)) == std::vector<Index>{12});
    }

    TEST_CASE("connected components, through edges for faces, and the two disjoint triangles")
    {
        const Mesh two = test::two_components();
        const Topology t = topology_of(two);
        CHECK(selected_indices(connected_vertices(t, std::vector<Index>{4})) ==
              std::vector<Index>{3, 4, 5});
        CHECK(selected_indices(connected_faces(two, t, std::vector<Index>{0})) ==
              std::vector<Index>{0});
        const Mesh fan = test::nonmanifold_fan(); // three faces on one singular edge
        const Topology tf = topology_of(fan);
        CHECK(selected_indices(connected_faces(fan, tf, std::vector<Index>{2})) ==
              std::vector<Index>{0, 1, 2});
    }

    TEST_CASE("the boundary of an open grid, a closed cube has none")
    {
        const Mesh g = test::open_grid(3, 2);
        const Topology t = topology_of(g);
        const SelectionMask b = boundary_vertices(t);
        CHECK(selected_indices(b).size() == 10); // all but the 2 inner vertices
        CHECK(b[5] == 0);
        CHECK(b[6] == 0);
        CHECK(selected_indices(boundary_faces(g, t)).size() == 6); // every quad touches it
        const Mesh cube = test::quad_cube();
        const Topology tc = topology_of(cube);
        CHECK(selected_indices(boundary_vertices(tc)).empty());
        CHECK(selected_indices(boundary_faces(cube, tc)).empty());
    }

    TEST_CASE("faces and vertices convert both ways")
    {
        const Mesh g = test::open_grid(2, 2);
        const SelectionMask f = mask_of(4, {0});
        CHECK(selected_indices(vertices_of_faces(g, f)) == std::vector<Index>{0, 1, 3, 4});
        CHECK(selected_indices(faces_of_vertices(g, vertices_of_faces(g, f))) ==
              std::vector<Index>{0});
    }

    TEST_CASE("grow and shrink give the same flags for any thread count")
    {
        Mesh sphere = test::icosphere(5);
        const Topology t = topology_of(sphere);
        SelectionMask seed(static_cast<size_t>(sphere.vertex_count()), 0);
        for (size_t k = 0; k < seed.size(); k += 97)
            seed[k] = 1;
        std::vector<SelectionMask> results;
        for (const int threads : {1, 2, 3})
        {
            set_thread_count(threads);
            results.push_back(shrink_vertices(t, grow_vertices(t, grow_vertices(t, seed))));
        }
        set_thread_count(0);
        CHECK(results[0] == results[1]);
        CHECK(results[0] == results[2]);
        CHECK(selected_indices(results[0]).size() > selected_indices(seed).size());
    }
}
