// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Recipe JSON parser. The input is the JSON text, unchanged. An accepted recipe must
// survive recipe_to_json -> parse_recipe -> recipe_to_json unchanged (the documented
// round trip); a recipe that fits a small fixed mesh (check_recipe) then runs at most 3
// steps (and 3 normal-smoothing iterations) on it, which must keep every coordinate
// finite when all of the recipe's numbers are within +-1000 (per-element weights: mu times
// weight within +-1e6).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "core/topology/topology.h"
#include "tests/fuzz/fuzz_support.h"

namespace meshfair::fuzz {
namespace {

// A cube of 6 quads with one corner cut off by a triangle-pentagon pair: 10 vertices,
// 8 faces of sizes 3, 4 and 5, and a boundary.
Mesh small_mesh()
{
    Mesh m;
    for (const Vec3& p : std::initializer_list<Vec3>{{0, 0, 0},
                                                     {1, 0, 0},
                                                     {1, 1, 0},
                                                     {0, 1, 0},
                                                     {0, 0, 1},
                                                     {1, 0, 1},
                                                     {1, 1, 1},
                                                     {0, 1, 1},
                                                     {0.5, 1.5, 0.5},
                                                     {-0.5, 0.5, 0.5}})
        m.add_vertex(p[0], p[1], p[2]);
    const std::initializer_list<std::initializer_list<Index>> faces = {
        {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5},
        {2, 3, 8},    {3, 7, 8},    {3, 0, 9},    {0, 4, 7, 3, 9}};
    for (const auto& f : faces)
        m.add_face(std::vector<Index>(f));
    return m;
}

bool bounded(double v)
{
    return std::abs(v) <= 1000;
}

bool bounded(const std::vector<Vec3>& points)
{
    for (const Vec3& p : points)
        if (!bounded(p[0]) || !bounded(p[1]) || !bounded(p[2]))
            return false;
    return true;
}

// A term's mu and its per-element weights mu * weights[k]: within what two numbers of
// +-1000 give (a list of sets is merged into mu = 1 and weights set.mu * set.weights[k]).
bool bounded(double mu, const std::vector<Scalar>& weights)
{
    return bounded(mu) && std::all_of(weights.begin(), weights.end(),
                                      [&](Scalar w) { return std::abs(mu * w) <= 1e6; });
}

// Every number of the recipe is within +-1000 (weights, step lengths, targets, normals).
bool bounded(const Recipe& r)
{
    bool ok = (r.optimal_step || bounded(r.lambda)) && bounded(r.tolerance);
    if (r.hard)
        ok = ok && bounded(r.hard->targets);
    if (r.soft)
        ok = ok && bounded(r.soft->mu, r.soft->weights) && bounded(r.soft->targets);
    if (r.centroid)
        ok = ok && bounded(r.centroid->mu, r.centroid->weights) && bounded(r.centroid->targets);
    if (r.normal)
        ok = ok && bounded(r.normal->mu, r.normal->weights) && bounded(r.normal->normals);
    if (r.normal_smoothing)
    {
        const NormalSmoothing& ns = *r.normal_smoothing;
        ok = ok && bounded(ns.lambda) && bounded(ns.hard.normals) &&
             bounded(ns.soft.mu, ns.soft.weights) && bounded(ns.soft.normals);
    }
    if (r.joint)
        ok = ok && bounded(r.joint->gamma);
    return ok;
}

int test_one_input(const std::uint8_t* data, size_t size)
{
    if (size > kMaxInput)
        return 0;
    Recipe recipe;
    try
    {
        recipe = parse_recipe(as_text(data, size), "fuzz.json");
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    const std::string json = recipe_to_json(recipe).dump();
    try
    {
        if (recipe_to_json(parse_recipe(json, "again.json")).dump() != json)
            fail("recipe_to_json -> parse_recipe changes the recipe: " + json);
    }
    catch (const InvalidInputError& e)
    {
        fail(std::string("recipe_to_json gives JSON that parse_recipe refuses: ") + e.what() +
             "\n" + json);
    }

    static const Mesh mesh = small_mesh();
    static const Topology topology = build_topology(mesh);
    try
    {
        check_recipe(recipe, mesh);
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    recipe.iterations = std::min(recipe.iterations, 3);
    if (recipe.normal_smoothing)
        recipe.normal_smoothing->iterations = std::min(recipe.normal_smoothing->iterations, 3);
    std::vector<Scalar> x = mesh.positions;
    try
    {
        Session session(mesh, topology, recipe);
        session.apply_hard_targets(x);
        run(session, x);
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    if (bounded(recipe) && !all_finite(x.data(), x.size()))
        fail("a recipe with bounded numbers gives non-finite positions: " + json);
    return 0;
}

} // namespace
} // namespace meshfair::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    return meshfair::fuzz::test_one_input(data, size);
}
