// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <vector>

#include "core/io/io.h"

namespace meshfair::io {

//! \brief Appends a PLY file to `out`: vertex x, y, z as double and a face list
//! "vertex_indices" (uchar count, int index; uint count when a face has > 255 sides),
//! then every attribute table as its own properties and elements, in their types, and
//! the header comments. ASCII writes shortest round-trip decimals; binary writes the
//! declared types in either byte order.
//!
//! An OBJ's per-corner normals become vertex normals `nx ny nz` (their mean at a vertex
//! where they differ, with a note); its texture coordinates become `texture_u
//! texture_v` when each vertex has one pair, else a face list `texcoord` (MeshLab's
//! per-corner layout). What PLY cannot hold (OBJ groups and materials) is named in
//! `notes`.
void write_ply(const Mesh& mesh, const MeshAttributes& attributes, Encoding encoding,
               std::string& out, std::vector<std::string>& notes);

} // namespace meshfair::io
