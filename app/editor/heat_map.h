// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/recipe/session.h"

namespace meshfair::app {

//! The heat map's terms, in its menu's order: the total, then each term with per-vertex
//! shares in energy_terms()'s order.
std::span<const EnergyTerm> heat_terms();
//! "total", or the term's label in energy_terms() ("edge", "anchor", ...): the heat map
//! menu's and scripts' word.
std::string_view heat_term_name(EnergyTerm term);
std::optional<EnergyTerm> heat_term_named(std::string_view name);

//! \brief Per-vertex colours (RGB in [0, 1], 3 per value) for each vertex's share of a term:
//! dark blue for none, through teal and yellow, to red at the 99th percentile of the
//! positive shares and above (so that a few extreme vertices do not wash out the rest).
//! With `shown` (#V flags, or empty: all), only those vertices are coloured and count for
//! the percentile; the others get the neutral grey kHeatHidden (a region's fixed vertices,
//! whose energy no step changes).
std::vector<float> heat_colors(std::span<const Scalar> shares, std::span<const char> shown = {});

} // namespace meshfair::app
