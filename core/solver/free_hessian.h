// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <functional>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/solver/sparse_cholesky.h"
#include "core/types.h"

namespace meshfair {

//! \brief One vertex's column of the half Hessian A of a quadratic energy,
//! E(x + d) = E(x) - 2 r^T d + d^T A d (the Jacobi system's A_i are its diagonal blocks,
//! jacobi_system.h): for each vertex j it couples to, the 3x3 block A_ji = a I + B with B
//! symmetric (xx xy xz yy yz zz). Every term of the paper gives blocks of that form: the
//! isotropic terms (edges, anchors, centroids) a scalar a, the face-normal term
//! mu_f u_f u_f^T. A term adds its part of column i with add() and add_block().
class HessianColumn
{
public:
    struct Entry
    {
        Index vertex;
        Scalar scalar;
        std::array<Scalar, 6> block;
    };
    //! Starts column i (vertex i) empty.
    void reset(Index i)
    {
        column_ = i;
        entries_.clear();
        index_.clear();
    }
    Index column() const { return column_; }
    //! A_ji += a I.
    void add(Index j, Scalar a) { entry(j).scalar += a; }
    //! A_ji += B, B symmetric given as xx xy xz yy yz zz (times `scale`).
    void add_block(Index j, const Scalar* b, Scalar scale = 1)
    {
        Entry& e = entry(j);
        for (int k = 0; k < 6; ++k)
            e.block[static_cast<size_t>(k)] += scale * b[k];
    }
    std::span<const Entry> entries() const { return entries_; }

private:
    Entry& entry(Index j)
    {
        // A column holds a vertex's neighbours (about 7, a 2-ring's 19 with the thin plate):
        // a search beats a map. A constrained face of thousands of corners couples them all
        // (the centroid term's n_f x n_f block): past kSearched entries a map finds them, or
        // such a column would take n_f^2 steps, and the face n_f^3.
        if (entries_.size() <= kSearched)
        {
            for (Entry& e : entries_)
                if (e.vertex == j)
                    return e;
            if (entries_.size() < kSearched)
                return entries_.emplace_back(Entry{j, 0, {}});
            for (size_t k = 0; k < entries_.size(); ++k)
                index_.emplace(entries_[k].vertex, k);
        }
        const auto [at, added] = index_.emplace(j, entries_.size());
        if (added)
            entries_.push_back(Entry{j, 0, {}});
        return entries_[at->second];
    }
    static constexpr size_t kSearched = 32;
    Index column_ = kInvalidIndex;
    std::vector<Entry> entries_;
    std::unordered_map<Index, size_t> index_; //!< vertex -> entry, past kSearched entries
};

//! \brief The half Hessian restricted to the free vertices, A_ff, as CHOLMOD reads it (the
//! upper triangle by columns), with `free[k]` the k-th unknown:
//! - scalar (no term adds a block): #free x #free, the same matrix for x, y and z, solved
//!   for three right-hand sides at once;
//! - blocks: 3 #free x 3 #free, unknown 3 k + a being coordinate a of free[k].
//! column(i, col) fills vertex i's column (col is reset to i first); entries at vertices
//! that are not free are dropped: their values are known, and their part is already in
//! the right-hand side r(x) = -1/2 dE/dx that the direct step solves for.
//! Columns are assembled in parallel (column must be safe to call concurrently) and the
//! result is the same for any thread count.
SymmetricMatrix assemble_free_hessian(Index vertex_count, std::span<const Index> free, bool blocks,
                                      const std::function<void(Index, HessianColumn&)>& column);

} // namespace meshfair
