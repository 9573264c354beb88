// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_ply.h"

namespace meshfair::io {

void write_ply(const Mesh&, Encoding, std::string&) {}

} // namespace meshfair::io
