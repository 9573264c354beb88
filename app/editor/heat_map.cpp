// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/heat_map.h"

#include <algorithm>
#include <array>
#include <utility>

#include "app/render/palette.h"
#include "core/recipe/energy_terms.h"

namespace meshfair::app {

std::span<const EnergyTerm> heat_terms()
{
    static const std::vector<EnergyTerm> terms = [] {
        std::vector<EnergyTerm> t{EnergyTerm::Total};
        for (const EnergyTermInfo& info : energy_terms())
            if (info.shares)
                t.push_back(*info.shares);
        return t;
    }();
    return terms;
}

std::string_view heat_term_name(EnergyTerm term)
{
    if (term == EnergyTerm::Total)
        return "total";
    const EnergyTermInfo* info = energy_term(term);
    return info != nullptr ? info->label : std::string_view{};
}

std::optional<EnergyTerm> heat_term_named(std::string_view name)
{
    for (const EnergyTerm t : heat_terms())
        if (heat_term_name(t) == name)
            return t;
    return std::nullopt;
}

std::vector<float> heat_colors(std::span<const Scalar> shares, std::span<const char> shown)
{
    const auto is_shown = [&](size_t i) { return shown.empty() || shown[i] != 0; };
    std::vector<Scalar> positive;
    for (size_t i = 0; i < shares.size(); ++i)
        if (shares[i] > 0 && is_shown(i))
            positive.push_back(shares[i]);
    Scalar top = 0;
    if (!positive.empty())
    {
        const size_t k = std::min(positive.size() - 1, positive.size() * 99 / 100);
        std::nth_element(positive.begin(), positive.begin() + static_cast<long>(k), positive.end());
        top = positive[k];
    }
    static constexpr float stops[4][3] = {
        {0.10f, 0.14f, 0.45f}, {0.10f, 0.60f, 0.60f}, {0.95f, 0.85f, 0.20f}, {0.85f, 0.15f, 0.10f}};
    std::vector<float> rgb(3 * shares.size());
    for (size_t i = 0; i < shares.size(); ++i)
    {
        if (!is_shown(i))
        {
            std::copy(palette::kHeatHidden.begin(), palette::kHeatHidden.end(), &rgb[3 * i]);
            continue;
        }
        const double t = top > 0 ? std::clamp(shares[i] / top, 0.0, 1.0) : 0.0;
        const double x = 3 * t;
        const int s = std::min(static_cast<int>(x), 2);
        const float f = static_cast<float>(x - s);
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + static_cast<size_t>(c)] = stops[s][c] + f * (stops[s + 1][c] - stops[s][c]);
    }
    return rgb;
}

} // namespace meshfair::app
