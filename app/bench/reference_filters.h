// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair::bench {

// Two reference methods for meshfair-quality, written from their papers independently of
// MeshFair's energies and Session (nothing of core/energies, core/recipe or core/solver but
// parallel_for). Polygons use the same formulas with their centroid and Newell normal.

//! Settings of bilateral_normal_filter; the defaults are the benchmark's.
struct BilateralSettings
{
    int normal_iterations = 20; //!< normal filtering passes
    Scalar sigma_r = 0.35;      //!< range kernel width, on |n_f - n_g|
    int vertex_iterations = 10; //!< vertex update passes
};

//! \brief Bilateral normal filtering (Zheng, Fu, Au, Tai 2011, "Bilateral normal filtering
//! for mesh denoising", its local scheme, with the vertex update of Sun et al. 2007), on x (3 #V,
//! modified in place).
//!
//! Face normals n_f, centroids c_f and areas A_f of the input; then normal_iterations times,
//! from the previous normals (Jacobi):
//!   n_f <- normalize(sum_{g in N(f)} A_g W_s(|c_f - c_g|) W_r(|n_f - n_g|) n_g),
//! N(f) = f and the faces sharing an edge with it, W(d) = exp(-d^2 / (2 sigma^2)), sigma_s
//! the mean distance between the centroids of faces sharing an edge, sigma_r from settings.
//! Then vertex_iterations times, from the current positions:
//!   x_i <- x_i + (1 / |F_i|) sum_{f containing i} n_f (n_f . (c_f - x_i)).
//! \pre the topology has TopologyParts::Corners and Dual; x holds 3 #V values.
void bilateral_normal_filter(const Mesh& mesh, const Topology& topology, std::span<Scalar> x,
                             const BilateralSettings& settings = {});

//! Settings of taubin_smooth; the defaults are the benchmark's.
struct TaubinSettings
{
    //! lambda|mu pairs: 20 by default, as many steps of each sign as the bundled recipe's
    //! 20 iterations (assets/recipes/combined.json).
    int pairs = 20;
    Scalar lambda = 0.5;
    Scalar mu = -0.53; //!< 0: plain Laplacian smoothing (lambda steps only)
};

//! \brief Taubin's lambda|mu smoothing (Taubin 1995, "A signal processing approach to fair
//! surface design") with the uniform (umbrella) Laplacian of the edge graph,
//! dx_i = (1 / n_i) sum_{j in V(i)} (x_j - x_i): per pair x <- x + lambda dx, then
//! x <- x + mu dx (dx recomputed). Every vertex moves; x (3 #V) is modified in place.
//! \pre the topology has TopologyParts::Neighbors; x holds 3 #V values.
void taubin_smooth(const Topology& topology, std::span<Scalar> x,
                   const TaubinSettings& settings = {});

} // namespace meshfair::bench
