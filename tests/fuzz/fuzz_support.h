// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// Helpers shared by the libFuzzer targets in this directory (see README.md).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/io/io.h"
#include "core/mesh/mesh.h"
#include "core/recipe/recipe.h"

namespace meshfair::fuzz {

//! Largest input a target looks at; the scripts also pass -max_len=65536.
inline constexpr size_t kMaxInput = 64 * 1024;

inline std::string_view as_text(const std::uint8_t* data, size_t size)
{
    return {reinterpret_cast<const char*>(data), size};
}

//! True when MESHFAIR_FUZZ_VERBOSE is set: read_or_refuse then prints each outcome (why
//! an input is refused), to check seeds by hand.
bool verbose();

//! Prints `what` and traps, which libFuzzer records as a crash with its input.
[[noreturn]] void fail(const std::string& what);

//! \brief Reads `data` as `format`. nullopt when the reader refuses it with an
//! InvalidInputError (FormatError included): the expected outcome for bad input. Any other
//! exception propagates, so libFuzzer reports it. An accepted mesh that does not satisfy
//! validate_mesh traps.
std::optional<Mesh> read_or_refuse(std::string_view data, io::Format format,
                                   io::ReadReport* report = nullptr,
                                   io::MeshAttributes* attributes = nullptr);

//! The format a file's content looks like: PLY magic, an [ST][C][N][4][n]OFF keyword,
//! STL ("solid" or a binary size that matches its triangle count), else OBJ.
io::Format sniff_format(std::string_view data);

//! \brief Steers PLY input to one encoding. Input starting with "ply" keeps its header
//! except the format line, which becomes "format ENCODING 1.0" (inserted after the
//! magic line when missing). Any other input is a body: bytes 0 and 1 are the vertex
//! and face counts and byte 2 picks the property types of a canned header (see
//! canned_ply_header), and the rest follows that header.
std::string steer_ply(std::string_view data, io::Encoding encoding);

//! The header steer_ply puts before a body; `types` bit 0: float / double coordinates,
//! bits 1-2: uchar / ushort / uint / int list counts, bit 3: int / uint indices, bit 4:
//! an extra "uchar red" vertex property after z.
std::string canned_ply_header(io::Encoding encoding, unsigned vertices, unsigned faces,
                              unsigned types);

//! Bitwise equality of two meshes (positions compared as bits, so -0.0 differs from 0.0).
bool identical(const Mesh& a, const Mesh& b);

//! \brief A cube of 6 quads with one corner cut off by a triangle-pentagon pair: 10
//! vertices, 8 faces of sizes 3, 4 and 5, and a boundary (the recipe and recovery targets'
//! mesh).
Mesh small_mesh();

//! \brief Every number of the recipe within +-1000 (step lengths, targets, normals, weights;
//! a term's mu times a per-element weight within +-1e6): a recipe whose steps must stay
//! finite on small_mesh.
bool bounded(const Recipe& recipe);

//! True when every value is finite.
bool all_finite(const double* values, size_t count);

} // namespace meshfair::fuzz
