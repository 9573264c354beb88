// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>

#include "core/errors.h"
#include "core/solver/free_hessian.h"
#include "core/types.h"

namespace meshfair {

enum class EnergyTerm;

//! Value of each term of the recipe's energy; inactive terms are 0.
struct TermEnergies
{
    Scalar edge = 0;             //!< sum_E |x_j - x_i|^2
    Scalar soft = 0;             //!< soft vertex constraints
    Scalar centroid = 0;         //!< soft face-centroid constraints
    Scalar normal = 0;           //!< face-normal constraints, each face-edge pair once
    Scalar normal_smoothing = 0; //!< joint mode: gamma sum_{E*} |u_f - u_g|^2
    Scalar normal_soft = 0;      //!< joint mode: soft normal constraints on u
    Scalar bending = 0;          //!< mu sum_k |u_k|^2, the squared umbrella operator
    Scalar total() const
    {
        return edge + soft + centroid + normal + normal_smoothing + normal_soft + bending;
    }
    TermEnergies& operator+=(const TermEnergies& o)
    {
        edge += o.edge;
        soft += o.soft;
        centroid += o.centroid;
        normal += o.normal;
        normal_smoothing += o.normal_smoothing;
        normal_soft += o.normal_soft;
        bending += o.bending;
        return *this;
    }
    //! The value of a position term (Total: nothing to store: \throw SolverError).
    Scalar& at(EnergyTerm term);
};

//! The terms of the energy over the positions (a heat map's choice), or all of them.
enum class EnergyTerm
{
    Total,
    Edge,
    Soft,
    Centroid,
    Normal,
    Bending
};

inline Scalar& TermEnergies::at(EnergyTerm term)
{
    switch (term)
    {
        case EnergyTerm::Edge:
            return edge;
        case EnergyTerm::Soft:
            return soft;
        case EnergyTerm::Centroid:
            return centroid;
        case EnergyTerm::Normal:
            return normal;
        case EnergyTerm::Bending:
            return bending;
        case EnergyTerm::Total:
            break;
    }
    throw SolverError("TermEnergies::at: the total is not a term");
}

//! \brief One term E_T(x) of the recipe's energy over the positions x (3 #V), as every
//! solver reads it \cite taubin_2012: its value, r = -1/2 dE_T/dx at the free vertices
//! (the generalized Jacobi right-hand side), its scalar part of the Jacobi diagonal, its
//! column of the half Hessian A_T (E_T(x + dx) = E_T(x) - 2 r^T dx + dx^T A_T dx; exact, the
//! terms here are quadratic in x for the normals they hold) and its share per vertex.
//!
//! A term with a 3x3 Jacobi block (the face-normal term) adds that block itself: the
//! Jacobi system asks it apart. Terms over the normals (normal smoothing, joint mode) and
//! the volume constraint are not position terms: they are applied between steps.
class PositionTerm
{
public:
    virtual ~PositionTerm() = default;
    //! Which term it is (its name: core/recipe/energy_terms.h).
    virtual EnergyTerm kind() const = 0;
    virtual Scalar energy(std::span<const Scalar> x) const = 0;
    //! Adds each vertex's share of energy(x) to per_vertex (#V); the shares sum to it.
    virtual void add_vertex_energy(std::span<const Scalar> x,
                                   std::span<Scalar> per_vertex) const = 0;
    //! \brief The part of energy(x) over the term's elements (edges, anchors, faces,
    //! umbrellas) none of whose vertices is free (is_free: #V flags): what no step can
    //! change while the other vertices stay, left out of the editor's plot of what moves.
    virtual Scalar held_energy(std::span<const Scalar> x, std::span<const char> is_free) const = 0;
    //! dx^T A_T dx, the exact line search's curvature along dx.
    virtual Scalar quadratic(std::span<const Scalar> dx) const = 0;
    //! diagonal[i] += the scalar part of A_T's diagonal block at i, for every vertex.
    virtual void add_diagonal(std::span<Scalar> diagonal) const = 0;
    //! Column i of A_T (the direct method's matrix).
    virtual void add_hessian_column(Index i, HessianColumn& column) const = 0;
    //! rhs_i += r_i, r = -1/2 dE_T/dx, for each i in `vertices` (the free ones).
    virtual void add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                         std::span<Scalar> rhs) const = 0;

protected:
    PositionTerm() = default;
    PositionTerm(const PositionTerm&) = default;
    PositionTerm& operator=(const PositionTerm&) = default;
};

} // namespace meshfair
