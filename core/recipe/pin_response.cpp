// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/pin_response.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/parallel/parallel.h"
#include "core/recipe/session.h"

namespace meshfair {

const PinResponses::Response& PinResponses::response(const std::vector<Index>& pins,
                                                     std::span<const Scalar> from,
                                                     std::span<const Scalar> x, size_t free_count,
                                                     const RightHandSide& rhs,
                                                     FreeSystemSolver& solver)
{
    for (const Response& r : responses_)
        if (r.pins == pins)
            return r;
    // The change of r_f when the group moves by 1 along x: r is affine in the pins, so the
    // difference is exact to rounding, whatever x is.
    std::vector<Scalar> moved(from.begin(), from.end());
    std::vector<Scalar> r0(free_count), r1(free_count);
    rhs(x, from, r0);
    for (const Index k : pins)
        moved[3 * static_cast<size_t>(k)] += 1;
    rhs(x, moved, r1);
    Response r{pins, std::vector<Scalar>(free_count)};
    for (size_t k = 0; k < free_count; ++k)
        r.w[k] = r1[k] - r0[k];
    solver.solve(r.w);
    if (responses_.size() == 8)
        responses_.erase(responses_.begin());
    responses_.push_back(std::move(r));
    return responses_.back();
}

void PinResponses::follow(std::span<const Scalar> from, std::span<const Scalar> to,
                          std::span<const Index> free, const RightHandSide& rhs,
                          FreeSystemSolver& solver, std::span<Scalar> x)
{
    // The pins grouped by how far they moved (a drag moves a set by one vector): the same
    // vector to 1e-9 of its length, since a set's targets moved by one offset differ from
    // their old ones by it only to rounding.
    std::vector<std::pair<std::array<Scalar, 3>, std::vector<Index>>> groups;
    for (size_t k = 0; 3 * k < to.size(); ++k)
    {
        const std::array<Scalar, 3> d = {to[3 * k] - from[3 * k], to[3 * k + 1] - from[3 * k + 1],
                                         to[3 * k + 2] - from[3 * k + 2]};
        if (d == std::array<Scalar, 3>{0, 0, 0})
            continue;
        const auto same = [&](const auto& g) {
            const std::array<Scalar, 3>& e = g.first;
            const Scalar length = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
            return std::abs(d[0] - e[0]) + std::abs(d[1] - e[1]) + std::abs(d[2] - e[2]) <=
                   1e-9 * length;
        };
        const auto g = std::find_if(groups.begin(), groups.end(), same);
        if (g == groups.end())
            groups.push_back({d, {static_cast<Index>(k)}});
        else
            g->second.push_back(static_cast<Index>(k));
    }
    for (const auto& group : groups)
    {
        const std::array<Scalar, 3>& d = group.first; // (a lambda cannot take a binding)
        const Response& r = response(group.second, from, x, free.size(), rhs, solver);
        parallel_for(static_cast<Index>(free.size()), [&](Index k) {
            Scalar* xi = &x[3 * static_cast<size_t>(free[k])];
            for (int a = 0; a < 3; ++a)
                xi[a] += r.w[k] * d[a];
        });
    }
}

// A pin drag on a Session: its pins moved (move_pins), and the minimizer followed.

void Session::note_minimizer(std::span<const Scalar> x, Index shortened)
{
    // On the kept positions, the minimizer for these pins: a pin drag follows it
    // (follow_pins) while the recipe is quadratic and the same for x, y and z.
    if (x.data() == x_.data() && shortened == 0 && recipe_.method == Method::Direct &&
        linear_->factorization() != nullptr && terms_->normal() == nullptr)
    {
        minimizer_pins_.clear(); // the pins where they are (at their targets, if any)
        for (const Index v : hard_)
        {
            const Scalar* xv = x_.data() + 3 * static_cast<size_t>(v); // (v may be the last)
            minimizer_pins_.insert(minimizer_pins_.end(), xv, xv + 3);
        }
    }
}

void Session::move_pins(std::span<const Scalar> targets)
{
    std::vector<Scalar> minimizer_pins = std::move(minimizer_pins_);
    set_hard_targets(targets);
    if (has_positions_)
    {
        apply_hard_targets(x_);
        if (!next_.empty()) // the fused step's buffers agree at fixed vertices
            apply_hard_targets(next_);
        can_revert_ = false;
    }
    minimizer_pins_ = std::move(minimizer_pins);
}

bool Session::follow_pins()
{
    if (minimizer_pins_.empty() || !has_positions_ || hard_targets_.empty())
        return false;
    progressive_start_.clear(); // the kept positions move otherwise
    // r_f's x coordinates at x with the pins at `targets` (the falloff's anchors with them).
    const auto rhs = [&](std::span<const Scalar> x, std::span<const Scalar> targets,
                         std::span<Scalar> r_x) {
        std::vector<Scalar> y(x.begin(), x.end());
        for (size_t k = 0; k < hard_.size(); ++k)
            std::copy_n(&targets[3 * k], 3, &y[3 * hard_[k]]);
        terms_->move_pins(targets);
        assemble_rhs(y);
        for (size_t k = 0; k < free_.size(); ++k)
            r_x[k] = system_.rhs[3 * static_cast<size_t>(free_[k])];
    };
    std::vector<Scalar> start;
    if (guard_)
        start = x_;
    pin_responses_.follow(minimizer_pins_, hard_targets_, free_, rhs, *linear_, x_);
    terms_->move_pins(hard_targets_);
    if (guard_)
    {
        guard_->begin_jump(start);
        if (guard_->turned_after_jump(x_) != 0)
        {
            x_.swap(start); // a step solves, with the guard on the whole jump
            return false;
        }
    }
    minimizer_pins_ = hard_targets_;
    forget_fixed_energy();
    can_revert_ = false;
    return true;
}

} // namespace meshfair
