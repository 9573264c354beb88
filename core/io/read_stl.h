// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <string_view>

#include "core/io/io.h"

namespace meshfair::io {

//! \brief Parses a STL file held in memory; `name` is used in error messages.
//! \throw FormatError naming the file and the line (text) or byte offset (binary).
Mesh read_stl(std::string_view data, const std::string& name, ReadReport& report);

} // namespace meshfair::io
