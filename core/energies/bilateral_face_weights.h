// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/energies/patch_guidance.h"
#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! Which faces a face's normal is smoothed with.
enum class FaceNeighborhood
{
    Edge,  //!< N*(f): the faces sharing an edge with f (the paper's dual graph)
    Vertex //!< the faces sharing a vertex with f (wider: fewer iterations, rounder corners)
};

//! \brief Bilateral weights of the dual graph's edges (feature-preserving normal
//! smoothing, see BilateralFaceWeights below): w_fg = exp(-|c_f - c_g|^2 / 2 sigma_s^2) *
//! exp(-|u_f - u_g|^2 / 2 sigma_r^2), recomputed from the current normals every
//! `reweight_every` iterations.
struct BilateralWeights
{
    //! sigma_s over the mean distance between the centroids of faces sharing an edge
    Scalar sigma_s = 1;
    Scalar sigma_r = 0.35; //!< in units of |u_f - u_g| (0 .. 2), dimensionless
    int reweight_every = 1;
    FaceNeighborhood neighbors = FaceNeighborhood::Edge;
    //! sigma_r is at least noise_scale times the median of |u_f - u_g| over the neighbouring
    //! faces at each reweighting (0: sigma_r as given)
    Scalar noise_scale = 1.5;
    //! the range kernel compares guidance normals (PatchGuidance: each face's most
    //! consistent patch's mean normal, from the current normals) instead of the normals
    //! themselves: guided mesh normal filtering \cite zhang_2015
    bool guided = false;
    bool operator==(const BilateralWeights&) const = default;
};

//! \brief Bilateral weights of the face graph, for feature-preserving normal smoothing
//! \cite zheng_2011: for faces f, g that are neighbours (sharing an edge: the paper's dual
//! graph E*; or, as an option, sharing a vertex)
//!
//!     w_fg = exp(-|c_f - c_g|^2 / 2 sigma_s^2) * exp(-|u_f - u_g|^2 / 2 sigma_r^2),
//!
//! c the face centroids, u the unit face normals. Used by NormalSmoothingTerm as the
//! weights of E_U(u) = sum_{f~g} w_fg |u_f - u_g|^2 + soft terms: with the weights held,
//! each stage is a quadratic of the paper's form, minimized by the same Jacobi step.
//! Recomputing them from the current normals (reweight) is iteratively reweighted least
//! squares of the robust energy
//!
//!     E_R(u) = sum_{f~g} s_fg sigma_r^2 (1 - exp(-|u_f - u_g|^2 / 2 sigma_r^2)),
//!
//! s_fg the spatial factor: (d/dr^2) of a pair's part is s_fg exp(-r^2 / 2 sigma_r^2) / 2,
//! proportional to w_fg, so each reweighted stage's quadratic majorizes E_R up to a constant
//! (Welsch's function is concave in r^2) and lowering it lowers E_R. Across a crease the
//! normals differ by far more than sigma_r: the pair's weight vanishes and the crease is
//! not smoothed away. Derivation in docs/math.md ("Feature-preserving normal smoothing").
//!
//! sigma_s is given relative to the mean distance between the centroids of faces sharing
//! an edge (at the positions the weights are built with) and sigma_r in units of the normals
//! (0 .. 2), so the same settings fit any scale. When that mean is 0 (no dual edge, or all
//! faces degenerate) the spatial factor is 1.
//!
//! Strong noise makes neighbouring normals differ by more than any crease-keeping sigma_r,
//! and a fixed sigma_r would then keep the noise as if it were features. Each reweighting
//! therefore uses sigma_r' = max(sigma_r, noise_scale * m), m the median of |u_f - u_g|
//! over the neighbour pairs (a robust scale of the normals' noise, as robust statistics
//! scale residuals by their median): while the normals are noisy sigma_r' is wide and
//! smooths; as they settle m falls and sigma_r' returns to sigma_r, which keeps creases
//! (features are few, so they barely move the median). The median is taken over at most
//! 2^20 pairs, every k-th in list order (deterministic).
class BilateralFaceWeights
{
public:
    //! \pre the topology has TopologyParts::Dual, and TopologyParts::Corners for
    //! FaceNeighborhood::Vertex; settings.sigma_s > 0, settings.sigma_r > 0 (check_recipe);
    //! x: 3 #V positions (for sigma_s). Every weight is 1 until reweight().
    BilateralFaceWeights(const Mesh& mesh, const Topology& topology,
                         const BilateralWeights& settings, std::span<const Scalar> x);

    //! The faces weighed against f (sorted; f itself excluded).
    std::span<const Index> neighbors_of(Index f) const
    {
        return {neighbors_.data() + offsets_[f],
                static_cast<size_t>(offsets_[f + 1] - offsets_[f])};
    }
    //! w_fg for each face g of neighbors_of(f), in the same order.
    std::span<const Scalar> weights_of(Index f) const
    {
        return {weights_.data() + offsets_[f], static_cast<size_t>(offsets_[f + 1] - offsets_[f])};
    }
    //! sum_g w_fg, the diagonal of face f's Jacobi step.
    Scalar weight_sum(Index f) const { return weight_sum_[f]; }
    //! sigma_s in units of the mesh (the setting times the mean centroid distance).
    Scalar sigma_s() const { return sigma_s_; }
    Scalar sigma_r() const { return sigma_r_; }
    //! The sigma_r' of the last reweight (sigma_r before any).
    Scalar effective_sigma_r() const { return effective_sigma_r_; }
    int reweight_every() const { return reweight_every_; }

    //! \brief Recomputes every w_fg from positions x (3 #V, for the centroids) and normals
    //! u (3 #F). Allocates nothing; the same bits for any thread count.
    void reweight(std::span<const Scalar> x, std::span<const Scalar> u);
    //! The robust energy E_R(u) with the spatial factors and sigma_r' of the last reweight
    //! (all 1 and sigma_r before any).
    Scalar robust_energy(std::span<const Scalar> u) const;

private:
    const Mesh* mesh_;
    std::vector<Index> offsets_, neighbors_; //!< CSR of each face's neighbours
    std::vector<Scalar> spatial_;            //!< s_fg, per CSR entry
    std::vector<Scalar> weights_;            //!< w_fg, per CSR entry
    std::vector<Scalar> weight_sum_;         //!< #F
    std::vector<Scalar> centroids_;          //!< 3 #F, the centroids spatial_ was taken at
    bool spatial_current_ = false;           //!< spatial_ is of centroids_
    std::vector<Scalar> sample_;             //!< the median's scratch (sampled pairs)
    std::optional<PatchGuidance> guidance_;  //!< with BilateralWeights::guided
    std::vector<Scalar> guide_;              //!< the guidance normals, 3 #F when guided
    Scalar sigma_s_ = 0, sigma_r_ = 0, noise_scale_ = 0, effective_sigma_r_ = 0;
    int reweight_every_ = 1;
};

//! \brief The mean distance between the centroids of the faces of each dual edge (faces
//! sharing a regular edge) at positions x; 0 when there is no dual edge.
//! \pre the topology has TopologyParts::Dual.
Scalar mean_dual_edge_length(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x);

} // namespace meshfair
