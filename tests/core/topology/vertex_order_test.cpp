// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/topology/vertex_order.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <queue>
#include <random>
#include <set>
#include <utility>

#include "core/io/io.h"
#include "core/topology/topology.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::test;

namespace {

bool is_permutation_of_range(const std::vector<Index>& order, Index n)
{
    std::vector<Index> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    return sorted == all_indices(n);
}

std::set<std::pair<Index, Index>> edge_set(const Topology& t, const std::vector<Index>& rename)
{
    std::set<std::pair<Index, Index>> edges;
    for (Index e = 0; e < t.edge_count(); ++e)
        edges.insert(
            std::minmax(rename[t.edge_vertices[2 * e]], rename[t.edge_vertices[2 * e + 1]]));
    return edges;
}

// The properties of breadth_first_order and renumber_vertices on one mesh.
void check_order(const Mesh& mesh)
{
    const Topology t = build_topology(mesh);
    const std::vector<Index> order = breadth_first_order(mesh);
    REQUIRE(is_permutation_of_range(order, mesh.vertex_count()));
    if (mesh.vertex_count() > 0)
        CHECK(order[0] == 0);
    // Breadth-first: every vertex after the first of its component has a neighbour
    // placed before it, and the graph distance from the root never decreases.
    const std::vector<Index> position = inverse_permutation(order);
    for (size_t k = 0; k < order.size(); ++k)
        CHECK(position[order[k]] == static_cast<Index>(k));
    std::vector<Index> depth(order.size(), -1);
    for (const Index i : order)
    {
        Index parent_depth = -1;
        for (const Index j : t.neighbors(i))
            if (position[j] < position[i] && depth[j] >= 0 &&
                (parent_depth < 0 || depth[j] < parent_depth))
                parent_depth = depth[j];
        depth[i] = parent_depth + 1; // a root (no earlier neighbour) starts at 0
    }
    for (size_t k = 1; k < order.size(); ++k)
        if (depth[order[k]] != 0)
            CHECK(depth[order[k]] >= depth[order[k - 1]]);

    // Renumbering moves positions with their vertex and keeps the faces' shape.
    const Mesh renamed = renumber_vertices(mesh, order);
    validate_mesh(renamed);
    REQUIRE(renamed.vertex_count() == mesh.vertex_count());
    CHECK(renamed.face_offsets == mesh.face_offsets);
    for (Index k = 0; k < mesh.vertex_count(); ++k)
        CHECK(renamed.position(k) == mesh.position(order[k]));
    for (Index f = 0; f < mesh.face_count(); ++f)
        for (size_t c = 0; c < mesh.face(f).size(); ++c)
            CHECK(renamed.face(f)[c] == position[mesh.face(f)[c]]);
    // The same graph under the renaming, and the inverse renaming gives the mesh back.
    CHECK(edge_set(build_topology(renamed), all_indices(mesh.vertex_count())) ==
          edge_set(t, position));
    CHECK(renumber_vertices(renamed, position) == mesh);
}

} // namespace

TEST_CASE("breadth_first_order and renumber_vertices on the synthetic meshes")
{
    for (const Mesh& m : {tetrahedron(), quad_cube(), open_grid(5, 3), nonmanifold_fan(),
                          two_components(), with_isolated_vertex(), mixed_polygons(), Mesh{}})
        check_order(m);
}

TEST_CASE("breadth_first_order: components are contiguous, each from its lowest vertex")
{
    const Mesh m = two_components(); // vertices 0-2 and 3-5
    const std::vector<Index> order = breadth_first_order(m);
    REQUIRE(order.size() == 6);
    CHECK(std::set<Index>(order.begin(), order.begin() + 3) == std::set<Index>{0, 1, 2});
    CHECK(order[3] == 3);
    const std::vector<Index> isolated = breadth_first_order(with_isolated_vertex());
    CHECK(isolated.back() == 3); // the unused vertex is a component of its own
}

TEST_CASE("breadth_first_order narrows the neighbour band of a shuffled grid")
{
    // A 40 x 40 grid numbered at random: the largest |i - j| over the edges is near #V;
    // after breadth-first renumbering it is about two BFS levels (< 3 * 41 here).
    Mesh grid = open_grid(40, 40);
    std::vector<Index> shuffle = all_indices(grid.vertex_count());
    std::reverse(shuffle.begin() + 1, shuffle.end());
    for (size_t k = 0; k + 7 < shuffle.size(); k += 7)
        std::swap(shuffle[k], shuffle[k + 5]);
    const Mesh shuffled = renumber_vertices(grid, shuffle);
    const auto bandwidth = [](const Mesh& m) {
        const Topology t = build_topology(m);
        Index widest = 0;
        for (Index e = 0; e < t.edge_count(); ++e)
            widest = std::max(widest, t.edge_vertices[2 * e + 1] - t.edge_vertices[2 * e]);
        return widest;
    };
    REQUIRE(bandwidth(shuffled) > 1000);
    const Mesh ordered = renumber_vertices(shuffled, breadth_first_order(shuffled));
    CHECK(bandwidth(ordered) < 3 * 41);
}

TEST_CASE("breadth_first_order and renumbering on the bunny")
{
    check_order(io::read_mesh((assets_dir() / "bunny.obj").string()));
}

TEST_CASE("locality_order: permutations, faces sorted by first vertex, exact round trip")
{
    for (const Mesh& m : {tetrahedron(), quad_cube(), open_grid(6, 4), nonmanifold_fan(),
                          two_components(), with_isolated_vertex(), mixed_polygons(),
                          io::read_mesh((assets_dir() / "bunny.obj").string())})
    {
        const LocalityOrder o = locality_order(m);
        REQUIRE(is_permutation_of_range(o.vertex_order, m.vertex_count()));
        REQUIRE(is_permutation_of_range(o.face_order, m.face_count()));
        CHECK(o.vertex_index == inverse_permutation(o.vertex_order));
        CHECK(o.face_index == inverse_permutation(o.face_order));
        const Mesh w = reorder_mesh(m, o);
        validate_mesh(w);
        Index previous_key = 0;
        for (Index g = 0; g < w.face_count(); ++g)
        {
            const auto face = w.face(g);
            const auto file_face = m.face(o.face_order[g]);
            REQUIRE(face.size() == file_face.size());
            for (size_t c = 0; c < face.size(); ++c)
                CHECK(face[c] == o.vertex_index[file_face[c]]); // same corners, same order
            const Index key = *std::min_element(face.begin(), face.end());
            CHECK(key >= previous_key);
            previous_key = key;
        }
        std::vector<Scalar> back(m.positions.size(), -1);
        positions_to_file_order(w.positions, o, back);
        CHECK(back == m.positions);
        // The inverse order brings the whole mesh back, faces and corners included.
        const Mesh again = reorder_mesh(w, inverse_order(o));
        CHECK(again.positions == m.positions);
        CHECK(again.face_offsets == m.face_offsets);
        CHECK(again.face_vertices == m.face_vertices);
    }
}

TEST_CASE("breadth_first_order is the textbook queue's order, far past its read-ahead")
{
    // The visit reads ahead along its queue and its corners; the order must be the plain
    // queue's: each vertex's corners in face order, the previous then the next vertex of
    // each. A shuffled grid of 4,900 vertices (about 29,000 corners) runs far past the
    // read-ahead distances, and the ends of the queue run into them.
    const Mesh grid = open_grid(70, 70);
    std::vector<Index> shuffle = all_indices(grid.vertex_count());
    std::mt19937 random(7);
    std::shuffle(shuffle.begin(), shuffle.end(), random);
    const Mesh m = renumber_vertices(grid, shuffle);
    std::vector<std::vector<Index>> around(static_cast<size_t>(m.vertex_count()));
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const auto face = m.face(f);
        for (size_t c = 0; c < face.size(); ++c)
        {
            around[face[c]].push_back(face[(c + face.size() - 1) % face.size()]);
            around[face[c]].push_back(face[(c + 1) % face.size()]);
        }
    }
    std::vector<Index> expected;
    std::vector<bool> seen(around.size(), false);
    for (Index root = 0; root < m.vertex_count(); ++root)
    {
        if (seen[root])
            continue;
        std::queue<Index> queue;
        queue.push(root);
        seen[root] = true;
        for (; !queue.empty(); queue.pop())
        {
            expected.push_back(queue.front());
            for (const Index j : around[queue.front()])
                if (!seen[j])
                {
                    seen[j] = true;
                    queue.push(j);
                }
        }
    }
    CHECK(breadth_first_order(m) == expected);
}
