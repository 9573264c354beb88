// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>

#include "core/energies/face_normal_term.h"
#include "core/energies/normal_smoothing_term.h"

namespace meshfair {

//! \brief Joint optimization of positions x and normals u \cite taubin_2012 ("Smoothing
//! Face Normal Vectors", last performance function):
//!
//!     E(x, u) = E_L(x) + sum_{f in F_N} mu_f sum_{(i,j) in E(f)} (u_f^T (x_j - x_i))^2
//!               + gamma sum_{(f,g) in E*} |u_f - u_g|^2 + sum_{f in F_S} mu_S,f |u_f - u0_f|^2
//!
//! The x part is the face-normal term's update with the current u. This file holds the
//! u part, which the paper leaves to the reader: minimizing E in u_f alone gives
//!
//!     (mu_f [f in F_N] M_f + (gamma n*_f + mu_S,f [f in F_S]) I) u_f
//!         = gamma sum_{g in N*(f)} u_g + mu_S,f [f in F_S] u0_f,
//!
//! M_f = sum_{(i,j) in E(f)} (x_j - x_i)(x_j - x_i)^T, a 3x3 SPD solve per face (Cholesky).
//! Then u_f += lambda (u_f* - u_f) and u_f is renormalized. Hard faces keep their normals;
//! a face whose matrix is singular (no dual neighbour, no soft constraint and a planar
//! polygon) keeps its normal. Weights: gamma >= 0; mu_f (FaceNormalTerm::face_weight) and
//! mu_S,f (NormalSmoothingTerm::soft_weight), the per-face weights, >= 0. With bilateral
//! weights on the smoothing term, gamma n*_f becomes gamma sum_g w_fg and each u_g weighs
//! gamma w_fg (NormalSmoothingTerm::for_each_neighbor); session reweights them.
class JointTerm
{
public:
    JointTerm(const FaceNormalTerm& normal_term, const NormalSmoothingTerm& smoothing,
              const Topology& topology, Scalar gamma);

    Scalar gamma() const { return gamma_; }
    //! gamma sum_{E*} |u_f - u_g|^2 (the soft part is smoothing.soft_energy).
    Scalar dual_energy(std::span<const Scalar> u) const
    {
        return gamma_ * smoothing_->dual_energy(u);
    }
    //! -1/2 dE/du_f at (x, u), for tests of the derivation.
    void normal_rhs(std::span<const Scalar> x, std::span<const Scalar> u, Index f, Scalar* r) const;
    //! The exact minimizer u_f* of E in u_f alone (before renormalization); false when
    //! the 3x3 matrix is singular.
    bool minimizer(std::span<const Scalar> x, std::span<const Scalar> u, Index f,
                   Scalar* out) const;
    //! One Jacobi step on all non-hard normals; `scratch` holds 3 #F.
    void update_normals(std::span<const Scalar> x, std::span<Scalar> u, Scalar lambda,
                        std::span<Scalar> scratch) const;

private:
    const FaceNormalTerm* normal_term_;
    const NormalSmoothingTerm* smoothing_;
    const Topology* topology_;
    Scalar gamma_;
};

} // namespace meshfair
