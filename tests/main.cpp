// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
