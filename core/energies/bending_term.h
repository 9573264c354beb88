// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/energies/position_term.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief The thin-plate (bending) energy of discrete fairing: the squared umbrella
//! operator \cite kobbelt_1998, the second-order counterpart of the paper's edge energy:
//!
//!     E_B(x) = mu sum_k |u_k|^2,   u_k = (1/m_k) sum_{j in U(k)} x_j - x_k,
//!
//! with U(k) = V(k), m_k = n_k for a vertex inside the surface (singular edges included).
//! On an open boundary a vertex's umbrella follows the boundary curve: U(k) is its two
//! neighbours along the boundary (m_k = 2), so a straight, evenly sampled border costs
//! nothing and a scan's border is not pulled inward, as the full umbrella would pull it;
//! a vertex with one or three or more boundary edges (where holes touch) and an isolated
//! vertex have no u_k. E_B = mu x^T L^T L x per coordinate (L the umbrella operator with
//! those rows): quadratic, homogeneous and positive semi-definite, zero on a flat evenly
//! sampled patch, whatever the scale or the position; its minimizer with a ring of
//! vertices held is smooth across the ring (C1), where the edge energy's is a membrane
//! that meets it with a crease and answers a point load with a horn.
//!
//! Half Hessian A_B = mu L^T L (a 2-ring stencil); r_i = -1/2 dE_B/dx_i
//! = mu (u_i - sum_{k: i in U(k)} u_k / m_k); Jacobi diagonal
//! mu (1 [i has a row] + sum_{k: i in U(k)} 1 / m_k^2). A Jacobi step is stable for
//! lambda <= 0.5 on any mesh (the spectral radius of D^-1 A_B is below 4); the direct
//! method solves the term exactly.
class BendingTerm final : public PositionTerm
{
public:
    //! \pre mu finite and >= 0.
    //! \throw SolverError unless the topology has TopologyParts::Neighbors and
    //! TopologyParts::Edges (its boundary edges).
    BendingTerm(const Topology& topology, Scalar mu);
    //! The vertices (ascending) whose right-hand side add_rhs gives: it precomputes which
    //! u_k they read. None until called.
    void set_free(std::span<const Index> free);

    Scalar mu() const { return mu_; }
    EnergyTerm kind() const override { return EnergyTerm::Bending; }
    Scalar energy(std::span<const Scalar> x) const override;
    //! Adds mu |u_k|^2 to per_vertex[k] (#V): the shares sum to the energy.
    void add_vertex_energy(std::span<const Scalar> x, std::span<Scalar> per_vertex) const override;
    //! The umbrellas u_k whose centre k and members are all held.
    Scalar held_energy(std::span<const Scalar> x, std::span<const char> is_free) const override;
    //! E_B(dx): E_B(x + dx) = E_B(x) - 2 r^T dx + quadratic(dx).
    Scalar quadratic(std::span<const Scalar> dx) const override { return energy(dx); }
    void add_diagonal(std::span<Scalar> diagonal) const override;
    //! Column i of A_B = mu L^T L: its 2-ring, isotropic.
    void add_hessian_column(Index i, HessianColumn& column) const override;
    //! rhs_i += r_i for each vertex given to set_free (`vertices` must be those). Not
    //! reentrant: it keeps the u_k it reads between calls (no allocation per step).
    void add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                 std::span<Scalar> rhs) const override;

private:
    //! True when vertex k has a row u_k.
    bool has_row(Index k) const { return row_size_[k] != 0; }
    //! True when i is in U(k), for k in V(i).
    bool in_umbrella(Index k, Index i) const
    {
        return row_size_[k] > 0 && (curve_.empty() || curve_[2 * k] == kInvalidIndex ||
                                    curve_[2 * k] == i || curve_[2 * k + 1] == i);
    }
    //! u_k at x into u (3 values); k must have a row.
    void umbrella(Index k, const Scalar* x, Scalar* u) const;

    const Topology* topology_;
    Scalar mu_;
    //! m_k: the umbrella's size (0: no row)
    std::vector<Index> row_size_;
    //! 2 #V: a boundary vertex's two neighbours along the boundary, else kInvalidIndex;
    //! empty on a surface without boundary
    std::vector<Index> curve_;
    std::vector<Index> free_;
    //! The vertices whose u_k add_rhs reads: the free ones and their neighbours, with rows
    std::vector<Index> needed_;
    mutable std::vector<Scalar> u_; //!< 3 #V, u_k at needed_ after add_rhs
};

} // namespace meshfair
