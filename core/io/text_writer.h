// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <string>

#include "core/io/attributes.h"
#include "core/mesh/mesh.h"

namespace meshfair::io {

//! \brief Appends the shortest decimal text that reads back (with strtod or
//! std::from_chars) to exactly `value`. Negative zero is written as "-0".
void append_double(std::string& out, double value);

//! \brief Appends an attribute value as text for its type: an integer, the shortest
//! text of a float32 or of a double, "nan", "inf" or "-inf". With `always_fraction`, a
//! value of a floating type that prints as an integer gets ".0" (OFF tells integer
//! colours, 0 to 255, from fractions, 0 to 1, by that).
void append_value(std::string& out, double value, ValueType type, bool always_fraction = false);

//! Appends a decimal integer.
void append_integer(std::string& out, std::int64_t value);

//! Appends one "x y z" line per vertex (the body rows of OFF and ASCII PLY).
void append_vertex_rows(std::string& out, const Mesh& mesh);

//! Appends one "n i_1 ... i_n" line per face, 0-based (the body rows of OFF and ASCII PLY).
void append_counted_face_rows(std::string& out, const Mesh& mesh);

} // namespace meshfair::io
