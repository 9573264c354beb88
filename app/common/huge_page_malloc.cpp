// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Transparent huge pages for the large arrays of MeshFair's programs.
//
// A million-vertex mesh lives in arrays of tens of megabytes. With 4 KiB pages the kernel
// takes one page fault per 4 KiB the first time each array is written, and on virtual
// machines a fault is expensive: measured here, faults were a third of meshfair-cli's time
// on a 1.25M-vertex mesh. Where the system's transparent huge pages are in "madvise" mode
// (Debian's default), asking for them turns 512 faults into one. glibc can do this itself
// (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) but only when told before the program starts;
// these definitions interpose malloc, calloc and realloc in the executable, forward to
// glibc, and advise the 2 MiB-aligned interior of every block of 8 MiB or more.
// Measured with meshfair-cli on the 1.25M-vertex bunny: read 2.3 s -> 0.5-0.9 s, setup
// 9.9 s -> 1.5-2.9 s (docs/performance.md).
//
// Not built under AddressSanitizer, which owns malloc.
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>

#include "app/common/sanitizer_malloc.h"

#if !MESHFAIR_SANITIZER_OWNS_MALLOC

extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr std::size_t kAdviseFrom = std::size_t{8} << 20;

void* advise(void* block, std::size_t size)
{
    if (block != nullptr && size >= kAdviseFrom)
    {
        const auto begin = reinterpret_cast<std::uintptr_t>(block);
        const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
        const std::uintptr_t last = (begin + size) & ~(kHugePage - 1);
        if (last > first) // a failure only means small pages, as without the advice
            madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
    }
    return block;
}

} // namespace

extern "C" void* malloc(std::size_t size)
{
    return advise(__libc_malloc(size), size);
}

extern "C" void* calloc(std::size_t count, std::size_t size)
{
    void* block = __libc_calloc(count, size);
    return block != nullptr ? advise(block, count * size) : nullptr;
}

extern "C" void* realloc(void* block, std::size_t size)
{
    return advise(__libc_realloc(block, size), size);
}

#endif
