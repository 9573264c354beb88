// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_off.h"

namespace meshfair::io {

void write_off(const Mesh&, std::string&) {}

} // namespace meshfair::io
