// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/text_writer.h"

#include <charconv>

namespace meshfair::io {

void append_double(std::string& out, double value)
{
    char buffer[32];
    // Without a precision argument std::to_chars gives the shortest round-trip form.
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, end);
}

void append_integer(std::string& out, std::int64_t value)
{
    char buffer[24];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, end);
}

} // namespace meshfair::io
