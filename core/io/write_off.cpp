// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_off.h"

#include "core/io/text_writer.h"

namespace meshfair::io {

void write_off(const Mesh& mesh, std::string& out)
{
    out += "OFF\n";
    append_integer(out, mesh.vertex_count());
    out += ' ';
    append_integer(out, mesh.face_count());
    // The edge count is optional information that readers ignore; 0 is customary.
    out += " 0\n";
    append_vertex_rows(out, mesh);
    append_counted_face_rows(out, mesh);
}

} // namespace meshfair::io
