// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_off.h"

#include "core/errors.h"

namespace meshfair::io {

Mesh read_off(std::string_view, const std::string& name, ReadReport&)
{
    throw InvalidInputError("'" + name + "': reader not written yet");
}

} // namespace meshfair::io
