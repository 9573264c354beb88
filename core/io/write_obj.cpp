// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_obj.h"

#include "core/io/text_writer.h"

namespace meshfair::io {

void write_obj(const Mesh& mesh, std::string& out)
{
    out += "# MeshFair: ";
    append_integer(out, mesh.vertex_count());
    out += " vertices, ";
    append_integer(out, mesh.face_count());
    out += " faces\n";
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        out += "v";
        for (int c = 0; c < 3; ++c)
        {
            out += ' ';
            append_double(out, mesh.positions[3 * i + c]);
        }
        out += '\n';
    }
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        out += "f";
        for (Index v : mesh.face(f))
        {
            out += ' ';
            append_integer(out, static_cast<std::int64_t>(v) + 1);
        }
        out += '\n';
    }
}

} // namespace meshfair::io
