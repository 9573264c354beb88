// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "core/recipe/recipe.h"
#include "core/recipe/session.h"

namespace meshfair {

//! \brief One term of the recipe's energy as every reader names it: the report's and
//! Python's key, the editor's word (the heat map, the energy plot), its value in
//! TermEnergies, the heat map's EnergyTerm when the term has per-vertex shares, and
//! whether a recipe has it. The one table of names: a new term is one row here.
struct EnergyTermInfo
{
    std::string_view key;             //!< "edge", "soft", ... (report, Python)
    std::string_view label;           //!< "edge", "anchor", ... (heat map, plot)
    Scalar TermEnergies::*energy;     //!< its value
    std::optional<EnergyTerm> shares; //!< Session::vertex_energy's term; none: no shares
    bool (*in_recipe)(const Recipe&); //!< true when the recipe's energy has the term
};

//! Every term, in the order reports and plots list them.
std::span<const EnergyTermInfo> energy_terms();

//! The term whose shares are `term` (EnergyTerm::Total has none: nullptr).
const EnergyTermInfo* energy_term(EnergyTerm term);

} // namespace meshfair
