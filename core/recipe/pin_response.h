// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/solver/free_system.h"
#include "core/types.h"

namespace meshfair {

//! \brief The minimizer's response to moving pins, for a pin drag (libigl's
//! min_quad_with_fixed: the solution is affine in the fixed values). For a quadratic energy
//! the same for x, y and z (no normal term), the minimizer over the free vertices is
//! x_f = A_ff^-1 r_f(pins), r affine in the pins' targets (through the edges to them and the
//! falloff's anchors that follow them). When a group of pins moves by one vector d, the
//! minimizer moves by w_g d, w_g = A_ff^-1 (the change of r_f when the group moves by 1 along
//! x) — one solve of one right-hand side per group, kept; every further move of the group is
//! then a pass over the free vertices, not a back-substitution (at a million vertices, a few
//! milliseconds instead of half a second).
class PinResponses
{
public:
    //! r_f (its x coordinates, #free) at positions x (3 #V) with the pins placed at `targets`
    //! (3 per pin) and the anchors that follow them moved with them.
    using RightHandSide = std::function<void(
        std::span<const Scalar> x, std::span<const Scalar> targets, std::span<Scalar> r_x)>;

    //! Forgets every response (another matrix, other pins).
    void clear() { responses_.clear(); }
    //! \brief x_f += sum_g w_g (to_g - from_g) over the groups of pins that moved by one
    //! vector from `from` to `to` (3 per pin), x being the minimizer for `from`: x becomes
    //! the minimizer for `to` (to rounding). Responses of new groups are solved with `solver`
    //! and kept (the last 8). Only the free vertices of x (3 #V) are written.
    void follow(std::span<const Scalar> from, std::span<const Scalar> to,
                std::span<const Index> free, const RightHandSide& rhs, FreeSystemSolver& solver,
                std::span<Scalar> x);

private:
    struct Response
    {
        std::vector<Index> pins; //!< the group, ascending indices into the pin list
        std::vector<Scalar> w;   //!< #free
    };
    const Response& response(const std::vector<Index>& pins, std::span<const Scalar> from,
                             std::span<const Scalar> x, size_t free_count, const RightHandSide& rhs,
                             FreeSystemSolver& solver);

    std::vector<Response> responses_;
};

} // namespace meshfair
