// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// MESHFAIR_SANITIZER_OWNS_MALLOC is 1 in builds with AddressSanitizer or ThreadSanitizer
// (GCC or clang), whose runtimes own malloc: code that interposes malloc must step aside
// there.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define MESHFAIR_SANITIZER_OWNS_MALLOC 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define MESHFAIR_SANITIZER_OWNS_MALLOC 1
#endif
#endif
#ifndef MESHFAIR_SANITIZER_OWNS_MALLOC
#define MESHFAIR_SANITIZER_OWNS_MALLOC 0
#endif
