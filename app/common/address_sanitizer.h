// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// MESHFAIR_ADDRESS_SANITIZER is 1 in builds with AddressSanitizer (GCC or clang), which
// owns malloc: code that interposes malloc must step aside there.
#if defined(__SANITIZE_ADDRESS__)
#define MESHFAIR_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MESHFAIR_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef MESHFAIR_ADDRESS_SANITIZER
#define MESHFAIR_ADDRESS_SANITIZER 0
#endif
