// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/falloff.h"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace meshfair {

namespace {

constexpr std::pair<std::string_view, FalloffCurve> kCurves[] = {
    {"smooth", FalloffCurve::Smooth}, {"sphere", FalloffCurve::Sphere},
    {"root", FalloffCurve::Root},     {"linear", FalloffCurve::Linear},
    {"sharp", FalloffCurve::Sharp},   {"constant", FalloffCurve::Constant}};

Scalar edge_length(std::span<const Scalar> x, Index i, Index j)
{
    Scalar sum = 0;
    for (int a = 0; a < 3; ++a)
    {
        const Scalar d = x[3 * static_cast<size_t>(i) + a] - x[3 * static_cast<size_t>(j) + a];
        sum += d * d;
    }
    return std::sqrt(sum);
}

} // namespace

std::string_view falloff_curve_name(FalloffCurve curve)
{
    for (const auto& [name, c] : kCurves)
        if (c == curve)
            return name;
    return "smooth";
}

std::optional<FalloffCurve> falloff_curve_named(std::string_view name)
{
    for (const auto& [n, c] : kCurves)
        if (n == name)
            return c;
    return std::nullopt;
}

Scalar falloff_weight(FalloffCurve curve, Scalar d, Scalar radius)
{
    if (!(radius > 0))
        return d == 0 ? 1 : 0;
    if (!(d < radius))
        return 0;
    const Scalar t = d / radius, s = 1 - t;
    switch (curve)
    {
        case FalloffCurve::Smooth:
            return 3 * s * s - 2 * s * s * s;
        case FalloffCurve::Sphere:
            return std::sqrt(1 - t * t);
        case FalloffCurve::Root:
            return std::sqrt(s);
        case FalloffCurve::Linear:
            return s;
        case FalloffCurve::Sharp:
            return s * s;
        case FalloffCurve::Constant:
            return 1;
    }
    return 0;
}

SurfaceDistances surface_distances(const Topology& topology, std::span<const Scalar> x,
                                   std::span<const Index> sources, Scalar limit)
{
    const Index nv = topology.vertex_count;
    SurfaceDistances out;
    out.distance.assign(nv, std::numeric_limits<Scalar>::infinity());
    out.source.assign(nv, kInvalidIndex);
    using Item = std::pair<Scalar, Index>; // (distance, vertex)
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (size_t k = 0; k < sources.size(); ++k)
        if (out.source[sources[k]] == kInvalidIndex)
        {
            out.distance[sources[k]] = 0;
            out.source[sources[k]] = static_cast<Index>(k);
            queue.emplace(0, sources[k]);
        }
    while (!queue.empty())
    {
        const auto [d, i] = queue.top();
        queue.pop();
        if (d > out.distance[i])
            continue; // a stale entry
        for (const Index j : topology.neighbors(i))
        {
            const Scalar next = d + edge_length(x, i, j);
            if (next > limit)
                continue;
            // Equal distances keep the first source that reached the vertex.
            if (next < out.distance[j])
            {
                out.distance[j] = next;
                out.source[j] = out.source[i];
                queue.emplace(next, j);
            }
        }
    }
    return out;
}

} // namespace meshfair
