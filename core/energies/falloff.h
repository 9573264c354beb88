// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/topology/topology.h"

namespace meshfair {

//! Blender's proportional-editing curves: the weight at a fraction t in [0, 1] of the
//! radius (0 at the source, 1 at the radius).
enum class FalloffCurve
{
    Smooth,  //!< 3 s^2 - 2 s^3, s = 1 - t
    Sphere,  //!< sqrt(1 - t^2)
    Root,    //!< sqrt(1 - t)
    Linear,  //!< 1 - t
    Sharp,   //!< (1 - t)^2
    Constant //!< 1
};

//! "smooth", "sphere", "root", "linear", "sharp", "constant" (recipes, the editor, scripts).
std::string_view falloff_curve_name(FalloffCurve curve);
std::optional<FalloffCurve> falloff_curve_named(std::string_view name);

//! \brief A falloff's weight at distance d for a radius r > 0: curve(d / r) for d < r, 0
//! from r on (the constant curve too). r = 0: 1 at d = 0 (the sources), else 0.
Scalar falloff_weight(FalloffCurve curve, Scalar d, Scalar radius);

//! Distances along the surface from a set of source vertices, and the nearest source.
struct SurfaceDistances
{
    std::vector<Scalar> distance; //!< #V: +infinity where no source is reachable
    std::vector<Index> source;    //!< #V: index into the source list, kInvalidIndex if none
};

//! \brief Shortest-path distances along the edges of the primal graph (each edge as long as
//! at positions x), from every source at once (Dijkstra), stopping beyond `limit`: the
//! distances up to `limit` are exact for the edge graph, the others are +infinity. The
//! edge-graph distance approximates the geodesic one from above. Ties go to the source
//! listed first.
//! \pre the topology has TopologyParts::Neighbors; sources distinct and < #V.
SurfaceDistances surface_distances(const Topology& topology, std::span<const Scalar> x,
                                   std::span<const Index> sources, Scalar limit);

} // namespace meshfair
