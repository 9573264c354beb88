// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <nlohmann/json.hpp>

#include "app/edit/constraint_sets.h"
#include "core/io/checked_json.h"

//! \file
//! \brief The editor's constraint sets and solver settings as JSON: what recovery files
//! keep and what Export recipe adds to the core's recipe (its "editor" object), so that
//! each reads back what the artist made: names, colours, weight maps, shown or not. Index
//! lists are written as runs (index_list_json). The readers refuse what no editor writes
//! with JsonValueError naming the key ("sets[2].color[1]") and what is wrong.

namespace meshfair::app {

nlohmann::json set_json(const ConstraintSet& set);
//! \brief A set of a mesh of `vertices` and `faces` elements: indices within them, one
//! target per vertex and one normal per face when given, colours in [0, 1], weights >= 0
//! (region: in [0, 1]) one per vertex of an anchor or region set.
//! \throw JsonValueError naming the key at fault.
ConstraintSet set_of(const CheckedJson& j, Index vertices, Index faces);

nlohmann::json settings_json(const SolverSettings& settings);
//! \brief Settings within what the editor can hold (weights >= 0, counts >= 1, ...);
//! keys that files of earlier versions lack take their defaults.
//! \throw as set_of.
SolverSettings settings_of(const CheckedJson& j);

//! \brief j[key], an integer from `lo` to 2147483647. \throw as set_of.
int count_at(const CheckedJson& j, const char* key, int lo);

} // namespace meshfair::app
