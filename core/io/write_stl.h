// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <vector>

#include "core/io/io.h"

namespace meshfair::io {

//! \brief Appends an STL file to `out`, each polygon fan-triangulated from its first
//! corner (the only place MeshFair splits polygons), with facet normals from the
//! triangle. ASCII writes shortest round-trip decimals; binary (little endian, the only
//! binary STL) stores float32, so it is exact only for float-representable coordinates.
//! Isolated vertices, and vertex order, cannot be represented in STL.
//! A face property `stl_attribute` (ushort) becomes a binary file's attribute bytes, one
//! per triangle of the face. `notes` names the attributes STL cannot hold, the vertices
//! in no face and the polygons split.
//! \throw InvalidInputError for binary output of a coordinate beyond the float32 range.
void write_stl(const Mesh& mesh, const MeshAttributes& attributes, Encoding encoding,
               std::string& out, std::vector<std::string>& notes);

} // namespace meshfair::io
