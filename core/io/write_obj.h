// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>

#include "core/mesh/mesh.h"

namespace meshfair::io {

//! \brief Appends a Wavefront OBJ ("v x y z" and 1-based "f i j k ...") to `out`,
//! coordinates in shortest round-trip form.
void write_obj(const Mesh& mesh, std::string& out);

} // namespace meshfair::io
