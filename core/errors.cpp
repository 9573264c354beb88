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

RecipeError::RecipeError(const std::string& key, const std::string& message,
                         const std::string& file)
    : InvalidInputError((file.empty() ? std::string("recipe") : "'" + file + "'") + ": " + key +
                        ": " + message),
      key_(key),
      message_(message)
{
}

} // namespace meshfair
