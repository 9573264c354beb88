// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stdexcept>

namespace meshfair {

//! A preparation stopped by PreparationProgress::cancel(): the caller asked, the input is
//! not at fault (not a SolverError: no conjugate gradients are tried in its place).
class PreparationCancelled : public std::runtime_error
{
public:
    PreparationCancelled() : std::runtime_error("the preparation was cancelled") {}
};

//! \brief Where the direct method's preparation is (building the terms, the fill-reducing
//! ordering, the numeric factorization), for a progress bar on another thread, and a
//! request to stop it.
//!
//! The preparing thread calls enter() as each phase begins; SparseCholesky does for the
//! ordering and the factorization. A cancel() takes effect at the next enter(), which
//! throws PreparationCancelled: CHOLMOD offers no way to stop its ordering or its
//! factorization in the middle, so the phase under way runs to its end first.
//! Thread-safe: one thread prepares, any other reads and cancels.
class PreparationProgress
{
public:
    enum class Phase
    {
        Assembling, //!< the terms and the free vertices' matrix
        Ordering,   //!< the fill-reducing ordering and the factor's structure
        Factoring,  //!< the numeric factorization
        Done,
    };
    struct Snapshot
    {
        Phase phase = Phase::Assembling;
        double seconds = 0;          //!< since the phase began
        double expected_seconds = 0; //!< its expected length; 0 when unknown
        std::int64_t unknowns = 0;   //!< the system's size (Ordering, Factoring)
        double flops = 0;            //!< the factorization's operations (Factoring)
        bool cancelled = false;      //!< cancel() was called
        //! The phase's part done by the clock: seconds / expected_seconds, below 1 (a
        //! phase past its estimate is not over); -1 when the length is not known.
        double fraction() const;
    };

    //! \brief A phase begins (the preparing thread). `expected_seconds`: its estimated
    //! length, 0 if unknown. Tells the listener, if any, after the snapshot is updated.
    //! \throw PreparationCancelled after cancel().
    void enter(Phase phase, std::int64_t unknowns = 0, double flops = 0,
               double expected_seconds = 0);
    //! Stops the preparation at its next phase (any thread).
    void cancel() { cancelled_ = true; }
    bool cancelled() const { return cancelled_; }
    Snapshot snapshot() const;
    //! \brief Called on the preparing thread at each enter(), with the phase's snapshot
    //! (a trace, a test that holds a phase). Set before the preparation starts.
    void set_listener(std::function<void(const Snapshot&)> listener)
    {
        listener_ = std::move(listener);
    }

private:
    using Clock = std::chrono::steady_clock;
    mutable std::mutex mutex_;
    Snapshot current_;
    Clock::time_point since_ = Clock::now();
    std::atomic<bool> cancelled_{false};
    std::function<void(const Snapshot&)> listener_;
};

//! "assembling", "ordering", "factoring", "done": for the editor and its trace.
const char* phase_name(PreparationProgress::Phase phase);

} // namespace meshfair
