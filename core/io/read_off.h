// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <string_view>

#include "core/io/attributes.h"
#include "core/io/io.h"

namespace meshfair::io {

//! \brief Parses a OFF file held in memory; `name` is used in error messages.
//! \throw FormatError naming the file and the line (text) or byte offset (binary).
//! The vertices' normals, colours and texture coordinates ([ST][C][N]OFF) and the faces'
//! colours go to `attributes`.
Mesh read_off(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes);

} // namespace meshfair::io
