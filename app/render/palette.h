// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>

//! \file
//! \brief One colour per meaning, so that nothing drawn over the surface is taken for
//! something else: the selection, the mesh's boundary and singular edges, the tools'
//! overlays and each constraint-set kind (whose glyphs and list swatches share it). The
//! side panel's legend lists them.

namespace meshfair::app::palette {

using Rgb = std::array<float, 3>;

inline constexpr Rgb kSelection{0.05f, 0.85f, 0.95f};   //!< selected faces and vertices: cyan
inline constexpr Rgb kBoundary{1.00f, 0.55f, 0.05f};    //!< mesh boundary edges: orange
inline constexpr Rgb kSingular{0.95f, 0.10f, 0.85f};    //!< edges of 3+ faces: magenta
inline constexpr Rgb kBackFace{0.22f, 0.36f, 0.80f};    //!< the back-face tint
inline constexpr Rgb kToolOverlay{1.00f, 1.00f, 1.00f}; //!< brush ring, rectangle, lasso
inline constexpr Rgb kRegion{0.30f, 0.80f, 0.30f};      //!< a region's border ring: green
inline constexpr Rgb kPin{0.90f, 0.15f, 0.15f};         //!< red
inline constexpr Rgb kAnchor{0.25f, 0.45f, 1.00f};      //!< blue
inline constexpr Rgb kCentroid{1.00f, 0.60f, 0.80f};    //!< pink
inline constexpr Rgb kNormal{0.65f, 0.35f, 0.95f};      //!< violet
inline constexpr Rgb kHardNormal{0.10f, 0.60f, 0.50f};  //!< dark teal
inline constexpr Rgb kSoftNormal{0.70f, 0.95f, 0.60f};  //!< pale green
//! A heat map's vertices left out (a region's fixed ones): grey, no value of the ramp.
inline constexpr Rgb kHeatHidden{0.45f, 0.45f, 0.47f};

} // namespace meshfair::app::palette
