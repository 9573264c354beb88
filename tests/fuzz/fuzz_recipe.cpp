// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Recipe JSON parser. The input is the JSON text, unchanged. An accepted recipe must
// survive recipe_to_json -> parse_recipe -> recipe_to_json unchanged (the documented
// round trip); a recipe that fits a small fixed mesh (check_recipe) then runs at most 3
// steps (and 3 normal-smoothing iterations, or those of at most 3 an edge length of the
// noise found with "auto") on it, which must keep every coordinate
// finite when all of the recipe's numbers are within +-1000 (per-element weights: mu times
// weight within +-1e6).

#include <algorithm>
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

constexpr RecipeLimits kLimits{1 << 16};

int test_one_input(const std::uint8_t* data, size_t size)
{
    if (size > kMaxInput)
        return 0;
    Recipe recipe;
    try
    {
        // (A run [0, 2147483647] is a few bytes: the budget keeps the lists within the
        // fuzzer's memory.)
        recipe = parse_recipe(as_text(data, size), "fuzz.json", kLimits);
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    const std::string json = recipe_to_json(recipe).dump();
    try
    {
        if (recipe_to_json(parse_recipe(json, "again.json", kLimits)).dump() != json)
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
    {
        recipe.normal_smoothing->iterations = std::min(recipe.normal_smoothing->iterations, 3);
        // "auto": a few iterations an edge length of noise (strength <= 10 by check_recipe).
        if (recipe.normal_smoothing->adaptive)
            recipe.normal_smoothing->adaptive->per_noise =
                std::min<Scalar>(recipe.normal_smoothing->adaptive->per_noise, 3);
    }
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
