// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

#include "core/errors.h"
#include "core/recipe/recipe.h"

namespace meshfair {

//! \brief Parses a recipe from JSON text (format in docs/recipe.md). Strict: unknown keys,
//! wrong types, non-integer indices, negative weights and non-finite numbers are refused.
//! Index ranges and set sizes need the mesh: see check_recipe.
//! \throw RecipeError naming the key; InvalidInputError for text that is not JSON
//! (naming `name` and the byte offset).
Recipe parse_recipe(std::string_view json_text, const std::string& name);

//! Reads and parses a recipe file. \throw as parse_recipe, or InvalidInputError when the
//! file cannot be read.
Recipe read_recipe(const std::string& path);

//! \brief The error for JSON text that does not parse, from nlohmann's parse_error
//! message ("... at line L, column C: why"): "'name':L:C: not valid JSON: why". Shared by
//! every JSON reader of MeshFair (recipes, the editor's scripts).
InvalidInputError json_syntax_error(const std::string& name, const std::string& parser_what);

//! The JSON form of a recipe; parse_recipe(recipe_to_json(r).dump()) gives r back.
nlohmann::json recipe_to_json(const Recipe& recipe);

//! \brief The "bilateral" object of a recipe's normal_smoothing (docs/recipe.md), parsed
//! with errors naming `key` ("normal_smoothing.bilateral" in a recipe); and its JSON form.
//! Shared with the editor's scripts and recovery files.
//! \throw RecipeError naming the key.
BilateralWeights parse_bilateral(const nlohmann::json& j, const std::string& key);
nlohmann::json bilateral_json(const BilateralWeights& b);
//! The same for a recipe's "falloff" object.
Falloff parse_falloff(const nlohmann::json& j, const std::string& key);
nlohmann::json falloff_json(const Falloff& f);
//! The "bending" section's object, read (RecipeError naming `key`'s members) and written.
Bending parse_bending(const nlohmann::json& j, const std::string& key);
nlohmann::json bending_json(const Bending& b);

} // namespace meshfair
