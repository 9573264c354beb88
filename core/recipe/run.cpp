// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/run.h"

#include <algorithm>

#include "core/errors.h"
#include "core/recipe/session.h"

namespace meshfair {

SmoothResult run(Session& session, std::span<Scalar> x,
                 const std::function<void(int, const TermEnergies&)>& on_step)
{
    session.set_positions(x);
    SmoothResult result = run(session, on_step);
    const std::span<const Scalar> kept = session.positions();
    std::copy(kept.begin(), kept.end(), x.begin());
    return result;
}

SmoothResult run(Session& session, const std::function<void(int, const TermEnergies&)>& on_step)
{
    if (!session.has_positions())
        throw SolverError("run: the session keeps no positions (call set_positions first)");
    SmoothResult result;
    const Recipe& recipe = session.recipe();
    const auto record = [&](const TermEnergies& e) {
        result.energies.push_back(e);
        if (on_step)
            on_step(static_cast<int>(result.energies.size()) - 1, e);
    };
    if (solves_for_minimizer(recipe.method))
    {
        // Each step solves for the minimizer from where it starts; the rule is the
        // gradient's, relative to the input's.
        DirectConvergence rule(recipe.tolerance);
        record(session.energy());
        // A step done (info), then the rule on the gradient at the new positions, taken
        // once: the stopping rule's and the report's Jacobi displacement. True: stop.
        const auto judge = [&](const StepInfo& info) {
            result.lambdas.push_back(info.lambda);
            result.shortened.push_back(info.shortened);
            result.inner_iterations.push_back(info.inner_iterations);
            ++result.iterations;
            record(session.energy());
            const Session::Residual residual = session.residual(session.positions());
            result.jacobi_displacement = residual.jacobi_displacement;
            result.stopped_by_tolerance = rule.stop_after(info.gradient, residual.gradient);
            result.gradients.push_back(rule.relative());
            return result.stopped_by_tolerance;
        };
        // After a pin drag's move (Session::move_pins) the first step follows the minimizer
        // without a solve where it can (follow_pins): a step of length 1 from the gradient
        // where the pins left the positions.
        if (recipe.iterations > 0 && session.can_follow_pins())
        {
            const Scalar started = session.gradient(session.positions());
            if (session.follow_pins() && judge(StepInfo{1, 0, started, 0}))
                return result;
        }
        for (bool stop = false; !stop && result.iterations < recipe.iterations;)
            stop = judge(session.step());
        return result;
    }
    // Steps (Jacobi, Taubin's, gradient descent): each step gives the energy and, with a
    // tolerance, the gradient of the positions it starts from (the fused sweep sums both):
    // the run learns one step late that x_k had converged, and undoes step k.
    StepConvergence rule(recipe.tolerance);
    const bool tracked = recipe.tolerance > 0;
    for (int k = 0; k < recipe.iterations; ++k)
    {
        TermEnergies before;
        const StepInfo info = session.step(before, tracked);
        record(before);
        if (tracked)
        {
            const bool stop = rule.converged_at(info.gradient);
            if (k > 0) // x_k's: after step k - 1
                result.gradients.push_back(rule.relative());
            if (stop)
            {
                session.revert_step();
                result.stopped_by_tolerance = true;
                return result;
            }
        }
        result.lambdas.push_back(info.lambda);
        result.shortened.push_back(info.shortened);
        ++result.iterations;
    }
    record(session.energy());
    if (tracked && result.iterations > 0)
    {
        result.stopped_by_tolerance = rule.converged_at(session.gradient(session.positions()));
        result.gradients.push_back(rule.relative());
    }
    return result;
}

SmoothResult smooth(Mesh& mesh, const Topology& topology, const Recipe& recipe)
{
    Session session(mesh, topology, recipe);
    session.apply_hard_targets(mesh.positions);
    return run(session, mesh.positions);
}

} // namespace meshfair
