// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_stl.h"

namespace meshfair::io {

void write_stl(const Mesh&, Encoding, std::string&) {}

} // namespace meshfair::io
