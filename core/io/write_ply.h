// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>

#include "core/io/io.h"

namespace meshfair::io {

//! \brief Appends a PLY file to `out`: vertex x, y, z as double and a face list
//! "vertex_indices" (uchar count, int index; uint count when a face has > 255 sides).
//! ASCII writes shortest round-trip decimals; binary writes doubles in either order.
void write_ply(const Mesh& mesh, Encoding encoding, std::string& out);

} // namespace meshfair::io
