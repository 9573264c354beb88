// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "core/io/checked_json.h"
#include "core/recipe/recipe.h"

namespace meshfair {

//! What a recipe may ask of its reader's memory.
struct RecipeLimits
{
    //! Indices listed in all, runs [first, last] counted whole: a run of a few bytes
    //! stands for as many indices as it spans.
    std::int64_t max_listed = std::int64_t{1} << 27;
};

//! \brief Parses a recipe from JSON text (format in docs/recipe.md). Strict: unknown keys,
//! wrong types, non-integer indices, negative weights and non-finite numbers are refused.
//! An index list holds indices and runs [first, last] (first <= last: every index from
//! first to last), as recipe_to_json writes them. Index ranges and set sizes need the
//! mesh: see check_recipe. The top-level "editor" object is the editor's (its sets' names,
//! colours and maps, the up axis): no part of the run, not read here.
//! \throw RecipeError naming `name` and the key; JsonSyntaxError for text that is not
//! JSON (naming `name`, the line and the column).
Recipe parse_recipe(std::string_view json_text, const std::string& name,
                    const RecipeLimits& limits = {});
//! The same from JSON parsed already (a reader that reads more of the file, the editor's
//! import). \throw RecipeError naming the file and the key.
Recipe parse_recipe(const CheckedJson& root, const RecipeLimits& limits = {});

//! Reads and parses a recipe file. \throw as parse_recipe, or InvalidInputError when the
//! file cannot be read.
Recipe read_recipe(const std::string& path);

//! \brief The JSON form of a recipe; parse_recipe(recipe_to_json(r).dump()) gives r back.
//! Index lists are written compactly (index_list_json).
nlohmann::json recipe_to_json(const Recipe& recipe);
//! \brief An index list as recipes write it: each run of 3 or more consecutive increasing
//! indices as [first, last], the others as they are, in the list's order (a scan's region
//! in its file's order shrinks as far as that order keeps neighbours together).
nlohmann::json index_list_json(std::span<const Index> indices);
//! \brief An index list as recipes write it, read: integers and runs [first, last], each
//! index in [0, 2147483647], no more than `budget` in all (taken from it).
//! \throw JsonValueError naming the list (and the item at fault: "key[3]").
std::vector<Index> parse_index_list(const CheckedJson& j, std::int64_t& budget);

//! \brief The "bilateral" object of a recipe's normal_smoothing (docs/recipe.md), parsed;
//! and its JSON form. Shared with the editor's scripts and recovery files.
//! \throw JsonValueError naming the key.
BilateralWeights parse_bilateral(const CheckedJson& j);
nlohmann::json bilateral_json(const BilateralWeights& b);
//! The same for a recipe's "falloff" object.
Falloff parse_falloff(const CheckedJson& j);
nlohmann::json falloff_json(const Falloff& f);
//! The "bending" section's object, read and written.
Bending parse_bending(const CheckedJson& j);
nlohmann::json bending_json(const Bending& b);

} // namespace meshfair
