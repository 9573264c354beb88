// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <algorithm>
#include <cmath>

#include "app/editor/command_executor.h"
#include "app/editor/weight_paint.h"

//! \file
//! \brief The Paint tool's commands: painting weight maps and the smoothing brush.

namespace meshfair::app {

bool CommandExecutor::operator()(const cmd::SetPaintSettings& c) const
{
    const PaintSettings& p = c.paint;
    if (!(p.strength >= 0 && p.strength <= 1))
        return fail("the paint strength must be in [0, 1]");
    if (p.steps < 1 || p.steps > 10000)
        return fail("the smoothing brush's steps must be in [1, 10000]");
    st.tools.paint = p;
    return true;
}

bool CommandExecutor::operator()(const cmd::PaintDab& c) const
{
    if (!(c.radius > 0) || !std::isfinite(c.radius))
        return fail("a dab's radius must be a number > 0");
    if (!(c.strength >= 0 && c.strength <= 1))
        return fail("a dab's strength must be in [0, 1]");
    if (c.steps < 1 || c.steps > 10000)
        return fail("a dab's steps must be in [1, 10000]");
    for (const Scalar x : c.center)
        if (!std::isfinite(x))
            return fail("a dab's centre must be a finite point");
    if (c.set.empty())
        return fail("a dab needs the set it paints");
    std::optional<size_t> k = s.set_named(c.set);
    if (!k)
    {
        if (c.mode == PaintMode::Subtract || c.mode == PaintMode::Smooth)
            return fail("no set named '" + c.set + "' to paint");
        // A new region: only what is painted moves.
        ConstraintSet set;
        set.name = c.set;
        set.kind = ConstraintKind::Region;
        set.color = default_color(ConstraintKind::Region);
        d.sets.push_back(std::move(set));
        k = d.sets.size() - 1;
        // Never made behind the artist's back: from now on only what is painted moves.
        say("the stroke made region '" + c.set +
            "': the smoothing brush paints its freedom, and runs move only what it frees "
            "(delete the set to smooth the whole mesh again)");
    }
    ConstraintSet& set = d.sets[*k];
    if (!takes_weight_map(set.kind) || !set.faces.empty())
        return fail("set '" + c.set +
                    "' has no weight map: paint a region of vertices or an anchor set");
    if (c.mode == PaintMode::Relax && set.kind != ConstraintKind::Region)
        return fail("the smoothing brush paints a region set, and '" + c.set + "' is not one");
    // A region out of the solve would leave the run without it: the whole mesh would move.
    if (c.mode == PaintMode::Relax && !set.enabled)
        return fail("set '" + c.set + "' is out of the solve: take it in to smooth with it");
    // The set as the stroke found it (the open step keeps the sets from before its first dab).
    static const ConstraintSet kNone; // a set the stroke made: no weight before it
    const ConstraintSet* start = &kNone;
    if (s.open_step_ && s.open_step_->before.sets)
        for (const ConstraintSet& was : *s.open_step_->before.sets)
            if (was.name == c.set)
                start = &was;
    // The reach is measured on the shape where the stroke began (the open step keeps it when
    // the stroke moves the shape): the runs of earlier dabs come in while the stroke goes on,
    // and a map that depended on which had come would not replay bit for bit.
    const std::vector<Scalar>& shape = s.open_step_ && s.open_step_->before.positions
                                           ? *s.open_step_->before.positions
                                           : d.mesh.positions;
    const DabReach reach = dab_reach(shape, c.center, c.radius, c.strength, c.curve);
    const size_t changed = paint_weights(set, start, d.topology, reach, c.mode);
    if (c.mode != PaintMode::Relax)
        return changed > 0;
    // Nothing freed yet (a dab off the surface's reach): no run, which would smooth the
    // whole mesh for want of a region.
    if (std::none_of(set.weights.begin(), set.weights.end(), [](Scalar w) { return w > 0; }))
        return false;

    // The smoothing brush: the stroke's shape is its recipe's run from where it began, with
    // the map as the newest dab left it. The run is the solver worker's (run_stroke returns
    // at once): the interface runs no step, a newer dab's run supersedes one not yet done,
    // and the view shows each run's positions as they come. The stroke's step is recorded
    // when its last run is done (EditorSession::close_step).
    if (s.solver_.stroke_running())
        s.update(); // a run done since the last frame is shown before this one supersedes it
    d.versions.bump(kSets | kSetMembers); // (what the solver's problems are judged on)
    std::string why;
    if (!s.solver_.run_stroke(s.open_step_->before, c.steps, why))
        return fail(why);
    return true;
}

} // namespace meshfair::app
