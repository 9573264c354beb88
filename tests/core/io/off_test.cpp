// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
