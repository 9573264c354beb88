// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/parallel/parallel.h"

#include <omp.h>

#include <atomic>

namespace meshfair {

namespace {

// A process-wide setting rather than omp_set_num_threads, whose value belongs to the
// calling thread only: the editor runs the solver on a worker thread.
std::atomic<int> g_thread_count{0};

} // namespace

void set_thread_count(int n)
{
    g_thread_count.store(std::max(n, 0), std::memory_order_relaxed);
}

int thread_count()
{
    const int n = g_thread_count.load(std::memory_order_relaxed);
    return n > 0 ? n : std::max(omp_get_max_threads(), 1);
}

} // namespace meshfair
