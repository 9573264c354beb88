// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair::io {

enum class Format
{
    Obj,
    Off,
    Ply,
    Stl
};

enum class Encoding
{
    Ascii,
    BinaryLittleEndian,
    BinaryBigEndian
};

//! What a reader did to accept a file, beyond copying it: every normalization or
//! skipped part is one human-readable note, so nothing is silently dropped.
struct ReadReport
{
    Format format = Format::Obj;
    Encoding encoding = Encoding::Ascii;
    std::vector<std::string> notes;
};

//! How to write a mesh.
struct WriteOptions
{
    //! PLY and STL only: Ascii, or binary (PLY: either byte order; STL: little endian).
    Encoding encoding = Encoding::BinaryLittleEndian;
};

//! \brief Format named by a path's extension (.obj .off .ply .stl, any case).
//! \throw InvalidInputError for any other extension.
Format format_from_path(const std::string& path);

std::string_view format_name(Format format);
std::string_view encoding_name(Encoding encoding);

//! \brief Reads a mesh file, choosing the reader from the extension.
//!
//! Vertex and face order are those of the file. The result satisfies validate_mesh.
//! \throw InvalidInputError when the file cannot be opened or the extension is unknown.
//! \throw FormatError (an InvalidInputError) naming file and line or byte offset when
//! the content is malformed.
Mesh read_mesh(const std::string& path, ReadReport* report = nullptr);

//! \brief Parses mesh data held in memory; `name` is used in error messages.
Mesh read_mesh_data(std::string_view data, Format format, const std::string& name,
                    ReadReport* report = nullptr);

//! \brief Serializes a mesh. OBJ, OFF, ASCII PLY and ASCII STL write every coordinate
//! in the shortest decimal form that reads back to the same double; binary PLY writes
//! doubles. Binary STL stores float32 (its format has no doubles), and STL output
//! fan-triangulates polygons: the only place MeshFair splits a polygon.
std::string write_mesh_data(const Mesh& mesh, Format format, const WriteOptions& options = {});

//! \brief Writes a mesh file atomically (see write_file_atomically).
//! \throw WriteError when the file cannot be written; an existing file is left intact.
void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options = {});

//! \brief Reads a whole file into memory.
//! \throw InvalidInputError when it cannot be opened or read.
std::string read_file(const std::string& path);

//! \brief Writes `data` to a temporary file beside `path`, flushes it to disk and
//! renames it over `path`, so `path` holds either its old content or all of the new.
//! \throw WriteError on any failed step; the temporary file is removed.
void write_file_atomically(const std::string& path, std::string_view data);

} // namespace meshfair::io
