// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/topology/topology.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "core/io/io.h"
#include "core/parallel/parallel.h"
#include "core/topology/edge_graph.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

struct Expected
{
    Index edges, boundary, regular, singular, dual, components, isolated;
};

void check_counts(const Mesh& m, const Expected& e)
{
    const Topology t = build_topology(m);
    CHECK(t.edge_count() == e.edges);
    CHECK(t.boundary_edge_count == e.boundary);
    CHECK(t.regular_edge_count == e.regular);
    CHECK(t.singular_edge_count == e.singular);
    CHECK(t.dual_edge_count() == e.dual);
    const TopologySummary s = summarize(t);
    CHECK(s.components == e.components);
    CHECK(s.isolated_vertices == e.isolated);
}

// Invariants that hold for every mesh: each checked against the faces directly.
void check_invariants(const Mesh& m)
{
    const Topology t = build_topology(m);
    // Edges unique, stored with i < j.
    std::set<std::pair<Index, Index>> edges;
    for (Index e = 0; e < t.edge_count(); ++e)
    {
        const Index i = t.edge_vertices[2 * e], j = t.edge_vertices[2 * e + 1];
        REQUIRE(i < j);
        edges.insert({i, j});
    }
    CHECK(edges.size() == static_cast<size_t>(t.edge_count()));
    // Every corner's edge joins it to the next corner; F(e) holds its face.
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const auto face = m.face(f);
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Index c = m.face_offsets[f] + static_cast<Index>(k);
            const Index e = t.corner_edge[c];
            const auto [a, b] = std::minmax(face[k], face[(k + 1) % face.size()]);
            CHECK(t.edge_vertices[2 * e] == a);
            CHECK(t.edge_vertices[2 * e + 1] == b);
            const auto faces = t.faces_of_edge(e);
            CHECK(std::find(faces.begin(), faces.end(), f) != faces.end());
            CHECK(t.face_of_corner(c) == f);
        }
    }
    // corner_face is held only where faces are not all triangles.
    bool triangles = true;
    for (Index f = 0; f < m.face_count(); ++f)
        triangles = triangles && m.face_size(f) == 3;
    CHECK(t.triangles == triangles);
    CHECK(t.corner_face.empty() == triangles);
    // sum n_e = corners; sum n_i = 2 #E; neighbours symmetric.
    CHECK(t.edge_faces.size() == static_cast<size_t>(m.corner_count()));
    CHECK(t.vertex_neighbors.size() == 2 * static_cast<size_t>(t.edge_count()));
    for (Index i = 0; i < t.vertex_count; ++i)
        for (const Index j : t.neighbors(i))
        {
            const auto back = t.neighbors(j);
            CHECK(std::find(back.begin(), back.end(), i) != back.end());
        }
    // Dual neighbours: symmetric, and each pair shares a regular edge.
    for (Index f = 0; f < t.face_count; ++f)
        for (const Index g : t.face_neighbors_of(f))
        {
            const auto back = t.face_neighbors_of(g);
            CHECK(std::find(back.begin(), back.end(), f) != back.end());
        }
    CHECK(t.boundary_edge_count + t.regular_edge_count + t.singular_edge_count == t.edge_count());
    // The counts (taken from the corners) agree with F(e) (taken from the edge hash), and
    // V(i) is increasing and holds exactly the other ends of the edges at i.
    Index kinds[3] = {0, 0, 0};
    for (Index e = 0; e < t.edge_count(); ++e)
        ++kinds[static_cast<int>(t.edge_kind(e))];
    CHECK(kinds[0] == t.boundary_edge_count);
    CHECK(kinds[1] == t.regular_edge_count);
    CHECK(kinds[2] == t.singular_edge_count);
    std::vector<std::set<Index>> ends(static_cast<size_t>(t.vertex_count));
    for (Index e = 0; e < t.edge_count(); ++e)
    {
        ends[t.edge_vertices[2 * e]].insert(t.edge_vertices[2 * e + 1]);
        ends[t.edge_vertices[2 * e + 1]].insert(t.edge_vertices[2 * e]);
    }
    for (Index i = 0; i < t.vertex_count; ++i)
    {
        const auto v = t.neighbors(i);
        CHECK(std::is_sorted(v.begin(), v.end()));
        CHECK(std::set<Index>(v.begin(), v.end()) == ends[i]);
    }
}

// Each part of a topology built with `parts` equals the same part of the whole one; the
// parts not asked for are empty; the counts are always there.
void check_parts(const Mesh& m, TopologyParts parts)
{
    const Topology all = build_topology(m);
    const Topology t = build_topology(m, parts);
    CAPTURE(static_cast<unsigned>(parts));
    CHECK(t.parts == parts);
    CHECK(t.edge_count() == all.edge_count());
    CHECK(t.boundary_edge_count == all.boundary_edge_count);
    CHECK(t.regular_edge_count == all.regular_edge_count);
    CHECK(t.singular_edge_count == all.singular_edge_count);
    const auto same_or_empty = [&](TopologyParts part, const std::vector<Index>& got,
                                   const std::vector<Index>& whole) {
        if (has_parts(parts, part))
            CHECK(got == whole);
        else
            CHECK(got.empty());
    };
    same_or_empty(TopologyParts::Neighbors, t.vertex_offsets, all.vertex_offsets);
    same_or_empty(TopologyParts::Neighbors, t.vertex_neighbors, all.vertex_neighbors);
    same_or_empty(TopologyParts::Corners, t.vertex_corner_offsets, all.vertex_corner_offsets);
    same_or_empty(TopologyParts::Corners, t.vertex_corners, all.vertex_corners);
    same_or_empty(TopologyParts::Corners, t.corner_face, all.corner_face);
    same_or_empty(TopologyParts::Edges, t.edge_vertices, all.edge_vertices);
    same_or_empty(TopologyParts::Edges, t.corner_edge, all.corner_edge);
    same_or_empty(TopologyParts::Edges, t.edge_faces, all.edge_faces);
    same_or_empty(TopologyParts::Dual, t.dual_edge_faces, all.dual_edge_faces);
    same_or_empty(TopologyParts::Dual, t.face_neighbors, all.face_neighbors);
}

// The paper's construction, literally: get/insert over the face corners into the
// EdgeGraph hash, n_e counted as insert() and get() meet each edge, F(e) filled in corner
// order, then the dual edges inserted over the regular edges in edge order.
struct PaperEdges
{
    std::vector<Index> edge_vertices, corner_edge, edge_faces, dual_edge_faces, face_neighbors;
};

PaperEdges paper_edges(const Mesh& m)
{
    PaperEdges p;
    EdgeGraph graph(static_cast<size_t>(m.corner_count()));
    std::vector<Index> n_e;
    p.corner_edge.resize(static_cast<size_t>(m.corner_count()));
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const auto face = m.face(f);
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Index i = face[k], j = face[(k + 1) % face.size()];
            Index e = graph.get(i, j);
            if (e == kInvalidIndex)
            {
                e = graph.insert(i, j);
                n_e.push_back(1);
            }
            else
                ++n_e[static_cast<size_t>(e)];
            p.corner_edge[static_cast<size_t>(m.face_offsets[f]) + k] = e;
        }
    }
    p.edge_vertices = graph.release_pairs();
    std::vector<std::vector<Index>> faces_of(n_e.size());
    for (Index c = 0; c < m.corner_count(); ++c)
    {
        const auto f =
            static_cast<Index>(std::upper_bound(m.face_offsets.begin(), m.face_offsets.end(), c) -
                               m.face_offsets.begin() - 1);
        faces_of[static_cast<size_t>(p.corner_edge[static_cast<size_t>(c)])].push_back(f);
    }
    EdgeGraph dual(16);
    for (const auto& faces : faces_of)
    {
        p.edge_faces.insert(p.edge_faces.end(), faces.begin(), faces.end());
        if (faces.size() == 2)
            dual.insert(faces[0], faces[1]);
    }
    p.dual_edge_faces = dual.release_pairs();
    std::vector<std::vector<Index>> neighbors(static_cast<size_t>(m.face_count()));
    for (size_t d = 0; d < p.dual_edge_faces.size(); d += 2)
    {
        neighbors[static_cast<size_t>(p.dual_edge_faces[d])].push_back(p.dual_edge_faces[d + 1]);
        neighbors[static_cast<size_t>(p.dual_edge_faces[d + 1])].push_back(p.dual_edge_faces[d]);
    }
    for (const auto& n : neighbors)
        p.face_neighbors.insert(p.face_neighbors.end(), n.begin(), n.end());
    return p;
}

void check_against_paper(const Mesh& m)
{
    const Topology t = build_topology(m);
    const PaperEdges p = paper_edges(m);
    CHECK(t.edge_vertices == p.edge_vertices);
    CHECK(t.corner_edge == p.corner_edge);
    CHECK(t.edge_faces == p.edge_faces);
    CHECK(t.dual_edge_faces == p.dual_edge_faces);
    CHECK(t.face_neighbors == p.face_neighbors);
}

} // namespace

TEST_SUITE("Topology")
{
    TEST_CASE("edges, F(e) and the dual graph are numbered exactly as the paper's get/insert")
    {
        test::ThreadCountGuard guard;
        Mesh folded; // two quads sharing two regular edges: one dual edge
        for (int k = 0; k < 5; ++k)
            folded.add_vertex(k, k * k, 0);
        folded.add_face(std::vector<Index>{0, 1, 2, 3});
        folded.add_face(std::vector<Index>{2, 1, 0, 4});
        for (const Mesh& m :
             {test::tetrahedron(), test::quad_cube(), test::open_grid(4, 3),
              test::nonmanifold_fan(), test::two_components(), test::with_isolated_vertex(),
              test::mixed_polygons(), test::quad_torus(6, 5, 2, 1), folded})
            check_against_paper(m);
        // The bunny as stored and with its faces and vertices shuffled (any file order),
        // on one, two and three threads.
        const Mesh bunny = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        Mesh shuffled;
        std::vector<Index> to(static_cast<size_t>(bunny.vertex_count()));
        for (Index v = 0; v < bunny.vertex_count(); ++v)
            to[static_cast<size_t>(v)] =
                static_cast<Index>((static_cast<std::int64_t>(v) * 7919) % bunny.vertex_count());
        shuffled.positions.resize(bunny.positions.size());
        for (Index v = 0; v < bunny.vertex_count(); ++v)
            for (int a = 0; a < 3; ++a)
                shuffled.positions[3 * static_cast<size_t>(to[static_cast<size_t>(v)]) + a] =
                    bunny.positions[3 * static_cast<size_t>(v) + a];
        for (Index k = 0; k < bunny.face_count(); ++k)
        {
            const Index f =
                static_cast<Index>((static_cast<std::int64_t>(k) * 104729) % bunny.face_count());
            std::vector<Index> face;
            for (const Index v : bunny.face(f))
                face.push_back(to[static_cast<size_t>(v)]);
            shuffled.add_face(face);
        }
        for (const int threads : {1, 2, 3})
        {
            CAPTURE(threads);
            set_thread_count(threads);
            check_against_paper(bunny);
            check_against_paper(shuffled);
        }
    }

    TEST_CASE("counts on hand-built meshes")
    {
        check_counts(test::tetrahedron(), {6, 0, 6, 0, 6, 1, 0});
        check_counts(test::quad_cube(), {12, 0, 12, 0, 12, 1, 0});
        check_counts(test::open_grid(3, 2), {17, 10, 7, 0, 7, 1, 0});
        check_counts(test::nonmanifold_fan(), {7, 6, 0, 1, 0, 1, 0});
        check_counts(test::two_components(), {6, 6, 0, 0, 0, 2, 0});
        check_counts(test::with_isolated_vertex(), {3, 3, 0, 0, 0, 2, 1});
        check_counts(test::mixed_polygons(), {19, 11, 8, 0, 8, 1, 0});
    }

    TEST_CASE("a point cloud has vertices and nothing else")
    {
        Mesh m;
        m.add_vertex(0, 0, 0);
        m.add_vertex(1, 0, 0);
        check_counts(m, {0, 0, 0, 0, 0, 2, 2});
        const Topology t = build_topology(m);
        CHECK(t.valence(0) == 0);
    }

    TEST_CASE("edges are numbered in order of first appearance, as insert() assigns them")
    {
        const Topology t = build_topology(test::tetrahedron());
        // Faces (0,1,2), (0,3,1), ...: edges 01, 12, 02, then 03, 13.
        const std::vector<Index> expected{0, 1, 1, 2, 0, 2, 0, 3, 1, 3};
        CHECK(std::equal(expected.begin(), expected.end(), t.edge_vertices.begin()));
    }

    TEST_CASE("the singular edge of a fan has its three faces and valence counts them once")
    {
        const Mesh m = test::nonmanifold_fan();
        const Topology t = build_topology(m);
        const Index e = t.corner_edge[0]; // edge (0, 1)
        CHECK(t.edge_kind(e) == EdgeKind::Singular);
        CHECK(t.edge_face_count(e) == 3);
        CHECK(t.valence(0) == 4);
    }

    TEST_CASE("quad faces have n_f = 4 edges and quad-cube vertices have n_i = 3")
    {
        const Topology t = build_topology(test::quad_cube());
        for (Index i = 0; i < 8; ++i)
            CHECK(t.valence(i) == 3);
        for (Index f = 0; f < 6; ++f)
            CHECK(t.dual_valence(f) == 4);
    }

    TEST_CASE("two faces sharing two regular edges form one dual edge")
    {
        // Two quads glued along two consecutive edges (a folded pair): 0-1-2 shared.
        Mesh m;
        for (int k = 0; k < 5; ++k)
            m.add_vertex(k, k * k, 0);
        const std::vector<Index> a{0, 1, 2, 3}, b{2, 1, 0, 4};
        m.add_face(a);
        m.add_face(b);
        const Topology t = build_topology(m);
        CHECK(t.regular_edge_count == 2);
        CHECK(t.dual_edge_count() == 1);
        CHECK(t.dual_valence(0) == 1);
    }

    TEST_CASE("invariants hold on every fixture and on the bundled bunny")
    {
        for (const Mesh& m :
             {test::tetrahedron(), test::quad_cube(), test::open_grid(4, 3),
              test::nonmanifold_fan(), test::two_components(), test::with_isolated_vertex(),
              test::mixed_polygons(), test::quad_torus(6, 5, 2, 1), test::icosphere(2)})
            check_invariants(m);
        const Mesh bunny = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        check_invariants(bunny);
        const Topology t = build_topology(bunny);
        // Closed surface of genus 0: V - E + F = 2.
        CHECK(bunny.vertex_count() - t.edge_count() + bunny.face_count() == 2);
    }

    TEST_CASE("any set of parts is the same as in the whole topology")
    {
        const Mesh bunny = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        for (const Mesh& m :
             {test::tetrahedron(), test::quad_cube(), test::open_grid(4, 3),
              test::nonmanifold_fan(), test::with_isolated_vertex(), test::mixed_polygons(), bunny})
            for (unsigned bits = 0; bits < 16; ++bits)
                check_parts(m, static_cast<TopologyParts>(bits));
    }

    TEST_CASE("closed fixtures satisfy Euler's formula")
    {
        const Mesh torus = test::quad_torus(8, 6, 2, 0.5);
        const Topology tt = build_topology(torus);
        CHECK(torus.vertex_count() - tt.edge_count() + torus.face_count() == 0);
        const Mesh sphere = test::icosphere(3);
        const Topology ts = build_topology(sphere);
        CHECK(sphere.vertex_count() - ts.edge_count() + sphere.face_count() == 2);
        CHECK(ts.boundary_edge_count == 0);
    }
}

TEST_SUITE("EdgeGraph")
{
    TEST_CASE("get and insert on unordered pairs")
    {
        EdgeGraph g(2);
        CHECK(g.get(3, 1) == kInvalidIndex);
        CHECK(g.insert(3, 1) == 0);
        CHECK(g.get(1, 3) == 0);
        CHECK(g.insert(1, 3) == 0);
        CHECK(g.insert(2, 5) == 1);
        CHECK(g.pairs() == std::vector<Index>{1, 3, 2, 5});
    }

    TEST_CASE("grows past its initial estimate and keeps every pair")
    {
        EdgeGraph g(4);
        for (Index i = 0; i < 5000; ++i)
            CHECK(g.insert(i, i + 7) == i);
        for (Index i = 0; i < 5000; ++i)
            CHECK(g.get(i + 7, i) == i);
        CHECK(g.get(1, 2) == kInvalidIndex);
    }
}
