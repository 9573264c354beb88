// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/energies/volume_constraint.h"
#include "core/solver/free_system.h"
#include "core/types.h"

namespace meshfair {

//! \brief The minimizer of a quadratic energy over the free vertices with each kept
//! component's volume held (the direct and CG methods with "volume"), from its
//! unconstrained minimizer x* = A_ff^-1 b.
//!
//! At the constrained minimizer r(x) = b - A x lies along the volume's gradient g(x) (a
//! Lagrange multiplier per component), so x = x* + t A_ff^-1 g(x) with t such that V(x) =
//! V_0: a fixed point of G(y) = x* + t(y) A_ff^-1 g(y), where each G(y) is one solve with
//! the factor kept and an exact line search along its direction (VolumeConstraint::
//! project_along; the components do not mix, A_ff couples no two of them). Its plain
//! iteration converges linearly, slowly where the volume's curvature times the multiplier
//! rivals A_ff (weak anchors around a shape the energy would collapse); Anderson's
//! acceleration (depth 5, a least-squares mixing of the last steps; Walker and Ni 2011)
//! takes it to the fixed point where the plain iteration had not in 100 solves (the tests'
//! small meshes under weak anchors); 11 solves on the 35k bunny with anchors of mu 1. The
//! last G(y), on the constraint to rounding, is the result.
class VolumeMinimizer
{
public:
    //! \brief x: x* on entry, the minimizer under the volume on return; start: a shape on
    //! the constraint (where the step began) whose gradient G starts from. Returns the
    //! conjugate gradients' iterations of its solves (0 with a factor).
    //! Allocates on its first call only (17 arrays of x's size: 7, and 2 x kDepth columns).
    int minimize(VolumeConstraint& volume, FreeSystemSolver& solver, std::span<const Index> free,
                 std::span<const Scalar> start, std::span<Scalar> x);

private:
    static constexpr int kDepth = 5;
    static constexpr int kMostEvaluations = 200;
    std::vector<Scalar> base_, at_, image_, residual_, scratch_;
    // The last kDepth differences of residuals and of images, as columns (ring buffers).
    std::vector<std::vector<Scalar>> residual_steps_, image_steps_;
    std::vector<Scalar> previous_residual_, previous_image_;
};

} // namespace meshfair
