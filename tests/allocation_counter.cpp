// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Replaces the global allocation functions of the test program with counting ones
// (tests/allocation_counter.h): C++'s operator new and, outside the sanitizer builds
// (where the sanitizer's runtime owns malloc), the C library's malloc family too, which is
// what the OpenMP runtime and every other library call. Not in a unity translation unit:
// the compiler must not see the replacements beside other files' allocations.
#include "tests/allocation_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

#include "app/common/sanitizer_malloc.h"

namespace {

std::atomic<long> g_count{0};
std::atomic<std::size_t> g_bytes{0}, g_largest{0};

void counted(std::size_t size)
{
    g_count.fetch_add(1, std::memory_order_relaxed);
    g_bytes.fetch_add(size, std::memory_order_relaxed);
    std::size_t seen = g_largest.load(std::memory_order_relaxed);
    while (size > seen && !g_largest.compare_exchange_weak(seen, size, std::memory_order_relaxed))
    {
    }
}

} // namespace

#define MESHFAIR_COUNT_MALLOC (!MESHFAIR_SANITIZER_OWNS_MALLOC)

#if MESHFAIR_COUNT_MALLOC
// glibc's own entry points; defining malloc here interposes it for every shared library.
extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);

extern "C" void* malloc(std::size_t size)
{
    counted(size);
    return __libc_malloc(size);
}

extern "C" void* calloc(std::size_t count, std::size_t size)
{
    counted(count * size);
    return __libc_calloc(count, size);
}

extern "C" void* realloc(void* p, std::size_t size)
{
    counted(size);
    return __libc_realloc(p, size);
}
#endif

void* operator new(std::size_t size)
{
    if (!MESHFAIR_COUNT_MALLOC) // else malloc counts it
        counted(size);
    if (void* p = std::malloc(size == 0 ? 1 : size))
        return p;
    throw std::bad_alloc();
}

void* operator new[](std::size_t size)
{
    return operator new(size);
}

void operator delete(void* p) noexcept
{
    std::free(p);
}

void operator delete[](void* p) noexcept
{
    std::free(p);
}

void operator delete(void* p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete[](void* p, std::size_t) noexcept
{
    std::free(p);
}

namespace meshfair::test {

AllocationScope::AllocationScope() : count_(g_count.load()), bytes_(g_bytes.load())
{
    g_largest.store(0);
}

long AllocationScope::count() const
{
    return g_count.load() - count_;
}

std::size_t AllocationScope::bytes() const
{
    return g_bytes.load() - bytes_;
}

std::size_t AllocationScope::largest() const
{
    return g_largest.load();
}

bool AllocationScope::counts_malloc()
{
    return MESHFAIR_COUNT_MALLOC;
}

} // namespace meshfair::test
