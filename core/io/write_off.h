// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>

#include "core/mesh/mesh.h"

namespace meshfair::io {

//! \brief Appends an ASCII OFF file to `out`, coordinates in shortest round-trip form.
void write_off(const Mesh& mesh, std::string& out);

} // namespace meshfair::io
