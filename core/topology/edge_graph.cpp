// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/topology/edge_graph.h"

#include <algorithm>
#include <bit>
#include <utility>

namespace meshfair {

namespace {

constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

// splitmix64's finalizer: consecutive vertex indices land in unrelated slots.
std::uint64_t mix(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

} // namespace

EdgeGraph::EdgeGraph(std::size_t expected_pairs)
{
    // Load factor <= 1/2 keeps linear probing short.
    const std::size_t capacity = std::bit_ceil(std::max<std::size_t>(16, 2 * expected_pairs));
    keys_.assign(capacity, kEmpty);
    values_.assign(capacity, kInvalidIndex);
    mask_ = capacity - 1;
    pairs_.reserve(2 * expected_pairs);
}

std::uint64_t EdgeGraph::key(Index i, Index j)
{
    if (i > j)
        std::swap(i, j);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) |
           static_cast<std::uint32_t>(j);
}

std::size_t EdgeGraph::slot_of(std::uint64_t k) const
{
    std::size_t s = mix(k) & mask_;
    while (keys_[s] != kEmpty && keys_[s] != k)
        s = (s + 1) & mask_;
    return s;
}

Index EdgeGraph::get(Index i, Index j) const
{
    return values_[slot_of(key(i, j))];
}

Index EdgeGraph::insert(Index i, Index j)
{
    const std::uint64_t k = key(i, j);
    std::size_t s = slot_of(k);
    if (keys_[s] == k)
        return values_[s];
    if (2 * (pairs_.size() / 2 + 1) > keys_.size())
    {
        grow();
        s = slot_of(k);
    }
    const Index e = size();
    keys_[s] = k;
    values_[s] = e;
    pairs_.push_back(std::min(i, j));
    pairs_.push_back(std::max(i, j));
    return e;
}

void EdgeGraph::grow()
{
    std::vector<std::uint64_t> old_keys = std::move(keys_);
    std::vector<Index> old_values = std::move(values_);
    keys_.assign(2 * old_keys.size(), kEmpty);
    values_.assign(2 * old_keys.size(), kInvalidIndex);
    mask_ = keys_.size() - 1;
    for (std::size_t s = 0; s < old_keys.size(); ++s)
        if (old_keys[s] != kEmpty)
        {
            const std::size_t t = slot_of(old_keys[s]);
            keys_[t] = old_keys[s];
            values_[t] = old_values[s];
        }
}

} // namespace meshfair
