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

//! \brief A value of an input at its key path ("soft[1].weights[0]") that is missing, of
//! another type or out of range (CheckedJson's reads), or a recipe's that does not fit the
//! mesh (check_recipe): names the file, the path and why.
class JsonValueError : public InvalidInputError
{
public:
    //! what() is "'file': path: why", or "recipe: path: why" without a file (a recipe built
    //! in memory).
    JsonValueError(const std::string& path, const std::string& why, const std::string& file = "");
    const std::string& file() const { return file_; }
    const std::string& path() const { return path_; }
    const std::string& why() const { return why_; }
    //! The names recipes speak of: the key at fault and what is wrong with it.
    const std::string& key() const { return path_; }
    const std::string& message() const { return why_; }

private:
    std::string file_;
    std::string path_;
    std::string why_;
};

//! A recipe that is malformed or does not fit the mesh: the one error of every JSON
//! reader, so that one catch sees a recipe's errors whether read or checked.
using RecipeError = JsonValueError;

//! \brief Text that is not JSON: what() is "'file':L:C: not valid JSON: why", without
//! ":L:C" when the parser names no place (a number too large for a double).
class JsonSyntaxError : public InvalidInputError
{
public:
    JsonSyntaxError(const std::string& file, std::int64_t line, std::int64_t column,
                    const std::string& why);
    const std::string& file() const { return file_; }
    std::int64_t line() const { return line_; }     //!< 1-based; 0 = unknown
    std::int64_t column() const { return column_; } //!< 1-based; 0 = unknown
    const std::string& why() const { return why_; }

private:
    std::string file_;
    std::int64_t line_;
    std::int64_t column_;
    std::string why_;
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
