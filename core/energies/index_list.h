// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

#include "core/types.h"

namespace meshfair {

//! \brief The elements a constraint term lists: indices in the order given, or, when that
//! order is 0, 1, ..., n - 1 (a set that is every face of the mesh), the count alone. A
//! term of every face of a million-face mesh so keeps no 4 MB list; the k-th element is k.
class IndexList
{
public:
    IndexList() = default;
    //! Keeps `indices`, or only their count when they are 0, 1, ..., size - 1.
    explicit IndexList(std::vector<Index> indices)
        : indices_(std::move(indices)), size_(static_cast<Index>(indices_.size()))
    {
        bool in_order = true;
        for (Index k = 0; k < size_ && in_order; ++k)
            in_order = indices_[k] == k;
        if (in_order)
            std::vector<Index>().swap(indices_); // freed, not only emptied
    }

    std::size_t size() const { return static_cast<std::size_t>(size_); }
    bool empty() const { return size_ == 0; }
    //! True when the k-th element is k for every k (no list is stored).
    bool identity() const { return indices_.empty(); }
    Index operator[](std::size_t k) const
    {
        return identity() ? static_cast<Index>(k) : indices_[k];
    }
    //! The stored indices, or nullptr when identity() (the k-th element is k).
    const Index* data() const { return identity() ? nullptr : indices_.data(); }
    class Iterator
    {
    public:
        using iterator_category = std::input_iterator_tag;
        using value_type = Index;
        using difference_type = std::ptrdiff_t;
        using pointer = const Index*;
        using reference = Index;
        Iterator(const IndexList* list, Index k) : list_(list), k_(k) {}
        Index operator*() const { return (*list_)[k_]; }
        Iterator& operator++()
        {
            ++k_;
            return *this;
        }
        bool operator==(const Iterator& o) const { return k_ == o.k_; }
        bool operator!=(const Iterator& o) const { return k_ != o.k_; }

    private:
        const IndexList* list_;
        Index k_;
    };
    Iterator begin() const { return {this, 0}; }
    Iterator end() const { return {this, size_}; }

private:
    std::vector<Index> indices_; //!< empty exactly when the list is 0, 1, ..., size_ - 1
    Index size_ = 0;
};

} // namespace meshfair
