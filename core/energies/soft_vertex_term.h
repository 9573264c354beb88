// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/energies/index_list.h"
#include "core/energies/position_term.h"
#include "core/types.h"

namespace meshfair {

//! \brief Soft vertex constraints \cite taubin_2012 ("Vertex Position Constraints"), with
//! a weight per constrained vertex:
//!
//!     E_S(x) = sum_{i in V_S} mu_i |x_i - x0_i|^2,     mu_i = mu w_i >= 0, x0 of size 3 #V_S
//!
//! w_i = weights[k] for the k-th listed vertex (all 1 when weights is empty: the paper's
//! single mu). Gradient 2 mu_i (x_i - x0_i) on constrained vertices. Generalized Jacobi:
//! diagonal += mu_i, rhs += mu_i (x0_i - x_i); with the edge term this is the paper's
//! update dx_i = (sum_j (x_j - x_i) + mu_i (x0_i - x_i)) / (n_i + mu_i). The energy scales
//! linearly in each mu_i; A_S = D_S. Moving targets (set_targets) changes the right-hand
//! side only. Without weights the arithmetic is that of one mu (mu sum |x_i - x0_i|^2).
class SoftVertexTerm final : public PositionTerm
{
public:
    //! \pre vertices distinct and < vertex_count; targets empty (every target at the origin
    //! until set_targets or set_targets_at) or 3 values per listed vertex; weights empty or
    //! one per listed vertex, each finite and >= 0 (as mu).
    SoftVertexTerm(Index vertex_count, std::vector<Index> vertices, Scalar mu,
                   std::span<const Scalar> targets = {}, std::span<const Scalar> weights = {});
    // Not copyable: the targets may be a view of the term's own array.
    SoftVertexTerm(const SoftVertexTerm&) = delete;
    SoftVertexTerm& operator=(const SoftVertexTerm&) = delete;

    void set_targets(std::span<const Scalar> targets);
    //! Targets at positions `x` (3 #V) of the listed vertices: no gathered copy.
    void set_targets_at(std::span<const Scalar> x);
    //! Targets at positions `x` (3 #V) of the listed vertices, read from `x` itself, with no
    //! copy: a session's initial positions, shared with the centroid term (24 bytes a vertex
    //! saved). \pre x stays alive and unchanged until the next set_targets or set_targets_at
    //! (which copy it first) or the term's end.
    void view_targets(std::span<const Scalar> x);
    Scalar mu() const { return mu_; }
    //! True when the vertices have weights of their own (not all mu).
    bool has_weights() const { return has_weights_; }
    //! mu_i: mu w_i on constrained vertices, 0 elsewhere.
    Scalar weight(Index i) const
    {
        return has_weights_ ? weight_[i] : (listed_[i] ? mu_ : Scalar(0));
    }
    //! The listed vertices (no list stored when every vertex, in order).
    const IndexList& vertices() const { return vertices_; }

    EnergyTerm kind() const override { return EnergyTerm::Soft; }
    Scalar energy(std::span<const Scalar> x) const override;
    //! Adds mu_i |x_i - x0_i|^2 to per_vertex[i] (#V) for each constrained vertex.
    void add_vertex_energy(std::span<const Scalar> x, std::span<Scalar> per_vertex) const override;
    //! The constrained vertices that are not free.
    Scalar held_energy(std::span<const Scalar> x, std::span<const char> is_free) const override;
    Scalar quadratic(std::span<const Scalar> dx) const override;
    void add_diagonal(std::span<Scalar> diagonal) const override;
    //! Column i of the half Hessian: mu_i at i (A_S = D_S, diagonal).
    void add_hessian_column(Index i, HessianColumn& column) const override
    {
        if (const Scalar w = weight(i); w != 0)
            column.add(i, w);
    }
    void add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                 std::span<Scalar> rhs) const override;
    //! One vertex's part: r[a] += mu_i (t_i - x_i)[a] (mu_i = 0 off the constrained set);
    //! with Energy, also *energy += mu_i |x_i - t_i|^2, the vertex's part of energy(x).
    template <bool Energy = false>
    void add_vertex_rhs(Index i, const Scalar* x, Scalar* r, Scalar* energy = nullptr) const
    {
        Scalar squared = 0;
        const Scalar w = weight(i);
        for (int a = 0; a < 3; ++a)
        {
            const Scalar d = target_[3 * i + a] - x[3 * i + a];
            r[a] += w * d;
            squared += d * d;
        }
        if constexpr (Energy)
            *energy += w * squared;
    }
    //! The vertex's part of energy(x): mu_i |x_i - t_i|^2 (0 off the constrained set).
    Scalar vertex_part(Index i, const Scalar* x) const
    {
        Scalar r[3] = {0, 0, 0}, e = 0;
        add_vertex_rhs<true>(i, x, r, &e);
        return e;
    }

private:
    //! Owns the targets unless they are a view (view_targets); copied before a change.
    void own_targets();

    Scalar mu_;
    bool has_weights_;
    IndexList vertices_;         //!< no list stored when every vertex, in order (4 bytes a vertex)
    std::vector<Scalar> weight_; //!< #V with weights: mu_i on constrained vertices, 0 elsewhere
    std::vector<char> listed_;   //!< #V without weights (mu_i = mu or 0): 1 byte, not 8
    std::vector<Scalar> own_target_; //!< 3 #V, or empty while target_ is a view
    std::span<const Scalar> target_; //!< 3 #V: own_target_ or view_targets's positions
};

} // namespace meshfair
