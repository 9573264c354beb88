// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! What estimate_noise measured.
struct NoiseEstimate
{
    //! The noise's standard deviation along the surface normal, in mean edge lengths of
    //! the surface without it (0 when nothing could be measured).
    Scalar sigma = 0;
    //! The same in units of the mesh.
    Scalar height = 0;
    //! The mean edge length without the noise's part (units of the mesh).
    Scalar edge_length = 0;
    //! The interior vertices measured (those with a closed fan of faces).
    Index vertices = 0;
};

//! \brief Estimates the noise of a mesh from the mesh alone: how far each vertex stands off
//! its neighbours along its normal, against the edge lengths.
//!
//! For each interior vertex i (as many incident faces as neighbours: a closed fan) the
//! umbrella residual r_i = n_i . (x_i - (1/n_i) sum_{j in V(i)} x_j), n_i the normalized
//! sum of its faces' area vectors. Under independent Gaussian noise of deviation h along
//! the normal, r_i is Gaussian with deviation h sqrt(1 + 1/n_i) (the surface's own
//! curvature adds O(L^2 / R), small beside the noise the estimate is for), so
//!
//!     h = mean_i |r_i / sqrt(1 + 1/n_i)| / sqrt(2 / pi),
//!
//! the mean absolute deviation's scale. Not the median: under impulsive noise (a tenth of
//! the vertices thrown off) the median sees only the clean rest and finds none; the mean
//! counts the outliers, and creases and corners, a few vertices, move it little. The
//! noise also lengthens the edges: E|e|^2 = L^2 + 2 h^2 for a clean length L, so the
//! clean mean edge length is taken as sqrt(mean |e|^2 - 2 h^2) and sigma = h / L.
//! Noise along other directions counts by its normal part only, which is the part a
//! smoothing removes. Only vertices with `counted[i] != 0` are measured (all when empty).
//! \pre the topology has TopologyParts::Neighbors and TopologyParts::Corners; x: 3 #V.
NoiseEstimate estimate_noise(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                             std::span<const char> counted = {});

} // namespace meshfair
