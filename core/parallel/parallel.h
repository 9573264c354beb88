// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "core/types.h"

namespace meshfair {

//! \brief How many threads MeshFair's loops use (OpenMP): n >= 1, or 0 for every core
//! (the default, or OMP_NUM_THREADS when set). Applies to the loops that start afterwards,
//! from any thread.
void set_thread_count(int n);
//! The thread count the next loop will use (>= 1).
int thread_count();

//! Loops shorter than this run on the calling thread: waking the others costs more.
inline constexpr Index kParallelThreshold = 8192;

namespace detail {

// The OpenMP regions live in functions of their own, called only with threads > 1:
// clang asks the OpenMP runtime for the thread number on entry to any function holding
// a region (taken or not), which starts the runtime, and LLVM's runtime aborts where
// /dev/shm is not writable (a chroot, another user). One thread never starts it.
template <class F>
[[gnu::noinline]] void parallel_for_threads(Index n, int threads, F& f)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (Index k = 0; k < n; ++k)
        f(k);
}

template <class F>
[[gnu::noinline]] void parallel_ranges_threads(Index n, int threads, F& f)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int t = 0; t < threads; ++t)
        f(static_cast<Index>(std::int64_t{n} * t / threads),
          static_cast<Index>(std::int64_t{n} * (t + 1) / threads));
}

template <class F>
[[gnu::noinline]] void parallel_blocks(std::int64_t blocks, int threads, F& sum_block)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t b = 0; b < blocks; ++b)
        sum_block(b);
}

} // namespace detail

//! \brief f(k) for every k in [0, n), split into contiguous static chunks over the
//! threads. Each call must write only what belongs to its k (a vertex gathers its own
//! sums; nothing scatters), which makes the results independent of the thread count.
template <class F>
void parallel_for(Index n, F&& f)
{
    const int threads = n >= kParallelThreshold ? thread_count() : 1;
    if (threads > 1)
        detail::parallel_for_threads(n, threads, f);
    else
        for (Index k = 0; k < n; ++k)
            f(k);
}

//! \brief f(begin, end) once per thread, on contiguous ranges that together cover [0, n):
//! parallel_for for loops whose body is one sweep, so that what does not change from one
//! element to the next is loaded once per range, not once per element. The same rule: each
//! element's results belong to it alone.
template <class F>
void parallel_ranges(Index n, F&& f)
{
    const int threads = n >= kParallelThreshold ? thread_count() : 1;
    if (threads > 1)
        detail::parallel_ranges_threads(n, threads, f);
    else
        f(Index{0}, n);
}

//! \brief The sum of f(begin, end) over blocks that cover [0, n), bit for bit the same for
//! any thread count: the blocks' sizes depend on n only (at least 4096 elements, at most
//! 1024 blocks), each block is one call, and the blocks' results are added in order
//! (Sums: a value with +=, zero when value-initialized). For sweeps that sum while they
//! work: each block runs as one range, so what a range loads once it still loads once.
//! Allocates nothing.
template <class Sums, class F>
Sums deterministic_block_sums(Index n, F&& f)
{
    constexpr std::int64_t kMaxBlocks = 1024;
    const std::int64_t size = n;
    const std::int64_t block = std::max<std::int64_t>(4096, (size + kMaxBlocks - 1) / kMaxBlocks);
    const std::int64_t blocks = (size + block - 1) / block;
    std::array<Sums, kMaxBlocks> partial;
    const auto sum_block = [&](std::int64_t b) {
        partial[static_cast<size_t>(b)] =
            f(static_cast<Index>(b * block), static_cast<Index>(std::min(size, (b + 1) * block)));
    };
    const int threads = blocks > 1 ? thread_count() : 1;
    if (threads > 1)
        detail::parallel_blocks(blocks, threads, sum_block);
    else
        for (std::int64_t b = 0; b < blocks; ++b)
            sum_block(b);
    Sums sum{};
    for (std::int64_t b = 0; b < blocks; ++b)
        sum += partial[static_cast<size_t>(b)];
    return sum;
}

//! \brief The sum of f(k) over [0, n), bit for bit the same for any thread count: each
//! block of deterministic_block_sums is summed in order, then the block sums in order.
//! \brief deterministic_block_sums<Sums>(n, f) when Sum; else parallel_ranges(n, f), one
//! range per thread, f's results dropped and Sums{} returned: a pass that sums only on
//! the steps that ask for its sums (the fused step's energy).
template <bool Sum, class Sums, class F>
Sums block_sums_if(Index n, F&& f)
{
    if constexpr (Sum)
        return deterministic_block_sums<Sums>(n, f);
    else
    {
        parallel_ranges(n, f);
        return Sums{};
    }
}

template <class F>
Scalar deterministic_sum(Index n, F&& f)
{
    return deterministic_block_sums<Scalar>(n, [&](Index begin, Index end) {
        Scalar s = 0;
        for (Index k = begin; k < end; ++k)
            s += f(k);
        return s;
    });
}

} // namespace meshfair
