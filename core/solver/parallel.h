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

//! \brief f(k) for every k in [0, n), split into contiguous static chunks over the
//! threads. Each call must write only what belongs to its k (a vertex gathers its own
//! sums; nothing scatters), which makes the results independent of the thread count.
template <class F>
void parallel_for(Index n, F&& f)
{
    const int threads = n >= kParallelThreshold ? thread_count() : 1;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (Index k = 0; k < n; ++k)
        f(k);
}

//! \brief The sum of f(k) over [0, n), bit for bit the same for any thread count: the
//! range is cut into blocks whose size depends on n only, each block is summed in order,
//! then the block sums are added in order. Allocates nothing (at most 1024 blocks).
template <class F>
Scalar deterministic_sum(Index n, F&& f)
{
    constexpr std::int64_t kMaxBlocks = 1024;
    const std::int64_t size = n;
    const std::int64_t block = std::max<std::int64_t>(4096, (size + kMaxBlocks - 1) / kMaxBlocks);
    const std::int64_t blocks = (size + block - 1) / block;
    std::array<Scalar, kMaxBlocks> partial;
    const int threads = blocks > 1 ? thread_count() : 1;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::int64_t b = 0; b < blocks; ++b)
    {
        Scalar s = 0;
        const std::int64_t end = std::min(size, (b + 1) * block);
        for (std::int64_t k = b * block; k < end; ++k)
            s += f(static_cast<Index>(k));
        partial[static_cast<size_t>(b)] = s;
    }
    Scalar sum = 0;
    for (std::int64_t b = 0; b < blocks; ++b)
        sum += partial[static_cast<size_t>(b)];
    return sum;
}

} // namespace meshfair
