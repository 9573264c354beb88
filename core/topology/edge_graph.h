// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"

namespace meshfair {

//! \brief The paper's graph data structure over vertex indices \cite taubin_2012 ("The
//! Primal Graph of a Polygon Mesh"): get(i, j) and insert(i, j) on unordered pairs in
//! expected constant time, backed by an open-addressing hash table.
//!
//! Each pair is stored once as (min, max); insert() appends it to the pair array and
//! gives it the next index, so indices follow the order of first insertion. The same
//! structure serves the dual graph (pairs of faces). build_topology gives the numbering
//! this construction gives without using it (its random accesses into the table were
//! slow on large meshes); the tests compare the two.
class EdgeGraph
{
public:
    //! \param expected_pairs an upper bound used to size the table once (it still grows).
    explicit EdgeGraph(std::size_t expected_pairs);

    //! The index of pair {i, j}, or kInvalidIndex if it was never inserted.
    Index get(Index i, Index j) const;
    //! The index of pair {i, j}, inserting it first if needed.
    Index insert(Index i, Index j);

    Index size() const { return static_cast<Index>(pairs_.size() / 2); }
    //! Flat array of 2 size() indices: pair e is (pairs[2e], pairs[2e+1]) with the first
    //! smaller than the second.
    const std::vector<Index>& pairs() const { return pairs_; }
    std::vector<Index> release_pairs() { return std::move(pairs_); }

private:
    static std::uint64_t key(Index i, Index j);
    std::size_t slot_of(std::uint64_t k) const;
    void grow();

    std::vector<std::uint64_t> keys_;
    std::vector<Index> values_;
    std::vector<Index> pairs_;
    std::size_t mask_ = 0;
};

} // namespace meshfair
