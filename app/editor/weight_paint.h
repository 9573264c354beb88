// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "app/edit/command.h"
#include "app/edit/constraint_sets.h"

namespace meshfair::app {

//! \brief The vertices a dab reaches and how much: those within `radius` of `center` (at
//! `positions`, 3 #V), each with strength * falloff_weight(curve, distance, radius) > 0, in
//! increasing vertex order.
struct DabReach
{
    std::vector<Index> vertices;
    std::vector<Scalar> amounts;
};
DabReach dab_reach(std::span<const Scalar> positions, const Vec3& center, Scalar radius,
                   Scalar strength, FalloffCurve curve);

//! \brief Paints a dab into a set's weight map (a vertex set: region or anchor), values kept
//! in [0, 1]; a set without a map gets one of 1s first. With an amount a at a vertex whose
//! weight was w0 when the stroke began (`stroke_start`: the set then, null when it was not
//! there; 0 for a vertex not in it):
//! - Add (and Relax): max(w, min(1, w0 + a)), a vertex not in the set joining it;
//! - Subtract: min(w, max(0, w0 - a));
//! - Smooth: (1 - a) w + a * the mean of its neighbours' weights (0 outside the set), from
//!   the weights before the dab (one Jacobi sweep).
//! So a stroke moves a weight by at most the strength however often its dabs overlap (as
//! weight painting does by default), while smoothing goes on as long as it is brushed.
//! Returns how many weights changed.
//! \pre takes_weight_map(set.kind); topology has the neighbour part.
size_t paint_weights(ConstraintSet& set, const ConstraintSet* stroke_start,
                     const Topology& topology, const DabReach& reach, PaintMode mode);

//! \brief Per-vertex colours of a weight map over the mesh (RGB in [0, 1], 3 #V), as
//! weight painting shows them: a translucent overlay over the surface's own colour
//! (`surface`), so that the shape a smoothing stroke makes stays readable under it: the
//! surface where the weight is 0 or the vertex is outside the set, and above 0 the
//! surface mixed, `opacity` of it, with Blender's ramp (cyan, green, yellow, red at 1).
std::vector<float> weight_colors(const ConstraintSet& set, Index vertex_count,
                                 const std::array<float, 3>& surface, float opacity = 0.5f);

} // namespace meshfair::app
