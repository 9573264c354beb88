// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <string>

namespace meshfair::io {

//! \brief Appends the shortest decimal text that reads back (with strtod or
//! std::from_chars) to exactly `value`. Negative zero is written as "-0".
void append_double(std::string& out, double value);

//! Appends a decimal integer.
void append_integer(std::string& out, std::int64_t value);

} // namespace meshfair::io
