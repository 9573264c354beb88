// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// The Session's steps that solve A_ff d = r_f (the direct, CG and implicit methods) and
// the gradient that judges them; the rest of the Session is session.cpp.
#include <algorithm>
#include <string>
#include <utility>

#include "core/parallel/parallel.h"
#include "core/recipe/session.h"
#include "core/solver/solver.h"

namespace meshfair {

StepInfo Session::direct_step(std::span<Scalar> x)
{
    if (!linear_)
        throw SolverError(
            "Session::step: the recipe's system was not factored (its "
            "precomputation failed, or its factorization was handed over)");
    assemble_rhs(x);
    StepInfo info{1};
    VolumeConstraint* volume = terms_->volume();
    // The direct method minimizes under the volume; an implicit step projects onto it.
    const bool constrained = minimizes_under_volume();
    if (constrained)
        volume_at_.assign(x.begin(), x.end()); // where r was assembled
    info.inner_iterations = linear_->add_solution(free_, system_.rhs, x);
    if (constrained)
    {
        // The gradient where the step started, less its part along the constraint's: 0 at
        // the constrained minimizer (system_.rhs is r there; the solve has read it).
        volume->remove_normal_part(volume_at_, system_.rhs);
        // From x*, the unconstrained minimizer, to the one under the volume.
        info.inner_iterations +=
            volume_minimizer_.minimize(*volume, *linear_, free_, volume_at_, x);
    }
    info.gradient = rhs_norm(system_, free_);
    if (guard_)
        info.shortened = guard_jump(*guard_, free_, guard_start_, x);
    if (!constrained)
        note_minimizer(x, info.shortened); // (pins are followed only where x is affine in them)
    if (volume != nullptr && (!constrained || info.shortened > 0))
        volume->project(x); // an implicit step's, or after the guard shortened steps
    return info;
}

void Session::begin_progressive_solve()
{
    if (!has_positions_ || !can_solve_progressively())
        throw SolverError(
            "Session::begin_progressive_solve: no positions, or the step is not "
            "solved by conjugate gradients");
    can_revert_ = false;
    minimizer_pins_.clear();
    assemble_rhs(x_);
    progressive_gradient_ = rhs_norm(system_, free_);
    progressive_start_.assign(x_.begin(), x_.end());
    linear_->begin_progressive(free_, system_.rhs);
}

StepInfo Session::advance_progressive_solve(int limit, bool& finished)
{
    if (progressive_start_.size() != x_.size())
        throw SolverError("Session::advance_progressive_solve: no progressive solve begun");
    const int before = linear_->progressive_iterations();
    finished = linear_->advance_progressive(limit, free_, progressive_start_, x_);
    StepInfo info{1};
    info.gradient = progressive_gradient_;
    info.inner_iterations = linear_->progressive_iterations() - before;
    if (guard_)
        info.shortened = guard_jump(*guard_, free_, progressive_start_, x_);
    forget_fixed_energy();
    if (finished)
        progressive_start_ = {};
    return info;
}

void Session::assemble_rhs(std::span<const Scalar> x)
{
    if (system_.rhs.size() != 3 * static_cast<size_t>(vertex_count_))
        system_.rhs.assign(3 * static_cast<size_t>(vertex_count_), 0); // a fused session
    parallel_for(static_cast<Index>(free_.size()),
                 [&](Index k) { std::fill_n(&system_.rhs[3 * free_[k]], 3, Scalar(0)); });
    terms_->add_rhs(x, free_, system_.rhs);
}

Scalar Session::gradient(std::span<const Scalar> x)
{
    check_size(x, "gradient");
    assemble_rhs(x);
    if (minimizes_under_volume())
        terms_->volume()->remove_normal_part(x, system_.rhs);
    return rhs_norm(system_, free_);
}

Session::Residual Session::residual(std::span<const Scalar> x)
{
    check_size(x, "residual");
    Residual out;
    assemble_rhs(x);
    if (minimizes_under_volume())
        terms_->volume()->remove_normal_part(x, system_.rhs);
    out.gradient = rhs_norm(system_, free_);
    if (free_.empty())
        return out;
    if (dx_.size() != 3 * static_cast<size_t>(vertex_count_))
        dx_.assign(3 * static_cast<size_t>(vertex_count_), 0);
    jacobi_displacements(system_, free_, !system_.inverse.empty(), dx_);
    out.jacobi_displacement = largest_displacement(free_, dx_);
    return out;
}

} // namespace meshfair
