// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <string_view>

#include "core/io/attributes.h"
#include "core/io/io.h"

namespace meshfair::io {

//! \brief Parses a STL file held in memory; `name` is used in error messages.
//! \throw FormatError naming the file and the line (text) or byte offset (binary).
//! A binary file's attribute bytes, when any is not zero, go to `attributes` (face
//! property `stl_attribute`).
Mesh read_stl(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes);

} // namespace meshfair::io
