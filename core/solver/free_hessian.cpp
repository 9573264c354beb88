// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/free_hessian.h"

#include <algorithm>

#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

// The entries of column i of A_ff: the free ones with a row <= i's (the upper triangle),
// sorted by row. Each holds its free index in `vertex`.
void free_entries(Index i, Index k, std::span<const Index> free_index, HessianColumn& col,
                  const std::function<void(Index, HessianColumn&)>& column,
                  std::vector<HessianColumn::Entry>& out)
{
    col.reset(i);
    column(i, col);
    out.clear();
    for (HessianColumn::Entry e : col.entries())
    {
        const Index r = free_index[e.vertex];
        if (r == kInvalidIndex || r > k)
            continue;
        e.vertex = r;
        out.push_back(e);
    }
    std::ranges::sort(out, {}, &HessianColumn::Entry::vertex);
}

// The matrix entries of block column a (0..2) of a free vertex with free index k: rows
// 3 r + b, b <= a on the diagonal block. Calls put(row, value) in ascending rows.
template <class Put>
void block_column(Index k, int a, const std::vector<HessianColumn::Entry>& entries, Put&& put)
{
    // Index of (b, a) in xx xy xz yy yz zz.
    constexpr int at[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for (const HessianColumn::Entry& e : entries)
        for (int b = 0; b < 3; ++b)
        {
            if (e.vertex == k && b > a)
                break;
            const Scalar v = e.block[static_cast<size_t>(at[b][a])] + (a == b ? e.scalar : 0);
            put(3 * std::int64_t{e.vertex} + b, v);
        }
}

} // namespace

SymmetricMatrix assemble_free_hessian(Index vertex_count, std::span<const Index> free, bool blocks,
                                      const std::function<void(Index, HessianColumn&)>& column)
{
    std::vector<Index> free_index(static_cast<size_t>(vertex_count), kInvalidIndex);
    const Index n = static_cast<Index>(free.size());
    for (Index k = 0; k < n; ++k)
        free_index[free[k]] = k;
    const int per = blocks ? 3 : 1; // matrix columns per free vertex
    SymmetricMatrix a;
    a.size = std::int64_t{n} * per;
    a.column_start.assign(static_cast<size_t>(a.size) + 1, 0);
    // Two passes over the columns, each on contiguous ranges of free vertices: the counts,
    // then the entries at their places. Every column is written by one range alone.
    // each_column(emit) calls emit(at, c, k, entries) for matrix column `at`, the c-th of
    // the k-th free vertex, with that vertex's entries sorted.
    const auto each_column = [&](auto&& emit) {
        parallel_ranges(n, [&](Index begin, Index end) {
            HessianColumn col;
            std::vector<HessianColumn::Entry> entries;
            for (Index k = begin; k < end; ++k)
            {
                free_entries(free[k], k, free_index, col, column, entries);
                for (int c = 0; c < per; ++c)
                    emit(static_cast<size_t>(std::int64_t{k} * per + c), c, k, entries);
            }
        });
    };
    // The entries of matrix column c of free vertex k: put(row, value) in ascending rows.
    const auto column_entries = [&](int c, Index k, const auto& entries, auto&& put) {
        if (blocks)
            block_column(k, c, entries, put);
        else
            for (const HessianColumn::Entry& e : entries)
                put(e.vertex, e.scalar);
    };
    each_column([&](size_t at, int c, Index k, const auto& entries) {
        std::int64_t count = 0;
        column_entries(c, k, entries, [&](std::int64_t, Scalar) { ++count; });
        a.column_start[at + 1] = count;
    });
    for (size_t c = 1; c < a.column_start.size(); ++c)
        a.column_start[c] += a.column_start[c - 1];
    a.row.resize(static_cast<size_t>(a.column_start.back()));
    a.value.resize(a.row.size());
    each_column([&](size_t at, int c, Index k, const auto& entries) {
        auto next = static_cast<size_t>(a.column_start[at]);
        column_entries(c, k, entries, [&](std::int64_t row, Scalar v) {
            a.row[next] = row;
            a.value[next] = v;
            ++next;
        });
    });
    return a;
}

} // namespace meshfair
