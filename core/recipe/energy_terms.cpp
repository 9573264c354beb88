// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/energy_terms.h"

#include <array>

namespace meshfair {

namespace {

// The edge term is always on, unless the bending section weighs it 0 (the thin plate alone).
bool has_edge(const Recipe& r)
{
    return !r.bending || r.bending->membrane > 0;
}
bool has_bending(const Recipe& r)
{
    return r.bending.has_value();
}
bool has_soft(const Recipe& r)
{
    return r.soft.has_value();
}
bool has_centroid(const Recipe& r)
{
    return r.centroid.has_value();
}
bool has_normal(const Recipe& r)
{
    return r.normal.has_value();
}
bool has_normal_smoothing(const Recipe& r)
{
    return r.joint.has_value(); // the normals' own energy is a term in joint mode only
}
bool has_normal_soft(const Recipe& r)
{
    return r.joint && r.normal_smoothing && !r.normal_smoothing->soft.faces.empty();
}

constexpr std::array<EnergyTermInfo, 7> kTerms = {{
    {"edge", "edge", &TermEnergies::edge, EnergyTerm::Edge, has_edge},
    {"bending", "bending", &TermEnergies::bending, EnergyTerm::Bending, has_bending},
    {"soft", "anchor", &TermEnergies::soft, EnergyTerm::Soft, has_soft},
    {"centroid", "centroid", &TermEnergies::centroid, EnergyTerm::Centroid, has_centroid},
    {"normal", "normal", &TermEnergies::normal, EnergyTerm::Normal, has_normal},
    {"normal_smoothing", "normal smoothing", &TermEnergies::normal_smoothing, std::nullopt,
     has_normal_smoothing},
    {"normal_soft", "soft normals", &TermEnergies::normal_soft, std::nullopt, has_normal_soft},
}};

} // namespace

std::span<const EnergyTermInfo> energy_terms()
{
    return kTerms;
}

const EnergyTermInfo* energy_term(EnergyTerm term)
{
    for (const EnergyTermInfo& t : kTerms)
        if (t.shares == term)
            return &t;
    return nullptr;
}

} // namespace meshfair
