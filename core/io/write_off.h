// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <vector>

#include "core/io/attributes.h"
#include "core/mesh/mesh.h"

namespace meshfair::io {

//! \brief Appends an ASCII OFF file to `out`, coordinates in shortest round-trip form.
//!
//! Vertex normals, colours and texture coordinates are written as Geomview's
//! [ST][C][N]OFF has them (x y z, nx ny nz, r g b [a], s t on each vertex line), and face
//! colours after each face's indices. Colours of an integer type are written as
//! integers, others as fractions with a decimal point, which is how OFF tells them apart.
//! An OBJ's per-corner values are written per vertex when each vertex has one. What OFF
//! cannot hold is named in `notes`; a PLY's header comments become OFF comments.
void write_off(const Mesh& mesh, const MeshAttributes& attributes, std::string& out,
               std::vector<std::string>& notes);

} // namespace meshfair::io
