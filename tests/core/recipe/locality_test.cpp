// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Solving in the locality numbering (what meshfair-cli does) gives the result of solving
// in the file's numbering: renumber_recipe maps every index list and every per-element
// list of a recipe (targets, normals, weights).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "core/recipe/locality_run.h"
#include "core/recipe/recipe.h"
#include "core/recipe/session.h"
#include "core/topology/vertex_order.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

std::vector<Scalar> smooth_in_file_order(Mesh mesh, const Recipe& recipe)
{
    smooth(mesh, build_topology(mesh), recipe);
    return mesh.positions;
}

std::vector<Scalar> smooth_in_locality_order(const Mesh& mesh, const Recipe& recipe)
{
    check_recipe(recipe, mesh);
    const LocalityOrder order = locality_order(mesh);
    Mesh work = reorder_mesh(mesh, order);
    smooth(work, build_topology(work),
           renumber_recipe(recipe, order.vertex_index, order.face_index));
    std::vector<Scalar> out(mesh.positions.size());
    positions_to_file_order(work.positions, order, out);
    return out;
}

Scalar relative_difference(const std::vector<Scalar>& a, const std::vector<Scalar>& b)
{
    Scalar diff = 0, scale = 0;
    for (size_t k = 0; k < a.size(); ++k)
    {
        diff = std::max(diff, std::abs(a[k] - b[k]));
        scale = std::max(scale, std::abs(a[k]));
    }
    return diff / scale;
}

Vec3 direction(int k)
{
    const Scalar a = 0.7 * k;
    return {std::cos(a), std::sin(a), 0.5};
}

} // namespace

TEST_SUITE("Session")
{
    TEST_CASE("solving in the locality numbering gives the file-numbering result")
    {
        Mesh m = test::quad_torus(16, 10, 1.0, 0.35);
        test::perturb(m, 0.02, 3);
        const Index nv = m.vertex_count(), nf = m.face_count();
        const LocalityOrder order = locality_order(m);
        REQUIRE(order.vertex_order != test::all_indices(nv)); // the test renumbers something
        REQUIRE(order.face_order != test::all_indices(nf));

        // Index lists everywhere, with per-element targets and normals.
        Recipe lists;
        lists.iterations = 6;
        lists.optimal_step = true;
        lists.region = Region{{3, 4, 5, 40, 41, 90, 91, 92, 93, 120}, {7, 8, 60, 61, 62, 100}};
        lists.hard = HardVertices{{4, 41}, {{1.3, 0.1, 0.2}, {0.2, 1.2, -0.1}}};
        lists.soft.emplace();
        lists.soft->vertices.indices = {5, 90, 92};
        lists.soft->mu = 0.4;
        lists.soft->targets = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        lists.centroid.emplace();
        lists.centroid->faces.indices = {8, 61, 100};
        lists.centroid->mu = 2.0;
        lists.centroid->targets = {{1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
        lists.centroid->denominator = CentroidDenominator::Exact;
        lists.normal.emplace();
        lists.normal->faces.indices = {7, 60, 62};
        lists.normal->source = NormalSource::Custom;
        lists.normal->normals = {direction(1), direction(2), direction(3)};

        // "all" lists, whose targets follow the elements' own order, and normal smoothing
        // with hard and soft normals, in joint mode.
        Recipe all;
        all.iterations = 5;
        // (Member by member: GCC 12 warns falsely on nested aggregate temporaries here.)
        all.soft.emplace();
        all.soft->vertices.all = true;
        all.soft->mu = 0.2;
        for (Index i = 0; i < nv; ++i)
            all.soft->targets.push_back({0.01 * i, 0, 0});
        all.centroid.emplace();
        all.centroid->faces.all = true;
        for (Index f = 0; f < nf; ++f)
            all.centroid->targets.push_back({0, 0.01 * f, 0});
        all.normal.emplace();
        all.normal->faces.all = true;
        all.normal->mu = 0.5;
        all.normal->source = NormalSource::Custom;
        for (Index f = 0; f < nf; ++f)
            all.normal->normals.push_back(direction(f));
        Recipe smoothed = all;
        smoothed.normal->source = NormalSource::Smoothed;
        smoothed.normal->normals.clear();
        smoothed.normal_smoothing =
            NormalSmoothing{4, 0.5, {{2, 9}, {}}, {{11, 12}, 0.5, {direction(7), direction(8)}}};
        smoothed.joint = Joint{0.5};

        // The same with a weight per element: weights follow their elements.
        const auto ramp = [](size_t n) {
            std::vector<Scalar> w(n);
            for (size_t k = 0; k < n; ++k)
                w[k] = 0.25 + static_cast<Scalar>(k % 9);
            return w;
        };
        Recipe weighted_lists = lists;
        weighted_lists.soft->weights = {3.0, 0.0, 0.5};
        weighted_lists.centroid->weights = {0.5, 4.0, 1.0};
        weighted_lists.normal->weights = {2.0, 0.25, 1.0};
        Recipe weighted_all = smoothed;
        weighted_all.soft->weights = ramp(static_cast<size_t>(nv));
        weighted_all.centroid->weights = ramp(static_cast<size_t>(nf));
        weighted_all.normal->weights = ramp(static_cast<size_t>(nf));
        weighted_all.normal_smoothing->soft.weights = {0.5, 2.0};

        const std::pair<const char*, const Recipe*> recipes[] = {
            {"lists", &lists},
            {"all", &all},
            {"smoothed", &smoothed},
            {"weighted lists", &weighted_lists},
            {"weighted all", &weighted_all}};
        for (const auto& entry : recipes)
        {
            // (Not a structured binding: clang 14 cannot capture one in CAPTURE's lambda.)
            const char* name = entry.first;
            const Recipe* recipe = entry.second;
            CAPTURE(name);
            const std::vector<Scalar> file = smooth_in_file_order(m, *recipe);
            const std::vector<Scalar> local = smooth_in_locality_order(m, *recipe);
            CHECK(relative_difference(file, m.positions) > 1e-4); // something moved
            CHECK(relative_difference(local, file) < 1e-12);
        }
    }

    TEST_CASE("a run restarted on the topology of the run before gives the same bits")
    {
        // What the editor does at each dab of the smoothing brush: a new recipe (other
        // weights) on the same mesh, its topology taken from the run before.
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.03, 11);
        const LocalityOrder order = locality_order(m);
        const Mesh work = reorder_mesh(m, order);
        Recipe first;
        first.iterations = 5;
        first.region = Region{test::all_indices(work.vertex_count() / 2), {}};
        Recipe second = first;
        second.soft = SoftVertices{};
        second.soft->vertices.indices = {0, 1, 2, 3};
        second.soft->weights = {3.0, 1.0, 0.5, 0.25};
        REQUIRE(required_topology(first) == required_topology(second));

        LocalityRun before(work, order, first);
        before.step();
        LocalityRun reused(work, order, second, std::move(before).take_topology());
        LocalityRun fresh(work, order, second);
        for (int k = 0; k < 5; ++k)
        {
            reused.step();
            fresh.step();
        }
        CHECK(std::equal(reused.session().positions().begin(), reused.session().positions().end(),
                         fresh.session().positions().begin(), fresh.session().positions().end()));
        CHECK(fresh.session().positions()[0] != work.positions[0]); // something moved

        // A topology of other parts (or another mesh) is refused, not used.
        Recipe normals = second;
        normals.normal = NormalConstraints{};
        normals.normal->faces.all = true;
        CHECK_THROWS_AS(
            LocalityRun(work, order, normals, build_topology(work, required_topology(second))),
            SolverError);
    }

    TEST_CASE("a run on a shared mesh gives the bits of a run on its own copy, and changes none")
    {
        // The editor's restarts share the document's base, order and connectivity.
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.03, 13);
        const LocalityOrder order = locality_order(m);
        const auto shared = std::make_shared<const Mesh>(reorder_mesh(m, order));
        const auto shared_order = std::make_shared<const LocalityOrder>(order);
        const Mesh kept = *shared;
        Recipe r;
        r.iterations = 4;
        r.region = Region{test::all_indices(shared->vertex_count() / 2), {}};
        r.hard = HardVertices{{0, 5}, {{0.1, 0.2, 0.3}, {-0.1, 0.0, 0.4}}};
        const Topology t = build_topology(*shared, required_topology(r));
        for (const bool from_start : {false, true})
        {
            CAPTURE(from_start);
            std::vector<Scalar> start;
            if (from_start)
            {
                start = shared->positions;
                start[3 * 7] += 0.01; // a shape of its own, pins placed by the caller
                for (size_t k = 0; k < r.hard->vertices.size(); ++k)
                    std::copy_n(r.hard->targets[k].begin(), 3,
                                &start[3 * static_cast<size_t>(r.hard->vertices[k])]);
            }
            LocalityRun on_shared(shared, shared_order, r, t, nullptr, start);
            LocalityRun owned(*shared, order, r, t);
            if (from_start)
                owned.session().set_positions(start);
            CHECK(&on_shared.mesh() == shared.get());
            CHECK(on_shared.order().vertex_order == order.vertex_order);
            for (int k = 0; k < 4; ++k)
            {
                on_shared.step();
                owned.step();
            }
            CHECK(std::equal(
                on_shared.session().positions().begin(), on_shared.session().positions().end(),
                owned.session().positions().begin(), owned.session().positions().end()));
            CHECK(on_shared.session().positions()[3] != shared->positions[3]); // it moved
            // Released, it is a mesh of its own with the run's positions.
            const LocalityRun::Released released = std::move(on_shared).release();
            CHECK(released.mesh.face_vertices == shared->face_vertices);
            CHECK(released.mesh.positions != shared->positions);
        }
        CHECK(*shared == kept); // nothing written into the shared mesh
    }
}
