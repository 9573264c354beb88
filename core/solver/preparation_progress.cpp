// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/preparation_progress.h"

#include <algorithm>

namespace meshfair {

double PreparationProgress::Snapshot::fraction() const
{
    if (expected_seconds <= 0)
        return -1;
    // An estimate: never "done" before the phase is.
    return std::min(seconds / expected_seconds, 0.99);
}

void PreparationProgress::enter(Phase phase, std::int64_t unknowns, double flops,
                                double expected_seconds)
{
    if (cancelled_)
        throw PreparationCancelled();
    Snapshot now;
    {
        std::lock_guard lock(mutex_);
        current_.phase = phase;
        current_.unknowns = unknowns;
        current_.flops = flops;
        current_.expected_seconds = expected_seconds;
        since_ = Clock::now();
        now = current_;
    }
    if (listener_)
        listener_(now);
    if (cancelled_) // (the listener may have waited for one)
        throw PreparationCancelled();
}

PreparationProgress::Snapshot PreparationProgress::snapshot() const
{
    std::lock_guard lock(mutex_);
    Snapshot s = current_;
    s.seconds = std::chrono::duration<double>(Clock::now() - since_).count();
    s.cancelled = cancelled_;
    return s;
}

const char* phase_name(PreparationProgress::Phase phase)
{
    switch (phase)
    {
        case PreparationProgress::Phase::Assembling:
            return "assembling";
        case PreparationProgress::Phase::Ordering:
            return "ordering";
        case PreparationProgress::Phase::Factoring:
            return "factoring";
        case PreparationProgress::Phase::Done:
            break;
    }
    return "done";
}

} // namespace meshfair
