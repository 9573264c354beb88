// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>

namespace meshfair::test {

//! \brief What the test program allocated while a scope was open: the number of
//! allocations, their total size and the largest single request. The test program's
//! global allocation functions count (tests/allocation_counter.cpp): C++'s operator new
//! always, and the C library's malloc family too outside the sanitizer builds (where the
//! sanitizer's runtime owns malloc). Work is counted, not timed: a reader that allocates
//! the gigabytes a hostile header promises shows it in `largest`, whatever the machine's
//! load. One scope at a time: opening one resets the largest request seen.
class AllocationScope
{
public:
    AllocationScope();
    long count() const;
    std::size_t bytes() const;
    std::size_t largest() const;
    //! True where the C library's malloc family is counted as well as operator new.
    static bool counts_malloc();

private:
    long count_;
    std::size_t bytes_;
};

} // namespace meshfair::test
