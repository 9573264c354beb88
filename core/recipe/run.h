// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/energies/position_term.h"
#include "core/mesh/mesh.h"
#include "core/recipe/recipe.h"
#include "core/topology/topology.h"

namespace meshfair {

class Session;

//! \brief The direct method's stopping rule, for run() and the editor's runs: after each
//! step, the gradient |r| at its result relative to the gradient where the first step
//! started (the input's) must be at most the tolerance (1e-12 when it is 0), or the step
//! stops when it no longer halves the gradient (rounding: the minimizer is reached).
class DirectConvergence
{
public:
    explicit DirectConvergence(Scalar tolerance)
        : tolerance_(tolerance > 0 ? tolerance : Scalar(1e-12))
    {
    }
    //! A step that started at gradient `started` (StepInfo::gradient) and ended at `now`;
    //! true when the run stops here.
    bool stop_after(Scalar started, Scalar now)
    {
        if (steps_++ == 0)
            first_ = started;
        relative_ = first_ > 0 ? now / first_ : 0;
        const bool stalled = steps_ > 1 && now >= Scalar(0.5) * last_;
        last_ = now;
        return relative_ <= tolerance_ || stalled;
    }
    //! The last step's gradient relative to the first's start.
    Scalar relative() const { return relative_; }

private:
    Scalar tolerance_;
    Scalar first_ = 0, last_ = 0, relative_ = 0;
    int steps_ = 0;
};

//! \brief The stopping rule of the step methods (Jacobi, Taubin's, gradient descent), for
//! run() and the editor's runs: the gradient |r(x_k)| where step k starts, relative to the
//! first step's (the input's), at most the tolerance: x_k is then the run's result (the
//! caller undoes step k, Session::revert_step). A tolerance of 0 never stops.
class StepConvergence
{
public:
    explicit StepConvergence(Scalar tolerance) : tolerance_(tolerance) {}
    //! Step k starts at `gradient` (StepInfo::gradient of step(before, true)); true when
    //! the positions it starts from are the run's result.
    bool converged_at(Scalar gradient)
    {
        if (steps_++ == 0)
            first_ = gradient;
        relative_ = first_ > 0 ? gradient / first_ : 0; // 0: the input is a minimizer
        return tolerance_ > 0 && relative_ <= tolerance_;
    }
    //! The last gradient relative to the first.
    Scalar relative() const { return relative_; }

private:
    Scalar tolerance_;
    Scalar first_ = 0, relative_ = 1;
    int steps_ = 0;
};

//! The outcome of a whole run.
struct SmoothResult
{
    std::vector<TermEnergies> energies; //!< before the first step, then after each one
    std::vector<Scalar> lambdas;        //!< per step
    std::vector<Index> shortened;       //!< per step: StepInfo::shortened
    //! |r(x)| / |r(x_0)| after each step (x_0 the input, r = -1/2 dE/dx over the free
    //! vertices): the direct method's and CG's always, the steps' (implicit ones too) with
    //! a tolerance; else empty.
    std::vector<Scalar> gradients;
    //! Conjugate gradients: each step's iterations (StepInfo::inner_iterations); else empty.
    std::vector<int> inner_iterations;
    //! The direct method: the largest free vertex's Jacobi displacement at the result
    //! (Session::Residual), how far one more Jacobi step would move it; -1
    //! for the other methods.
    Scalar jacobi_displacement = -1;
    int iterations = 0; //!< steps taken
    bool stopped_by_tolerance = false;
};

//! \brief Runs session.recipe().iterations steps on x (modified in place), stopping early
//! by the recipe's tolerance on the gradient relative to the input's; `on_step` (optional)
//! sees each step's energies. Steps stop at the first positions whose relative gradient is
//! at most the tolerance (StepConvergence; 0: every step). The direct method stops when it
//! falls to the tolerance (1e-12 when it is 0), or stops falling (rounding): a quadratic
//! recipe after one or two steps (DirectConvergence).
SmoothResult run(Session& session, std::span<Scalar> x,
                 const std::function<void(int, const TermEnergies&)>& on_step = {});
//! The same on the session's kept positions (set_positions or adopt_positions first).
//! After Session::move_pins its first step is the direct method's minimizer followed from
//! the pins before (follow_pins) when it can be, judged by the same rule.
//! \throw SolverError when the session keeps no positions.
SmoothResult run(Session& session,
                 const std::function<void(int, const TermEnergies&)>& on_step = {});

//! \brief One-liner: check the recipe, precompute, move hard vertices to their targets
//! and run. mesh.positions are modified in place.
//! \throw RecipeError when the recipe does not fit the mesh.
SmoothResult smooth(Mesh& mesh, const Topology& topology, const Recipe& recipe);

} // namespace meshfair
