// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/energies/bilateral_face_weights.h"
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
//!
//! With bilateral weights (set_weights) the dual edges weigh w_fg and the neighbours may be
//! the faces sharing a vertex: E_U(u) = sum_{f~g} w_fg |u_f - u_g|^2 + soft terms (each
//! pair once), whose Jacobi step is
//! du_f = (sum_g w_fg (u_g - u_f) + mu_f [f in F_S] (u0_f - u_f)) / (sum_g w_fg + mu_f [f in F_S]).
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

    //! \brief Weighs the face graph with `weights` (kept by the caller, outliving this
    //! term; nullptr: every dual edge weighs 1 again, the paper's E_U bit for bit).
    void set_weights(const BilateralFaceWeights* weights) { weights_ = weights; }
    const BilateralFaceWeights* weights() const { return weights_; }
    //! sum_g w_fg over f's neighbours (n*_f without weights).
    Scalar neighbor_weight_sum(Index f) const
    {
        return weights_ ? weights_->weight_sum(f) : static_cast<Scalar>(topology_->dual_valence(f));
    }
    //! visit(g, w_fg) for each neighbour g of f (w_fg = 1 without weights).
    template <class Visit>
    void for_each_neighbor(Index f, Visit&& visit) const
    {
        if (!weights_)
        {
            for (const Index g : topology_->face_neighbors_of(f))
                visit(g, Scalar(1));
            return;
        }
        const std::span<const Index> faces = weights_->neighbors_of(f);
        const std::span<const Scalar> w = weights_->weights_of(f);
        for (size_t k = 0; k < faces.size(); ++k)
            visit(faces[k], w[k]);
    }

    //! sum over E* of |u_f - u_g|^2 (of w_fg |u_f - u_g|^2 over the weighed pairs).
    Scalar dual_energy(std::span<const Scalar> u) const;
    //! sum_{F_S} mu_f |u_f - u0_f|^2.
    Scalar soft_energy(std::span<const Scalar> u) const;
    //! Writes the hard normals into u.
    void apply_hard(std::span<Scalar> u) const;
    //! \brief The Jacobi displacements du (3 #F) of E_U at u, before lambda and the
    //! renormalization: du_f = r_f / D_f with r_f = -1/2 dE_U/du_f and D_f the diagonal
    //! (the weights' sum plus mu_f); 0 at hard faces and faces with D_f = 0.
    void displacements(std::span<const Scalar> u, std::span<Scalar> du) const;
    //! One generalized Jacobi step on E_U, then renormalization; `scratch` holds 3 #F.
    void step(std::span<Scalar> u, Scalar lambda, std::span<Scalar> scratch) const;

private:
    const Topology* topology_;
    const BilateralFaceWeights* weights_ = nullptr;
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
