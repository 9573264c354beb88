// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/errors.h"

namespace meshfair {

std::string SourceLocation::to_string() const
{
    // Built with append() only: GCC 12 reports a false -Wrestrict on "literal" + string.
    std::string s = file.empty() ? std::string("<input>") : file;
    if (byte_offset >= 0)
    {
        s.append(": byte ").append(std::to_string(byte_offset));
        if (!element.empty())
        {
            s.append(" (").append(element);
            if (row >= 0)
                s.append(" ").append(std::to_string(row));
            if (!property.empty())
                s.append(", property ").append(property);
            s.append(")");
        }
        return s;
    }
    if (line > 0)
    {
        s.append(":").append(std::to_string(line));
        if (column > 0)
            s.append(":").append(std::to_string(column));
    }
    return s;
}

FormatError::FormatError(SourceLocation where, const std::string& message)
    : InvalidInputError(where.to_string() + ": " + message),
      where_(std::move(where)),
      message_(message)
{
}

std::string recipe_item_key(const std::string& key, std::size_t k)
{
    return key + "[" + std::to_string(k) + "]";
}

JsonValueError::JsonValueError(const std::string& path, const std::string& why,
                               const std::string& file)
    : InvalidInputError((file.empty() ? std::string("recipe") : "'" + file + "'") + ": " + path +
                        ": " + why),
      file_(file),
      path_(path),
      why_(why)
{
}

namespace {

std::string syntax_place(std::int64_t line, std::int64_t column)
{
    return line > 0 ? ":" + std::to_string(line) + ":" + std::to_string(column) : "";
}

} // namespace

JsonSyntaxError::JsonSyntaxError(const std::string& file, std::int64_t line, std::int64_t column,
                                 const std::string& why)
    : InvalidInputError("'" + file + "'" + syntax_place(line, column) + ": not valid JSON: " + why),
      file_(file),
      line_(line),
      column_(column),
      why_(why)
{
}

} // namespace meshfair
