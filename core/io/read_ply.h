// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <string_view>

#include "core/io/attributes.h"
#include "core/io/io.h"

namespace meshfair::io {

//! \brief Parses a PLY file held in memory; `name` is used in error messages.
//! \throw FormatError naming the file and the line (text) or byte offset (binary).
//! Every property besides x y z and the faces' vertex indices, every other element and the
//! header's comments go to `attributes`.
Mesh read_ply(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes);

} // namespace meshfair::io
