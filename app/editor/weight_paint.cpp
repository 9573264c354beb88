// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/weight_paint.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace meshfair::app {

DabReach dab_reach(std::span<const Scalar> positions, const Vec3& center, Scalar radius,
                   Scalar strength, FalloffCurve curve)
{
    DabReach reach;
    const size_t n = positions.size() / 3;
    const Scalar r2 = radius * radius;
    for (size_t i = 0; i < n; ++i)
    {
        Scalar d2 = 0;
        for (size_t a = 0; a < 3; ++a)
        {
            const Scalar t = positions[3 * i + a] - center[a];
            d2 += t * t;
        }
        if (!(d2 < r2))
            continue;
        const Scalar amount = strength * falloff_weight(curve, std::sqrt(d2), radius);
        if (amount > 0)
        {
            reach.vertices.push_back(static_cast<Index>(i));
            reach.amounts.push_back(amount);
        }
    }
    return reach;
}

size_t paint_weights(ConstraintSet& set, const ConstraintSet* stroke_start,
                     const Topology& topology, const DabReach& reach, PaintMode mode)
{
    if (set.weights.empty())
        set.weights.assign(set.vertices.size(), 1);
    // Where each vertex is in the set (-1: not in it).
    std::vector<Index> slot(static_cast<size_t>(topology.vertex_count), -1);
    for (size_t k = 0; k < set.vertices.size(); ++k)
        slot[static_cast<size_t>(set.vertices[k])] = static_cast<Index>(k);
    const auto weight = [&](Index v) {
        const Index k = slot[static_cast<size_t>(v)];
        return k < 0 ? Scalar(0) : set.weights[static_cast<size_t>(k)];
    };
    // The weights when the stroke began.
    std::vector<Scalar> start(reach.vertices.size(), 0);
    if (stroke_start == nullptr)
        for (size_t r = 0; r < reach.vertices.size(); ++r)
            start[r] = weight(reach.vertices[r]);
    else
    {
        std::vector<Index> was(static_cast<size_t>(topology.vertex_count), -1);
        for (size_t k = 0; k < stroke_start->vertices.size(); ++k)
            was[static_cast<size_t>(stroke_start->vertices[k])] = static_cast<Index>(k);
        for (size_t r = 0; r < reach.vertices.size(); ++r)
            if (const Index k = was[static_cast<size_t>(reach.vertices[r])]; k >= 0)
                start[r] = map_value(*stroke_start, static_cast<size_t>(k));
    }
    // The new values from the old ones first, then written: a dab is one Jacobi sweep.
    std::vector<Scalar> next(reach.vertices.size());
    for (size_t r = 0; r < reach.vertices.size(); ++r)
    {
        const Index v = reach.vertices[r];
        const Scalar a = reach.amounts[r], w = weight(v);
        switch (mode)
        {
            case PaintMode::Relax:
            case PaintMode::Add:
                next[r] = std::max(w, std::min<Scalar>(1, start[r] + a));
                break;
            case PaintMode::Subtract:
                next[r] = std::min(w, std::max<Scalar>(0, start[r] - a));
                break;
            case PaintMode::Smooth:
            {
                const std::span<const Index> ring = topology.neighbors(v);
                Scalar mean = 0;
                for (const Index u : ring)
                    mean += weight(u);
                mean = ring.empty() ? w : mean / static_cast<Scalar>(ring.size());
                next[r] = std::clamp<Scalar>((1 - a) * w + a * mean, 0, 1);
                break;
            }
        }
    }
    size_t changed = 0;
    for (size_t r = 0; r < reach.vertices.size(); ++r)
    {
        const Index v = reach.vertices[r];
        const Index k = slot[static_cast<size_t>(v)];
        if (k < 0)
        {
            if (next[r] <= 0)
                continue; // only painting up brings a vertex in
            set.vertices.push_back(v);
            set.weights.push_back(next[r]);
            slot[static_cast<size_t>(v)] = static_cast<Index>(set.vertices.size() - 1);
            ++changed;
        }
        else if (set.weights[static_cast<size_t>(k)] != next[r])
        {
            set.weights[static_cast<size_t>(k)] = next[r];
            ++changed;
        }
    }
    return changed;
}

std::vector<float> weight_colors(const ConstraintSet& set, Index vertex_count,
                                 const std::array<float, 3>& surface, float opacity)
{
    // Blender's weight colours: blue, cyan, green, yellow, red at 0, 1/4, 1/2, 3/4, 1.
    static constexpr std::array<std::array<float, 3>, 5> ramp = {
        {{0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}};
    const auto color = [&](Scalar w) {
        const float t = static_cast<float>(std::clamp<Scalar>(w, 0, 1)) * 4;
        const int i = std::min(3, static_cast<int>(t));
        const float f = t - static_cast<float>(i);
        std::array<float, 3> c{};
        for (size_t a = 0; a < 3; ++a)
            c[a] =
                ramp[static_cast<size_t>(i)][a] * (1 - f) + ramp[static_cast<size_t>(i) + 1][a] * f;
        return c;
    };
    std::vector<float> rgb(3 * static_cast<size_t>(vertex_count));
    for (size_t i = 0; i < static_cast<size_t>(vertex_count); ++i)
        std::copy(surface.begin(), surface.end(), rgb.begin() + static_cast<std::ptrdiff_t>(3 * i));
    for (size_t k = 0; k < set.vertices.size(); ++k)
    {
        const Scalar w = map_value(set, k);
        if (!(w > 0))
            continue; // the surface as it is
        std::array<float, 3> c = color(w);
        for (size_t a = 0; a < 3; ++a)
            c[a] = (1 - opacity) * surface[a] + opacity * c[a];
        std::copy(
            c.begin(), c.end(),
            rgb.begin() + static_cast<std::ptrdiff_t>(3 * static_cast<size_t>(set.vertices[k])));
    }
    return rgb;
}

} // namespace meshfair::app
