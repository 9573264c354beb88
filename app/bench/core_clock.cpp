// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/core_clock.h"

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace meshfair::bench {

namespace {

//! Four dependent additions per iteration: the empty asm makes the compiler keep each one
//! (it cannot see through it to fold them), so an iteration takes 4 cycles.
[[gnu::noinline]] std::uint64_t addition_chain(std::uint64_t iterations)
{
    std::uint64_t x = 0;
    for (std::uint64_t i = 0; i < iterations; ++i)
    {
        x += i;
        __asm__ volatile("" : "+r"(x));
        x += i;
        __asm__ volatile("" : "+r"(x));
        x += i;
        __asm__ volatile("" : "+r"(x));
        x += i;
        __asm__ volatile("" : "+r"(x));
    }
    return x;
}

} // namespace

double core_clock_hz(int trials)
{
    constexpr std::uint64_t kIterations = 25'000'000; // 100 M cycles: tens of milliseconds
    double best = 0;
    for (int t = 0; t < trials; ++t)
    {
        const auto start = std::chrono::steady_clock::now();
        volatile std::uint64_t sink = addition_chain(kIterations);
        static_cast<void>(sink);
        const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
        best = std::max(best, 4.0 * static_cast<double>(kIterations) / seconds.count());
    }
    return best;
}

} // namespace meshfair::bench
