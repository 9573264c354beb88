// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/write_ply.h"

#include <bit>
#include <cstdint>
#include <cstring>

#include "core/io/text_writer.h"

namespace meshfair::io {

namespace {

template <typename T>
void append_binary(std::string& out, T value, bool is_big_endian)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (is_big_endian != (std::endian::native == std::endian::big))
        for (size_t k = 0; k < sizeof(T) / 2; ++k)
            std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
    out.append(bytes, sizeof(T));
}

} // namespace

void write_ply(const Mesh& mesh, Encoding encoding, std::string& out)
{
    bool has_long_faces = false;
    for (Index f = 0; f < mesh.face_count(); ++f)
        has_long_faces = has_long_faces || mesh.face_size(f) > 255;

    out += "ply\nformat ";
    out += encoding_name(encoding);
    out += " 1.0\ncomment MeshFair\nelement vertex ";
    append_integer(out, mesh.vertex_count());
    out += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
    append_integer(out, mesh.face_count());
    out += has_long_faces ? "\nproperty list uint int vertex_indices\n"
                          : "\nproperty list uchar int vertex_indices\n";
    out += "end_header\n";

    if (encoding == Encoding::Ascii)
    {
        append_vertex_rows(out, mesh);
        append_counted_face_rows(out, mesh);
        return;
    }

    const bool is_big_endian = encoding == Encoding::BinaryBigEndian;
    const size_t count_size = has_long_faces ? 4 : 1;
    out.reserve(out.size() + mesh.positions.size() * sizeof(double) +
                static_cast<size_t>(mesh.face_count()) * count_size +
                mesh.face_vertices.size() * sizeof(std::int32_t));
    for (double x : mesh.positions)
        append_binary(out, x, is_big_endian);
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        if (has_long_faces)
            append_binary(out, static_cast<std::uint32_t>(mesh.face_size(f)), is_big_endian);
        else
            append_binary(out, static_cast<std::uint8_t>(mesh.face_size(f)), is_big_endian);
        for (Index v : mesh.face(f))
            append_binary(out, static_cast<std::int32_t>(v), is_big_endian);
    }
}

} // namespace meshfair::io
