// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
int main() { return 0; }
