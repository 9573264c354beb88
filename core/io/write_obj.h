// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <vector>

#include "core/io/attributes.h"
#include "core/mesh/mesh.h"

namespace meshfair::io {

//! \brief Appends a Wavefront OBJ to `out`: "v x y z [r g b]", "vt", "vn", 1-based
//! "f v/vt/vn ..." and the groups, objects, smoothing groups and materials before the
//! faces they applied to (those before the first face at the top); coordinates in
//! shortest round-trip form.
//!
//! Vertex colours are written as fractions (an integer type's value over its largest);
//! per-vertex texture coordinates and normals become one vt or vn per vertex, and a
//! face list `texcoord` one vt per corner. A PLY's header comments become OBJ comments.
//! What OBJ cannot hold is named in `notes`.
void write_obj(const Mesh& mesh, const MeshAttributes& attributes, std::string& out,
               std::vector<std::string>& notes);

} // namespace meshfair::io
