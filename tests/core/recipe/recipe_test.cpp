// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/recipe.h"

#include <doctest/doctest.h>

#include "core/errors.h"
#include "core/recipe/recipe_json.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

// The message of the error a recipe text raises (parse, then check against a cube).
std::string error_of(const std::string& json)
{
    try
    {
        check_recipe(parse_recipe(json, "r.json"), test::quad_cube());
    }
    catch (const InvalidInputError& e)
    {
        return e.what();
    }
    return "accepted";
}

} // namespace

TEST_SUITE("Recipe")
{
    TEST_CASE("the documented example parses into every section")
    {
        const Recipe r = parse_recipe(R"({
            "iterations": 12, "lambda": "optimal", "tolerance": 1e-6, "method": "jacobi",
            "region": {"faces": [0, 1]},
            "hard": {"vertices": [3, 7], "targets": [[0, 0, 0], [1, 1, 1]]},
            "soft": {"vertices": [1, 2], "mu": 0.5},
            "centroid": {"faces": "all", "mu": 2, "denominator": "exact"},
            "normal": {"faces": [0, 1], "mu": 1.5, "normals": [[0, 0, 2], [1, 0, 0]]},
            "normal_smoothing": {"iterations": 4, "lambda": 0.25,
                "hard": {"faces": [2], "normals": [[0, 1, 0]]},
                "soft": {"faces": [3], "mu": 0.1}},
            "joint": {"gamma": 3}, "bending": {"mu": 2.5, "membrane": 0.5}})",
                                      "r.json");
        CHECK(r.iterations == 12);
        CHECK(r.optimal_step);
        CHECK(r.tolerance == 1e-6);
        CHECK(r.region->faces == std::vector<Index>{0, 1});
        CHECK(r.hard->targets[1] == Vec3{1, 1, 1});
        CHECK(r.soft->mu == 0.5);
        CHECK(r.centroid->faces.all);
        CHECK(r.centroid->denominator == CentroidDenominator::Exact);
        CHECK(r.normal->source == NormalSource::Custom);
        CHECK(r.normal_smoothing->hard.faces == std::vector<Index>{2});
        CHECK(r.normal_smoothing->soft.mu == 0.1);
        CHECK(r.joint->gamma == 3);
        CHECK(r.bending == Bending{2.5, 0.5});
        CHECK_NOTHROW(check_recipe(r, test::quad_cube()));
    }

    TEST_CASE("omitted sections are inactive and defaults are the paper's")
    {
        const Recipe r = parse_recipe("{}", "r.json");
        CHECK(r.iterations == 10);
        CHECK(r.lambda == 0.5);
        CHECK_FALSE(r.optimal_step);
        CHECK_FALSE(r.soft.has_value());
        CHECK_FALSE(r.normal.has_value());
        CHECK_FALSE(r.bending.has_value());
        CHECK(parse_recipe(R"({"bending": {}})", "r.json").bending == Bending{1, 0});
        const Recipe s =
            parse_recipe(R"({"normal": {"faces": "all"}, "normal_smoothing": {}})", "r.json");
        CHECK(s.normal->source == NormalSource::Smoothed);
    }

    TEST_CASE("a recipe survives its JSON form")
    {
        const Recipe r = parse_recipe(R"({"lambda": 0.3, "soft": {"vertices": "all", "mu": 2},
            "centroid": {"faces": [1, 2], "targets": [[1, 2, 3], [4, 5, 6]]},
            "normal": {"faces": "all", "normals": "smoothed"},
            "normal_smoothing": {"iterations": 3, "hard": {"faces": [0]}}, "joint": {"gamma": 0.5},
            "bending": {"mu": 0.25, "membrane": 2}})",
                                      "r.json");
        const Recipe back = parse_recipe(recipe_to_json(r).dump(), "again.json");
        CHECK(recipe_to_json(back) == recipe_to_json(r));
        CHECK(back.centroid->targets[1] == Vec3{4, 5, 6});
        CHECK(back.bending == Bending{0.25, 2});
    }

    TEST_CASE(
        "index lists are written as runs where indices follow one another, read in either "
        "form, in the same order, within the reader's budget")
    {
        const std::vector<Index> listed{7, 8, 9, 10, 2, 3, 5, 6, 7, 0, 40, 41, 42};
        const nlohmann::json runs = index_list_json(listed);
        CHECK(runs.dump() == "[[7,10],2,3,[5,7],0,[40,42]]");
        std::int64_t budget = 100;
        CHECK(parse_index_list(CheckedJson(runs, "r.json", "k"), budget) == listed);
        CHECK(budget == 100 - static_cast<std::int64_t>(listed.size()));
        // The plain list reads the same.
        budget = 100;
        const nlohmann::json plain(listed);
        CHECK(parse_index_list(CheckedJson(plain, "r.json", "k"), budget) == listed);
        CHECK(index_list_json(std::vector<Index>{}).dump() == "[]");
        CHECK(index_list_json(std::vector<Index>{4, 5}).dump() == "[4,5]");
        // A recipe writes its lists so, and reads them back.
        const Recipe r = parse_recipe(
            R"({"region": {"vertices": [[0, 5], 7]}, "hard": {"vertices": [1, 2, 3, 4]},
                "soft": {"vertices": [[6, 6], 7], "mu": 1}})",
            "r.json");
        CHECK(r.region->vertices == std::vector<Index>{0, 1, 2, 3, 4, 5, 7});
        CHECK(r.soft->vertices.indices == std::vector<Index>{6, 7});
        const nlohmann::json written = recipe_to_json(r);
        CHECK(written["region"]["vertices"].dump() == "[[0,5],7]");
        CHECK(written["hard"]["vertices"].dump() == "[[1,4]]");
        CHECK(recipe_to_json(parse_recipe(written.dump(), "again.json")) == written);
        // What is refused, naming the item.
        CHECK(error_of(R"({"hard": {"vertices": [1, [5, 3]]}})") ==
              "'r.json': hard.vertices[1]: a run's last index must not be below its first (got "
              "[5, 3])");
        CHECK(error_of(R"({"hard": {"vertices": [[1, 2, 3]]}})") ==
              "'r.json': hard.vertices[0]: a run must be [first, last]");
        CHECK(error_of(R"({"hard": {"vertices": [[-1, 2]]}})") ==
              "'r.json': hard.vertices[0][0]: index -1 is out of range");
        CHECK_THROWS_WITH_AS(
            parse_recipe(R"({"region": {"vertices": [[0, 2147483647]]}})", "big.json",
                         RecipeLimits{1000}),
            "'big.json': region.vertices[0]: lists more indices than a recipe may (1000 left)",
            RecipeError);
        CHECK(error_of(R"({"editor": 3})") ==
              "'r.json': editor: must be an object (the editor's sets and view)");
        CHECK(parse_recipe(R"({"editor": {"anything": [1]}})", "r.json").iterations == 10);
    }

    TEST_CASE("every malformed recipe is refused naming the key")
    {
        CHECK(error_of(R"({"iteratoins": 3})") ==
              "'r.json': iteratoins: unknown key (allowed here: description, editor, iterations, "
              "lambda, tolerance, method, taubin_mu, region, hard, soft, centroid, normal, "
              "normal_smoothing, joint, "
              "bending, volume, falloff, prevent_flips, factor_budget_mb, time)");
        CHECK(error_of(R"({"bending": {"stiffness": 1}})") ==
              "'r.json': bending.stiffness: unknown key (allowed here: mu, membrane)");
        CHECK(error_of(R"({"bending": {"mu": -1}})") ==
              "'r.json': bending.mu: must be >= 0 (got -1)");
        CHECK(error_of(R"({"bending": {"membrane": "yes"}})") ==
              "'r.json': bending.membrane: must be a number");
        CHECK(error_of(R"({"soft": {"vertices": [1], "muu": 1}})") ==
              "'r.json': soft.muu: unknown key (allowed here: vertices, mu, targets, weights)");
        CHECK(error_of(R"({"hard": {"vertices": [1, 9]}})") ==
              "recipe: hard.vertices[1]: vertex 9 is out of range (the mesh has 8 vertices)");
        CHECK(error_of(R"({"centroid": {"faces": [6]}})") ==
              "recipe: centroid.faces[0]: face 6 is out of range (the mesh has 6 faces)");
        CHECK(error_of(R"({"hard": {"vertices": [-1]}})") ==
              "'r.json': hard.vertices[0]: index -1 is out of range");
        CHECK(error_of(R"({"hard": {"vertices": [2, 2]}})") ==
              "recipe: hard.vertices[1]: vertex 2 is listed twice");
        CHECK(error_of(R"({"hard": {"vertices": [1, 2]}, "soft": {"vertices": [3, 2]}})") ==
              "recipe: soft.vertices[1]: vertex 2 is also in hard.vertices (hard and soft "
              "vertex sets must be disjoint)");
        CHECK(error_of(R"({"normal": {"faces": "all"}, "normal_smoothing": {"hard": {"faces":
              [1]}, "soft": {"faces": [1]}}})") ==
              "recipe: normal_smoothing.soft.faces[0]: face 1 is also in "
              "normal_smoothing.hard.faces (hard and soft normal sets must be disjoint)");
        CHECK(error_of(R"({"soft": {"vertices": "all", "mu": -1}})") ==
              "'r.json': soft.mu: must be >= 0 (got -1)");
        CHECK(error_of(R"({"soft": {"vertices": "all", "mu": 1e400}})").find("'r.json'") == 0);
        CHECK(error_of(R"({"hard": {"vertices": [1], "targets": [[0, 0, 0], [1, 1, 1]]}})") ==
              "recipe: hard.targets: has 2 entries but hard.vertices has 1");
        CHECK(error_of(R"({"soft": {"vertices": "all", "targets": [[0, 0, 0]]}})") ==
              "recipe: soft.targets: has 1 entries but the mesh (soft.vertices is \"all\") has 8");
        CHECK(error_of(R"({"hard": {"vertices": [1], "targets": [[0, 0]]}})") ==
              "'r.json': hard.targets[0]: must be an [x, y, z] triple");
        CHECK(error_of(R"({"hard": {"vertices": [1.5]}})") ==
              "'r.json': hard.vertices[0]: must be an integer (got 1.5)");
        CHECK(error_of(R"({"hard": {"vertices": [99999999999999999999]}})") ==
              "'r.json': hard.vertices[0]: is out of range (got 1e+20)");
        CHECK(error_of(R"({"lambda": "fast"})") ==
              "'r.json': lambda: must be a number > 0 or \"optimal\"");
        CHECK(error_of(R"({"lambda": 0})") == "'r.json': lambda: must be > 0 (got 0)");
        CHECK(error_of(R"({"iterations": -2})") ==
              "'r.json': iterations: must be an integer in [0, 2147483647] (got -2)");
        CHECK(error_of(R"({"method": "newton"})") ==
              "'r.json': method: must be \"jacobi\", \"gradient_descent\", \"taubin\", "
              "\"direct\", \"cg\" or \"implicit\"");
        CHECK(error_of(R"({"centroid": {"faces": "all", "denominator": "printed"}})") ==
              "'r.json': centroid.denominator: must be \"paper\" or \"exact\"");
        CHECK(error_of(R"({"normal": {"faces": [0], "normals": [[0, 0, 0]]}})") ==
              "recipe: normal.normals[0]: a normal must not be the zero vector");
        CHECK(error_of(R"({"normal": {"faces": [0, 1], "normals": [[0, 0, 1]]}})") ==
              "recipe: normal.normals: has 1 entries but normal.faces has 2");
        CHECK(error_of(R"({"normal_smoothing": {}})") ==
              "recipe: normal_smoothing: needs a \"normal\" section: smoothed normals act on "
              "the mesh through the face-normal term");
        CHECK(error_of(R"({"joint": {"gamma": 1}})") ==
              "recipe: joint: needs a \"normal\" section (its faces and mu couple x and u)");
        CHECK(error_of(R"({"region": {}})") == "'r.json': region: needs \"vertices\" or \"faces\"");
        CHECK(error_of(R"({"soft": {"mu": 1}})") == "'r.json': soft.vertices: is required");
        CHECK(error_of(R"([1, 2])") == "'r.json': (top level): must be an object");
        CHECK(error_of(R"({"soft": 3})") ==
              "'r.json': soft: must be an object or an array of objects");
        CHECK(error_of(R"({"iterations": 3,})") ==
              "'r.json':1:18: not valid JSON: syntax error while parsing object key - unexpected "
              "'}'; expected string literal");
    }

    TEST_CASE(
        "bilateral weights, the volume and Taubin's method: parsed, written back, and "
        "refused naming the key")
    {
        const Recipe r = parse_recipe(R"({"method": "taubin", "taubin_mu": -0.6, "volume": {},
            "normal": {"faces": "all", "normals": "smoothed"}, "normal_smoothing": {"bilateral":
            {"sigma_s": 2, "sigma_r": 0.3, "reweight_every": 3, "neighbors": "vertex"}}})",
                                      "r.json");
        CHECK(r.method == Method::Taubin);
        CHECK(r.taubin_mu == -0.6);
        CHECK(r.volume.has_value());
        REQUIRE(r.normal_smoothing->bilateral.has_value());
        const BilateralWeights& b = *r.normal_smoothing->bilateral;
        CHECK(b.sigma_s == 2);
        CHECK(b.sigma_r == 0.3);
        CHECK(b.reweight_every == 3);
        CHECK(b.neighbors == FaceNeighborhood::Vertex);
        const Recipe back = parse_recipe(recipe_to_json(r).dump(), "again.json");
        CHECK(recipe_to_json(back) == recipe_to_json(r));
        // Defaults, and nothing new written for a recipe that does not use them.
        const Recipe d = parse_recipe(R"({"normal": {"faces": "all"}, "normal_smoothing":
            {"bilateral": {}}})",
                                      "r.json");
        CHECK(d.normal_smoothing->bilateral->sigma_s == 1);
        CHECK(d.normal_smoothing->bilateral->sigma_r == 0.35);
        CHECK(d.normal_smoothing->bilateral->reweight_every == 1);
        CHECK(d.normal_smoothing->bilateral->neighbors == FaceNeighborhood::Edge);
        const nlohmann::json plain = recipe_to_json(parse_recipe("{}", "r.json"));
        CHECK(!plain.contains("taubin_mu"));
        CHECK(!plain.contains("volume"));

        const std::string smoothing = R"({"normal": {"faces": "all"}, "normal_smoothing": )";
        CHECK(error_of(smoothing + R"({"bilateral": {"sigma_s": 0}}})") ==
              "'r.json': normal_smoothing.bilateral.sigma_s: must be > 0 (got 0)");
        CHECK(error_of(smoothing + R"({"bilateral": {"sigma_r": -0.3}}})") ==
              "'r.json': normal_smoothing.bilateral.sigma_r: must be > 0 (got -0.3)");
        CHECK(error_of(smoothing + R"({"bilateral": {"reweight_every": 0}}})") ==
              "'r.json': normal_smoothing.bilateral.reweight_every: must be >= 1 (got 0)");
        CHECK(error_of(smoothing + R"({"bilateral": {"neighbors": "face"}}})") ==
              "'r.json': normal_smoothing.bilateral.neighbors: must be \"edge\" or \"vertex\"");
        CHECK(error_of(smoothing + R"({"bilateral": {"sigma": 1}}})") ==
              "'r.json': normal_smoothing.bilateral.sigma: unknown key (allowed here: sigma_s, "
              "sigma_r, noise_scale, reweight_every, neighbors, guidance)");
        CHECK(error_of(R"({"volume": {"keep": true}})") ==
              "'r.json': volume.keep: unknown key (allowed here: open, components)");
        CHECK(error_of(R"({"volume": {"open": "ignore"}})") ==
              "'r.json': volume.open: must be \"capped\" or \"none\"");
        CHECK(error_of(R"({"volume": {"components": "some"}})") ==
              "'r.json': volume.components: must be \"all\" or \"free\"");
        CHECK(error_of(R"({"prevent_flips": 1})") ==
              "'r.json': prevent_flips: must be true or false");
        // The volume's options and the flip guard, written back only when not the defaults.
        const Recipe v = parse_recipe(
            R"({"volume": {"open": "none", "components": "free"}, "prevent_flips": true})",
            "r.json");
        CHECK(v.volume->open == OpenVolume::None);
        CHECK(v.volume->free_components_only);
        CHECK(v.prevent_flips);
        CHECK(recipe_to_json(v)["volume"] ==
              nlohmann::json::parse(R"({"open": "none", "components": "free"})"));
        CHECK(recipe_to_json(v)["prevent_flips"] == true);
        CHECK(recipe_to_json(r)["volume"] == nlohmann::json::object());
        CHECK(!recipe_to_json(r).contains("prevent_flips"));
        CHECK(error_of(R"({"volume": true})") == "'r.json': volume: must be an object");
        CHECK(error_of(R"({"method": "taubin", "taubin_mu": -0.4})") ==
              "recipe: taubin_mu: must be finite and below -lambda (Taubin's mu < -lambda < 0 "
              "keeps the low frequencies)");
        CHECK(error_of(R"({"method": "taubin", "lambda": "optimal"})") ==
              "recipe: lambda: \"optimal\" is not a step length of method \"taubin\" (its two "
              "steps have fixed lengths)");
        CHECK(error_of(R"({"method": "taubin", "normal": {"faces": "all"}, "joint": {}})") ==
              "recipe: joint: is not available with method \"taubin\" (the normals have no "
              "lambda|mu pair)");
        const Recipe f = parse_recipe(R"({"region": {"vertices": [1]}, "falloff": {"radius": 0.5,
            "units": "mesh", "curve": "sphere", "mu": 2, "around": ["border"]}})",
                                      "r.json");
        REQUIRE(f.falloff.has_value());
        CHECK(f.falloff->radius == 0.5);
        CHECK(!f.falloff->radius_in_edge_lengths);
        CHECK(f.falloff->curve == FalloffCurve::Sphere);
        CHECK(f.falloff->mu == 2);
        CHECK(f.falloff->border);
        CHECK(!f.falloff->pins);
        CHECK(recipe_to_json(parse_recipe(recipe_to_json(f).dump(), "again.json")) ==
              recipe_to_json(f));
        CHECK(error_of(R"({"falloff": {"radius": -2}})") ==
              "'r.json': falloff.radius: must be >= 0 (got -2)");
        CHECK(error_of(R"({"falloff": {"curve": "bell"}})") ==
              "'r.json': falloff.curve: must be \"smooth\", \"sphere\", \"root\", \"linear\", "
              "\"sharp\" or \"constant\"");
        CHECK(error_of(R"({"falloff": {"units": "cm"}})") ==
              "'r.json': falloff.units: must be \"edge_lengths\" or \"mesh\"");
        CHECK(error_of(R"({"falloff": {"around": []}})") ==
              "'r.json': falloff.around: must be a non-empty list of \"border\" and \"pins\"");
        CHECK(error_of(R"({"falloff": {"around": ["border", "edges"]}})") ==
              "'r.json': falloff.around[1]: must be \"border\" or \"pins\"");
        // In code, where the parser cannot refuse them first.
        Recipe bad;
        bad.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Smoothed, {}};
        bad.normal_smoothing = NormalSmoothing{};
        bad.normal_smoothing->bilateral =
            BilateralWeights{std::nan(""), 0.35, 1, FaceNeighborhood::Edge};
        CHECK_THROWS_WITH_AS(check_recipe(bad, test::quad_cube()),
                             "recipe: normal_smoothing.bilateral.sigma_s: must be finite and > 0",
                             RecipeError);
    }

    TEST_CASE("coordinates beyond 1e100 are refused before smoothing, where they would overflow")
    {
        Mesh mesh = test::tetrahedron();
        mesh.positions[5] = 1e300;
        try
        {
            check_recipe(Recipe{}, mesh);
            FAIL("accepted");
        }
        catch (const RecipeError&)
        {
            FAIL("a mesh coordinate is not a recipe key");
        }
        catch (const InvalidInputError& e)
        {
            CHECK(std::string(e.what()) ==
                  "vertex 1 has the coordinate 1e+300, beyond the +-1e100 that smoothing "
                  "supports (squared distances would overflow): scale the mesh down");
        }
        mesh.positions[5] = -1e100; // the bound itself is accepted
        CHECK_NOTHROW(check_recipe(Recipe{}, mesh));
        Recipe r;
        r.hard = HardVertices{{0}, {Vec3{0, 0, 2e100}}};
        CHECK_THROWS_WITH_AS(check_recipe(r, mesh),
                             "recipe: hard.targets[0]: must be finite and within +-1e100",
                             RecipeError);
    }

    TEST_CASE("weights parse one per element, and a recipe without them writes what it did")
    {
        const Recipe r = parse_recipe(R"({"soft": {"vertices": [1, 2], "mu": 0.5,
            "weights": [2, 0]}, "centroid": {"faces": "all", "weights": [1, 2, 3, 4, 5, 6]},
            "normal": {"faces": [0], "weights": [0.25]},
            "normal_smoothing": {"soft": {"faces": [3], "mu": 0.1, "weights": [4]}}})",
                                      "r.json");
        CHECK(r.soft->weights == std::vector<Scalar>{2, 0});
        CHECK(r.centroid->weights.size() == 6);
        CHECK(r.normal->weights == std::vector<Scalar>{0.25});
        CHECK(r.normal_smoothing->soft.weights == std::vector<Scalar>{4});
        CHECK_NOTHROW(check_recipe(r, test::quad_cube()));
        const Recipe back = parse_recipe(recipe_to_json(r).dump(), "again.json");
        CHECK(recipe_to_json(back) == recipe_to_json(r));
        CHECK(back.centroid->weights == r.centroid->weights);
        // No weights: no "weights" key, the JSON written before weights existed.
        const Recipe plain = parse_recipe(
            R"({"soft": {"vertices": [1]}, "centroid": {"faces": [0]}, "normal": {"faces": "all"},
                "normal_smoothing": {"soft": {"faces": [3]}}})",
            "r.json");
        CHECK(recipe_to_json(plain).dump() ==
              R"({"centroid":{"denominator":"paper","faces":[0],"mu":1.0},"iterations":10,)"
              R"("lambda":0.5,"method":"jacobi","normal":{"faces":"all","mu":1.0,"normals":)"
              R"("smoothed"},"normal_smoothing":{"iterations":10,"lambda":0.5,"soft":{"faces":)"
              R"([3],"mu":1.0}},"soft":{"mu":1.0,"vertices":[1]},"tolerance":0.0})");
    }

    TEST_CASE("a list of sets is one set weighing each element by its set's mu and weights")
    {
        const Recipe r = parse_recipe(R"({
            "soft": [{"vertices": [1, 2], "mu": 0.5, "targets": [[0, 0, 0], [1, 1, 1]]},
                     {"vertices": [7], "mu": 4, "weights": [0.25], "targets": [[2, 2, 2]]}],
            "centroid": [{"faces": [0], "mu": 2, "denominator": "exact"},
                         {"faces": [5, 3], "weights": [3, 0], "denominator": "exact"}],
            "normal": [{"faces": [1], "mu": 3, "normals": [[0, 0, 1]]},
                       {"faces": [2], "normals": [[1, 0, 0]]}]})",
                                      "r.json");
        CHECK(r.soft->vertices.indices == std::vector<Index>{1, 2, 7});
        CHECK(r.soft->mu == 1);
        CHECK(r.soft->weights == std::vector<Scalar>{0.5, 0.5, 1});
        CHECK(r.soft->targets.size() == 3);
        CHECK(r.soft->targets[2] == Vec3{2, 2, 2});
        CHECK(r.centroid->faces.indices == std::vector<Index>{0, 5, 3});
        CHECK(r.centroid->weights == std::vector<Scalar>{2, 3, 0});
        CHECK(r.centroid->denominator == CentroidDenominator::Exact);
        CHECK(r.normal->source == NormalSource::Custom);
        CHECK(r.normal->normals == std::vector<Vec3>{{0, 0, 1}, {1, 0, 0}});
        CHECK(r.normal->weights == std::vector<Scalar>{3, 1});
        CHECK_NOTHROW(check_recipe(r, test::quad_cube()));
        // Written back as one object with weights, which parses to the same recipe.
        const nlohmann::json j = recipe_to_json(r);
        CHECK(j["soft"]["weights"] == nlohmann::json{0.5, 0.5, 1.0});
        CHECK(recipe_to_json(parse_recipe(j.dump(), "again.json")) == j);
        // A list of one set is that set.
        const Recipe one = parse_recipe(R"({"soft": [{"vertices": [1, 2], "mu": 0.5}]})", "r.json");
        CHECK(one.soft->mu == 0.5);
        CHECK(one.soft->weights.empty());
        CHECK(recipe_to_json(one) ==
              recipe_to_json(parse_recipe(R"({"soft": {"vertices": [1, 2], "mu": 0.5}})", "r")));
        const Recipe all = parse_recipe(R"({"normal": [{"faces": "all", "mu": 2}]})", "r.json");
        CHECK(all.normal->faces.all);
    }

    TEST_CASE("every malformed weight or list of sets is refused naming the key")
    {
        // Weights.
        CHECK(
            error_of(R"({"soft": {"vertices": [1, 2, 3, 4, 5, 6], "weights": [1, 1, 1, 1, 1]}})") ==
            "recipe: soft.weights: 5 weights for 6 vertices");
        CHECK(error_of(R"({"soft": {"vertices": "all", "weights": [1]}})") ==
              "recipe: soft.weights: 1 weights for 8 vertices (soft.vertices is \"all\")");
        CHECK(error_of(R"({"centroid": {"faces": "all", "weights": [1, 2]}})") ==
              "recipe: centroid.weights: 2 weights for 6 faces (centroid.faces is \"all\")");
        CHECK(error_of(R"({"normal": {"faces": [0, 1], "weights": [1]}})") ==
              "recipe: normal.weights: 1 weights for 2 faces");
        CHECK(
            error_of(R"({"normal": {"faces": "all"}, "normal_smoothing": {"soft": {"faces": [1, 2],
              "weights": [1, 2, 3]}}})") ==
            "recipe: normal_smoothing.soft.weights: 3 weights for 2 faces");
        CHECK(error_of(R"({"soft": {"vertices": [1, 2], "weights": [1, -2]}})") ==
              "'r.json': soft.weights[1]: must be >= 0 (got -2)");
        CHECK(error_of(R"({"soft": {"vertices": [1], "weights": 2}})") ==
              "'r.json': soft.weights: must be an array of numbers >= 0");
        CHECK(error_of(R"({"centroid": {"faces": [1], "weights": ["a"]}})") ==
              "'r.json': centroid.weights[0]: must be a number");
        CHECK(error_of(R"({"normal": {"faces": [1], "weights": [1e400]}})").find("'r.json'") == 0);
        CHECK(error_of(R"({"soft": {"vertices": [1], "mu": 1e300, "weights": [1e300]}})") ==
              "recipe: soft.weights[0]: times mu is not finite");
        // Lists of sets.
        CHECK(error_of(R"({"soft": []})") ==
              "'r.json': soft: must hold at least one set (leave the section out for none)");
        CHECK(error_of(R"({"soft": [3]})") == "'r.json': soft[0]: must be an object");
        CHECK(error_of(R"({"soft": [{"vertices": [1], "muu": 1}]})") ==
              "'r.json': soft[0].muu: unknown key (allowed here: vertices, mu, targets, weights)");
        CHECK(error_of(R"({"centroid": [{"faces": [1]}, {"mu": 1}]})") ==
              "'r.json': centroid[1].faces: is required");
        CHECK(error_of(R"({"soft": [{"vertices": [1, 2]}, {"vertices": [3, 4, 5, 2]}]})") ==
              "recipe: soft[1].vertices[3]: vertex 2 is already in soft[0]");
        CHECK(error_of(R"({"soft": [{"vertices": [1]}, {"vertices": [3, 3]}]})") ==
              "recipe: soft[1].vertices[1]: vertex 3 is listed twice");
        CHECK(error_of(R"({"soft": [{"vertices": [1]}, {"vertices": [3, 9]}]})") ==
              "recipe: soft[1].vertices[1]: vertex 9 is out of range (the mesh has 8 vertices)");
        CHECK(error_of(R"({"soft": [{"vertices": [9]}]})") ==
              "recipe: soft[0].vertices[0]: vertex 9 is out of range (the mesh has 8 vertices)");
        CHECK(error_of(R"({"hard": {"vertices": [2]}, "soft": [{"vertices": [1]},
              {"vertices": [2]}]})") ==
              "recipe: soft[1].vertices[0]: vertex 2 is also in hard.vertices (hard and soft "
              "vertex sets must be disjoint)");
        CHECK(error_of(R"({"normal": [{"faces": [0, 4]}, {"faces": [4]}]})") ==
              "recipe: normal[1].faces[0]: face 4 is already in normal[0]");
        CHECK(error_of(R"({"centroid": [{"faces": [0]}, {"faces": [1, 0]}]})") ==
              "recipe: centroid[1].faces[1]: face 0 is already in centroid[0]");
        CHECK(error_of(R"({"soft": [{"vertices": "all"}, {"vertices": [1]}]})") ==
              "'r.json': soft[0].vertices: \"all\" is allowed only when soft holds one set (this "
              "list holds 2)");
        CHECK(error_of(R"({"soft": [{"vertices": [1], "targets": [[0, 0, 0]]},
              {"vertices": [2]}]})") ==
              "'r.json': soft[1].targets: is missing, but soft[0] gives targets: in a list, "
              "every set gives them or none does");
        CHECK(
            error_of(R"({"centroid": [{"faces": [1]}, {"faces": [2], "targets": [[0, 0, 0]]}]})") ==
            "'r.json': centroid[1].targets: is given, but centroid[0] gives no targets: in a "
            "list, every set gives them or none does");
        CHECK(error_of(R"({"soft": [{"vertices": [1], "targets": [[0, 0, 0]]},
              {"vertices": [2, 3], "targets": [[0, 0, 0]]}]})") ==
              "'r.json': soft[1].targets: has 1 entries but soft[1].vertices has 2");
        CHECK(error_of(R"({"soft": [{"vertices": [1]}, {"vertices": [2, 3], "weights": [1]}]})") ==
              "'r.json': soft[1].weights: 1 weights for 2 vertices");
        CHECK(error_of(R"({"soft": [{"vertices": [1]}, {"vertices": [2], "mu": 1e300,
              "weights": [1e300]}]})") ==
              "'r.json': soft[1].weights[0]: times soft[1].mu is not finite");
        CHECK(
            error_of(R"({"centroid": [{"faces": [0]}, {"faces": [1], "denominator": "exact"}]})") ==
            "'r.json': centroid[1].denominator: \"exact\" differs from centroid[0]'s "
            "\"paper\" (the sets of a list share one denominator)");
        CHECK(error_of(R"({"normal": [{"faces": [0], "normals": "initial"},
              {"faces": [1], "normals": [[0, 0, 1]]}]})") ==
              "'r.json': normal[1].normals: given normals differs from normal[0]'s "
              "\"initial\" (the sets of a list take their normals from one source)");
        CHECK(error_of(R"({"normal": [{"faces": [0]}, {"faces": [1], "normals": "smoothed"}]})") ==
              "'r.json': normal[1].normals: \"smoothed\" differs from normal[0]'s \"initial\" "
              "(the sets of a list take their normals from one source)");
        CHECK(error_of(R"({"normal": [{"faces": [0], "normals": [[0, 0, 1]]},
              {"faces": [1, 2], "normals": [[0, 0, 1]]}]})") ==
              "'r.json': normal[1].normals: has 1 entries but normal[1].faces has 2");
        CHECK(error_of(R"({"normal": [{"faces": [0], "normals": [[0, 0, 1]]},
              {"faces": [1], "normals": [[0, 0, 0]]}]})") ==
              "recipe: normal[1].normals[0]: a normal must not be the zero vector");
        CHECK(error_of(R"({"soft": [{"vertices": [1], "targets": [[0, 0, 0]]},
              {"vertices": [2], "targets": [[0, 0, 1e300]]}]})") ==
              "recipe: soft[1].targets[0]: must be finite and within +-1e100");
    }

    TEST_CASE("renumbering moves weights with their elements")
    {
        Recipe r;
        r.soft = SoftVertices{{true, {}}, 1.0, {}, {0, 1, 2, 3}};
        r.centroid =
            CentroidConstraints{{false, {1, 0}}, 1.0, {}, CentroidDenominator::Paper, {5, 6}};
        r.normal = NormalConstraints{{true, {}}, 1.0, NormalSource::Initial, {}, {7, 8}};
        r.normal_smoothing = NormalSmoothing{};
        r.normal_smoothing->soft = SoftNormals{{0}, 1.0, {}, {9}};
        const std::vector<Index> new_vertex{2, 0, 3, 1}, new_face{1, 0};
        const Recipe s = renumber_recipe(r, new_vertex, new_face);
        CHECK(s.soft->weights == std::vector<Scalar>{1, 3, 0, 2}); // "all": permuted
        CHECK(s.centroid->faces.indices == std::vector<Index>{0, 1});
        CHECK(s.centroid->weights == std::vector<Scalar>{5, 6}); // a list: kept in its order
        CHECK(s.normal->weights == std::vector<Scalar>{8, 7});
        CHECK(s.normal_smoothing->soft.faces == std::vector<Index>{1});
        CHECK(s.normal_smoothing->soft.weights == std::vector<Scalar>{9});
    }
}
