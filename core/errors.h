// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace meshfair {

//! A violated precondition on user input: a bad argument, recipe or mesh file.
class InvalidInputError : public std::invalid_argument
{
public:
    explicit InvalidInputError(const std::string& what) : std::invalid_argument(what) {}
};

//! Where in an input file something was found. Text formats fill `line` (and
//! `column` when known); binary formats fill `byte_offset` and name the element,
//! its row and the property being read.
struct SourceLocation
{
    std::string file;
    std::int64_t line = 0;         //!< 1-based; 0 = unknown or binary
    std::int64_t column = 0;       //!< 1-based; 0 = unknown
    std::int64_t byte_offset = -1; //!< for binary data; -1 = not binary
    std::string element;           //!< e.g. "vertex", "face", "triangle"
    std::int64_t row = -1;         //!< index of the element row; -1 = none
    std::string property;          //!< e.g. "x", "vertex_indices"

    //! A place in a text file.
    static SourceLocation text(std::string file, std::int64_t line, std::int64_t column = 0)
    {
        SourceLocation loc;
        loc.file = std::move(file);
        loc.line = line;
        loc.column = column;
        return loc;
    }
    //! A whole file, when no finer place applies.
    static SourceLocation whole(std::string file) { return text(std::move(file), 0); }

    //! "file:12:5" for text, "file: byte 84 (triangle 0, property normal)" for binary.
    std::string to_string() const;
};

//! A mesh file that is malformed: the message names the file and where.
class FormatError : public InvalidInputError
{
public:
    FormatError(SourceLocation where, const std::string& message);
    const SourceLocation& where() const { return where_; }
    const std::string& message() const { return message_; }

private:
    SourceLocation where_;
    std::string message_;
};

//! A recipe that is malformed or does not fit the mesh: the message names the key.
class RecipeError : public InvalidInputError
{
public:
    //! what() is "'file': key: message", or "recipe: key: message" without a file.
    RecipeError(const std::string& key, const std::string& message, const std::string& file = "");
    const std::string& key() const { return key_; }
    const std::string& message() const { return message_; }

private:
    std::string key_;
    std::string message_;
};

//! The key of entry k of the list at key in a RecipeError: "key[k]".
std::string recipe_item_key(const std::string& key, std::size_t k);

//! An operating-system failure reading or writing a file.
class IOError : public std::runtime_error
{
public:
    explicit IOError(const std::string& what) : std::runtime_error(what) {}
};

//! Writing an output file failed; the target is left as it was, except when only the
//! final directory fsync failed after the new content was in place (the message says so).
class WriteError : public IOError
{
public:
    explicit WriteError(const std::string& what) : IOError(what) {}
};

//! The solver was handed data that does not match its precomputation.
class SolverError : public std::runtime_error
{
public:
    explicit SolverError(const std::string& what) : std::runtime_error(what) {}
};

} // namespace meshfair
