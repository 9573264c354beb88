// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <string_view>

#include "core/io/attributes.h"
#include "core/io/io.h"

namespace meshfair::io {

//! \brief Parses a OBJ file held in memory; `name` is used in error messages.
//! \throw FormatError naming the file and the line (text) or byte offset (binary).
//! Files of 8 MiB and more are parsed on the threads (read_obj_in_ranges).
//! Texture coordinates (vt), normals (vn), vertex colours (v x y z r g b) and the groups,
//! objects, smoothing groups and materials go to `attributes`.
Mesh read_obj(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes);

//! \brief read_obj with the data cut at line ends into `ranges` parts parsed at the same
//! time and joined in file order. The result, the report and every error message are
//! those of the serial parse (`ranges` = 1), for any `ranges`: a part that starts at an
//! unknown vertex count and line gives up on whatever depends on them (negative indices,
//! notes that name a line, errors), and then the whole file is parsed serially.
//! `parsed_in`, when given, receives the number of parts the result came from (1 when
//! the serial parse decided).
Mesh read_obj_in_ranges(std::string_view data, const std::string& name, ReadReport& report,
                        MeshAttributes& attributes, int ranges, int* parsed_in = nullptr);

} // namespace meshfair::io
