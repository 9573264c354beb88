// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>

#include "app/edit/constraint_sets.h"
#include "app/editor/panels/panel_context.h"
#include "core/recipe/recipe_json.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

//! The recipe the editor runs after importing `r`: its sets and settings, built back.
Recipe through_the_editor(const Recipe& r, const Mesh& m)
{
    const ImportedRecipe imported = sets_from_recipe(r, m);
    CHECK(constraint_problems(imported.sets, imported.settings).empty());
    return build_recipe(imported.sets, imported.settings, m, m.positions, imported.iterations);
}

//! smooth() of the same noisy mesh with both recipes gives the same bits.
void check_same_result(const Recipe& a, const Recipe& b, const Mesh& m)
{
    const Topology t = build_topology(m);
    Mesh x = m, y = m;
    smooth(x, t, a);
    smooth(y, t, b);
    CHECK(std::memcmp(x.positions.data(), y.positions.data(),
                      x.positions.size() * sizeof(Scalar)) == 0);
    CHECK(x.positions != m.positions);
}

} // namespace

TEST_SUITE("Editor recipes")
{
    TEST_CASE("one row per constraint kind, in the kinds' order, each name read back")
    {
        const std::span<const ConstraintKindInfo> kinds = constraint_kinds();
        REQUIRE(kinds.size() == static_cast<size_t>(kConstraintKinds));
        for (size_t k = 0; k < kinds.size(); ++k)
        {
            const ConstraintKindInfo& info = kinds[k];
            CAPTURE(std::string(info.name));
            CHECK(static_cast<size_t>(info.kind) == k);
            CHECK(kind_named(info.name) == info.kind);
            CHECK(std::string(kind_label(info.kind)) == std::string(info.label));
            // A kind takes vertices or faces, and a weight map only over vertices; the kind a
            // set loses to takes the same elements.
            CHECK((!info.weight_map || info.vertices));
            CHECK((!info.normals || !info.vertices));
            if (info.loses_to)
                CHECK(kind_info(*info.loses_to).vertices == info.vertices);
            SolverSettings settings;
            if (info.weight != nullptr)
            {
                settings.*info.weight = 7;
                ConstraintSet set;
                set.kind = info.kind;
                CHECK(weight_of(set, settings) == 7);
                CHECK(takes_weight(info.kind));
            }
            else
                CHECK_FALSE(takes_weight(info.kind));
        }
        CHECK_FALSE(kind_named("hard normal").has_value()); // the label is not the name
    }

    TEST_CASE("the presets come into the editor whole and run there as they run from files")
    {
        Mesh m = test::icosphere(3);
        test::perturb(m, 0.02, 5);
        {
            const Recipe file = read_recipe((test::assets_dir() / "recipes/denoise.json").string());
            const Recipe editor = through_the_editor(file, m);
            REQUIRE(editor.normal_smoothing.has_value());
            CHECK(editor.normal_smoothing->bilateral == file.normal_smoothing->bilateral);
            CHECK(editor.volume == file.volume);
            CHECK(editor.prevent_flips);
            check_same_result(file, editor, m);
        }
        {
            const Recipe file = read_recipe((test::assets_dir() / "recipes/relax.json").string());
            const Recipe editor = through_the_editor(file, m);
            CHECK(editor.method == Method::Taubin);
            CHECK(editor.taubin_mu == file.taubin_mu);
            CHECK(editor.volume.has_value());
            check_same_result(file, editor, m);
        }
        {
            // fair-region with a region (the editor's selection) and a pin: the direct
            // method with the thin plate.
            Recipe file = read_recipe((test::assets_dir() / "recipes/fair-region.json").string());
            file.region = Region{test::all_indices(m.vertex_count() / 2), {}};
            file.hard = HardVertices{{3}, {{0.0, 0.0, 1.3}}};
            const Recipe editor = through_the_editor(file, m);
            CHECK(editor.method == Method::Direct);
            CHECK(editor.bending == file.bending);
            CHECK(editor.bending.has_value());
            CHECK(editor.prevent_flips);
            check_same_result(file, editor, m);
        }
    }

    TEST_CASE("settings the sets cannot run are named, not dropped")
    {
        SolverSettings s;
        s.falloff = Falloff{};
        std::vector<ConstraintSet> sets(1);
        sets[0].kind = ConstraintKind::Anchor;
        sets[0].vertices = {1, 2};
        // A falloff with nothing to fade from is no problem (the run's note says so).
        CHECK(constraint_problems(sets, s).empty());
        sets[0].kind = ConstraintKind::Pin;
        CHECK(constraint_problems(sets, s).empty());
        s.method = Method::Taubin;
        s.optimal_step = true;
        CHECK(constraint_problems(sets, s) ==
              std::vector<std::string>{"Taubin's method takes a fixed lambda and no joint mode"});
        s.optimal_step = false;
        s.taubin_mu = -0.3; // not below -lambda = -0.5
        CHECK(constraint_problems(sets, s) ==
              std::vector<std::string>{"Taubin's mu must be below -lambda"});
    }

    TEST_CASE("a preset keeps the artist's regions, pins and the kinds it does not have")
    {
        Mesh m = test::icosphere(2);
        const auto set = [](std::string name, ConstraintKind kind, std::vector<Index> v) {
            ConstraintSet s;
            s.name = std::move(name);
            s.kind = kind;
            s.vertices = std::move(v);
            return s;
        };
        const std::vector<ConstraintSet> user = {
            set("patch", ConstraintKind::Region, {1, 2, 3, 4}),
            set("pins", ConstraintKind::Pin, {5}),
            set("normal", ConstraintKind::Anchor, {6, 7}), // a user's name the preset uses too
        };
        const Recipe denoise = read_recipe((test::assets_dir() / "recipes/denoise.json").string());
        ImportedRecipe preset = sets_from_recipe(denoise, m);
        const std::vector<ConstraintSet> merged = merge_preset(user, preset.sets);
        // The user's three, then the preset's centroid and normal sets (no anchors in it).
        REQUIRE(merged.size() == 5);
        CHECK(merged[0] == user[0]);
        CHECK(merged[1] == user[1]);
        CHECK(merged[2] == user[2]);
        CHECK(merged[3].kind == ConstraintKind::Centroid);
        CHECK(merged[4].kind == ConstraintKind::Normal);
        CHECK(merged[4].name == "normal 2");
        // The preset's own anchors replace the user's; its regions do not.
        std::vector<ConstraintSet> with_anchor = preset.sets;
        with_anchor.push_back(set("anchor", ConstraintKind::Anchor, {9}));
        with_anchor.push_back(set("region", ConstraintKind::Region, {9, 10}));
        const std::vector<ConstraintSet> replaced = merge_preset(user, with_anchor);
        CHECK(std::count_if(replaced.begin(), replaced.end(), [](const ConstraintSet& s) {
                  return s.kind == ConstraintKind::Anchor && s.vertices == std::vector<Index>{9};
              }) == 1);
        CHECK(std::count_if(replaced.begin(), replaced.end(), [](const ConstraintSet& s) {
                  return s.kind == ConstraintKind::Region;
              }) == 1);
        CHECK(std::none_of(replaced.begin(), replaced.end(), [](const ConstraintSet& s) {
            return s.vertices == std::vector<Index>{6, 7};
        }));
        // With no region of the user's, the preset's comes in.
        CHECK(merge_preset({}, with_anchor).size() == with_anchor.size());
    }
}
