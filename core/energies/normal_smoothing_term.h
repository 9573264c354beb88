// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/topology/topology.h"

namespace meshfair {

//! \brief Face-normal smoothing on the dual graph \cite taubin_2012 ("Smoothing Face
//! Normal Vectors"), with hard and soft normal constraints, a weight per soft face:
//!
//!     E_U(u) = sum_{(f,g) in E*} |u_f - u_g|^2 + sum_{f in F_S} mu_f |u_f - u0_f|^2
//!
//! over unit normals u (3 #F), mu_f = mu w_f >= 0 (w_f = soft_weights[k] for the k-th soft
//! face, all 1 without weights); faces in F_H (hard) keep their given normals. Same form as
//! the edge and soft-vertex terms on the dual graph, so the generalized Jacobi step is
//! du_f = (sum_{g in N*(f)} (u_g - u_f) + mu_f [f in F_S] (u0_f - u_f)) / (n*_f + mu_f [f in F_S]),
//! u_f += lambda du_f, and then u_f is renormalized to unit length (a normal whose update
//! has zero length keeps its previous value). Faces with n*_f = 0 and no soft constraint
//! do not move. The renormalization makes the step a heuristic rather than a descent
//! step, as in the paper.
class NormalSmoothingTerm
{
public:
    //! \pre hard and soft face lists disjoint, each face < #F; normals 3 per listed face;
    //! soft_weights empty or one per soft face, each finite and >= 0 (as soft_mu).
    NormalSmoothingTerm(const Topology& topology, std::span<const Index> hard_faces,
                        std::span<const Scalar> hard_normals, std::span<const Index> soft_faces,
                        Scalar soft_mu, std::span<const Scalar> soft_normals,
                        std::span<const Scalar> soft_weights = {});

    bool is_hard(Index f) const { return !hard_.empty() && hard_[f] != 0; }
    //! mu_f of a soft face, 0 elsewhere.
    Scalar soft_weight(Index f) const { return soft_weight_.empty() ? 0 : soft_weight_[f]; }
    const Scalar* soft_target(Index f) const
    {
        static constexpr Scalar kNone[3] = {0, 0, 0};
        return soft_target_.empty() ? kNone : &soft_target_[3 * f];
    }
    bool has_soft() const { return !soft_faces_.empty(); }

    //! sum over E* of |u_f - u_g|^2.
    Scalar dual_energy(std::span<const Scalar> u) const;
    //! sum_{F_S} mu_f |u_f - u0_f|^2.
    Scalar soft_energy(std::span<const Scalar> u) const;
    //! Writes the hard normals into u.
    void apply_hard(std::span<Scalar> u) const;
    //! One generalized Jacobi step on E_U, then renormalization; `scratch` holds 3 #F.
    void step(std::span<Scalar> u, Scalar lambda, std::span<Scalar> scratch) const;

private:
    const Topology* topology_;
    std::vector<Index> hard_faces_, soft_faces_;
    // Per-face arrays exist only when there are hard (soft) faces: a recipe without
    // normal smoothing pays nothing for it (66 bytes per face otherwise).
    std::vector<char> hard_;          //!< #F, empty without hard faces
    std::vector<Scalar> hard_normal_; //!< 3 per hard face
    std::vector<Scalar> soft_weight_; //!< #F, empty without soft faces
    std::vector<Scalar> soft_target_; //!< 3 #F, empty without soft faces
};

//! Scales the 3-vector at v to unit length; leaves it (returns false) when its length is 0.
bool normalize3(Scalar* v);

} // namespace meshfair
