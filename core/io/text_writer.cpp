// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/text_writer.h"

#include <charconv>
#include <cmath>

namespace meshfair::io {

void append_double(std::string& out, double value)
{
    char buffer[32];
    // Without a precision argument std::to_chars gives the shortest round-trip form.
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, end);
}

void append_value(std::string& out, double value, ValueType type, bool always_fraction)
{
    if (is_integer_type(type))
    {
        append_integer(out, static_cast<std::int64_t>(value));
        return;
    }
    if (std::isnan(value))
    {
        out += "nan";
        return;
    }
    const size_t start = out.size();
    if (type == ValueType::Float32 && std::isfinite(value))
    {
        char buffer[32];
        auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value));
        out.append(buffer, end);
    }
    else
        append_double(out, value);
    if (always_fraction && std::isfinite(value) &&
        out.find_first_of(".e", start) == std::string::npos)
        out += ".0";
}

void append_integer(std::string& out, std::int64_t value)
{
    char buffer[24];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, end);
}

void append_vertex_rows(std::string& out, const Mesh& mesh)
{
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        append_double(out, mesh.positions[3 * i]);
        out += ' ';
        append_double(out, mesh.positions[3 * i + 1]);
        out += ' ';
        append_double(out, mesh.positions[3 * i + 2]);
        out += '\n';
    }
}

void append_counted_face_rows(std::string& out, const Mesh& mesh)
{
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        append_integer(out, mesh.face_size(f));
        for (const Index v : mesh.face(f))
        {
            out += ' ';
            append_integer(out, v);
        }
        out += '\n';
    }
}

} // namespace meshfair::io
