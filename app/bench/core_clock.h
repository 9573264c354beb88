// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

namespace meshfair::bench {

//! \brief The clock of a busy core, in cycles per second, timed on a chain of dependent
//! integer additions (one cycle each on every x86-64 and AArch64 core of the last decade).
//! Virtual machines often give perf no cycle counter; with this clock a step time becomes
//! cycles per vertex. The best of `trials` (a shared machine only ever slows it down).
double core_clock_hz(int trials = 5);

} // namespace meshfair::bench
