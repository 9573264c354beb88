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
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        for (int c = 0; c < 3; ++c)
        {
            if (c > 0)
                out += ' ';
            append_double(out, mesh.positions[3 * i + c]);
        }
        out += '\n';
    }
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        append_integer(out, mesh.face_size(f));
        for (Index v : mesh.face(f))
        {
            out += ' ';
            append_integer(out, v);
        }
        out += '\n';
    }
}

} // namespace meshfair::io
