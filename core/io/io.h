// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/io/attributes.h"
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

//! What a writer does with the normals among the attributes.
enum class Normals
{
    Recompute, //!< from the positions written (recompute_normals): they match the surface
    Keep       //!< as read, with a note: they describe the surface the file was read with
};

//! How to write a mesh.
struct WriteOptions
{
    //! PLY and STL only: Ascii, or binary (PLY: either byte order; STL: little endian).
    Encoding encoding = Encoding::BinaryLittleEndian;
    Normals normals = Normals::Recompute;
};

//! \brief Format named by a path's extension (.obj .off .ply .stl, any case).
//! \throw InvalidInputError for any other extension.
Format format_from_path(const std::string& path);

std::string_view format_name(Format format);
std::string_view encoding_name(Encoding encoding);

//! \brief Reads a mesh file, choosing the reader from the extension.
//!
//! Vertex and face order are those of the file. The result satisfies validate_mesh.
//! Everything else the file holds (texture coordinates, normals, colours, other
//! properties and elements, groups and materials) goes to `attributes` when given (see
//! MeshAttributes); a note in the report names whatever a reader cannot keep.
//! \throw InvalidInputError when the file cannot be opened or the extension is unknown.
//! \throw FormatError (an InvalidInputError) naming file and line or byte offset when
//! the content is malformed.
Mesh read_mesh(const std::string& path, ReadReport* report = nullptr,
               MeshAttributes* attributes = nullptr);

//! \brief Parses mesh data held in memory; `name` is used in error messages.
Mesh read_mesh_data(std::string_view data, Format format, const std::string& name,
                    ReadReport* report = nullptr, MeshAttributes* attributes = nullptr);

//! \brief Serializes a mesh. OBJ, OFF, ASCII PLY and ASCII STL write every coordinate
//! in the shortest decimal form that reads back to the same double; binary PLY writes
//! doubles. Binary STL stores float32 (its format has no doubles), and STL output
//! fan-triangulates polygons: the only place MeshFair splits a polygon.
//!
//! `attributes` (in the mesh's numbering, as read_mesh gives them) are written wherever
//! the format can hold them, converted where it holds them differently (docs/formats.md,
//! "Attributes"); normals as `options.normals` says. Every attribute, and every part of
//! the mesh, the format cannot hold is named in one note per kind appended to `notes`.
//! \throw InvalidInputError when the attributes do not fit the mesh (check_attributes).
std::string write_mesh_data(const Mesh& mesh, Format format, const WriteOptions& options = {},
                            const MeshAttributes* attributes = nullptr,
                            std::vector<std::string>* notes = nullptr);

//! \brief Writes a mesh file atomically (see write_file_atomically), as write_mesh_data
//! serializes it.
//! \throw WriteError when the file cannot be written; an existing file is left intact
//! (unless the message says the new content is in place).
void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options = {},
                const MeshAttributes* attributes = nullptr,
                std::vector<std::string>* notes = nullptr);

//! \brief Reads a whole file into memory.
//! \throw InvalidInputError when it cannot be opened or read.
std::string read_file(const std::string& path);

//! \brief Replaces the file at `path` by `data` so that, at every instant and after a
//! crash or a kill, `path` holds either its old content or all of the new.
//!
//! Protocol: create `<target>.tmp-XXXXXX` beside the target (O_CREAT|O_EXCL, close-on-
//! exec) with the target's permission bits (a new file: 0666 & ~umask), write all of
//! `data` (EINTR retried, short writes continued, a write of 0 bytes is an error),
//! fsync, close, rename it over the target, then fsync the directory.
//!
//! Policies:
//! - Symbolic links are followed (up to 40 hops, like the kernel), also a dangling
//!   one, whose relative content is read against the link's own directory: the link
//!   stays a link, the file it points to gets the new content and the temporary file
//!   lives beside that file. Hard links are not kept: the target becomes a new inode.
//! - Only a regular file is replaced: a directory, a device, a FIFO or a socket is
//!   refused, and so is a file the caller could not open for writing (checked with
//!   access(W_OK) on the effective ids, as `>` in a shell would fail; root may replace a
//!   read-only file). The replacement keeps the mode; owner, group, ACLs and extended
//!   attributes become those of a new file of the caller.
//!
//! Precondition: `data` is the complete content, serialized before calling.
//! \throw WriteError on any failed step, with a message "'path': step: reason" (the
//! reason is strerror(errno)). The temporary file is removed and the target untouched,
//! except when only the final directory fsync fails: then the new content is already
//! in place and the message says so. A failed fsync is never retried. When the process
//! is killed (SIGKILL, or SIGXFSZ over `ulimit -f` when that signal is not ignored), the
//! target is still old or new, but a stale `.tmp-` file may be left beside it.
void write_file_atomically(const std::string& path, std::string_view data);

} // namespace meshfair::io
