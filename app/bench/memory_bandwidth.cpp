// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/memory_bandwidth.h"

#include <algorithm>
#include <chrono>

namespace meshfair::bench {

TriadBandwidth::TriadBandwidth(std::size_t elements)
    : n_(elements), a_(new double[elements]), b_(new double[elements]), c_(new double[elements])
{
    // First touch in the same static partition as the triad, so on NUMA machines each
    // thread's part of the arrays is in its own node's memory.
    const auto n = static_cast<std::ptrdiff_t>(n_);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i)
    {
        a_[i] = 0;
        b_[i] = 1;
        c_[i] = 2;
    }
}

double TriadBandwidth::measure(int trials)
{
    double best = 0;
    for (int t = 0; t < trials; ++t)
        best = std::max(best, triad());
    return best;
}

double TriadBandwidth::triad()
{
    const auto n = static_cast<std::ptrdiff_t>(n_);
    double* a = a_.get();
    const double* b = b_.get();
    const double* c = c_.get();
    const double s = 3;
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i)
        a[i] = b[i] + s * c[i];
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    return 24.0 * static_cast<double>(n) / seconds.count();
}

} // namespace meshfair::bench
