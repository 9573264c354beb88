// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <condition_variable>
#include <mutex>
#include <optional>

#include "core/solver/preparation_progress.h"

namespace meshfair::test {

// Holds the solver's thread where a phase of its preparation begins, until released.
class PhaseGate
{
public:
    //! The next preparation stops at `phase` (on the solver's thread).
    void hold(meshfair::PreparationProgress::Phase phase)
    {
        std::lock_guard lock(mutex_);
        hold_ = phase;
        held_ = false;
    }
    void wait_held()
    {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return held_; });
    }
    void release()
    {
        {
            std::lock_guard lock(mutex_);
            hold_.reset();
        }
        changed_.notify_all();
    }
    //! The solver's listener.
    void arrive(const meshfair::PreparationProgress::Snapshot& p)
    {
        std::unique_lock lock(mutex_);
        ++seen_;
        if (hold_ != p.phase)
            return;
        held_ = true;
        changed_.notify_all();
        changed_.wait(lock, [&] { return !hold_; });
    }
    int phases_seen() const
    {
        std::lock_guard lock(mutex_);
        return seen_;
    }

private:
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<meshfair::PreparationProgress::Phase> hold_;
    bool held_ = false;
    int seen_ = 0;
};

} // namespace meshfair::test
