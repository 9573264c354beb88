// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/errors.h"

namespace meshfair::io {

//! \brief Walks a text file held in memory line by line, numbering lines from 1.
//!
//! Accepts LF, CRLF and CR-only line endings and skips a UTF-8 byte-order mark at the
//! start. A NUL byte anywhere in a line is refused (text formats never contain one).
class LineReader
{
public:
    LineReader(std::string_view data, std::string file);

    //! Moves to the next line; false at the end of the data.
    //! \throw FormatError when the line holds a NUL byte.
    bool next();
    std::string_view line() const { return line_; }
    std::int64_t line_number() const { return line_number_; }
    //! Byte offset of the start of the current line's successor (= bytes consumed).
    size_t consumed() const { return pos_; }
    size_t remaining_bytes() const { return data_.size() - pos_; }
    const std::string& file() const { return file_; }

    //! The current line and a column inside it (1-based). Column 0 picks a default: the
    //! line's first non-blank character, or just past the last line once next() has
    //! returned false (the data ended there).
    SourceLocation here(std::int64_t column = 0) const;
    //! Column (1-based) of `token`, which must be a view into line().
    std::int64_t column_of(std::string_view token) const;
    [[noreturn]] void fail(const std::string& message, std::int64_t column = 0) const;
    [[noreturn]] void fail_at(std::string_view token, const std::string& message) const;

private:
    std::string_view data_;
    std::string file_;
    size_t pos_ = 0;
    std::string_view line_;
    std::int64_t line_number_ = 0;
    bool ended_ = false;
};

//! \brief Splits a line into whitespace-separated tokens (space, tab, VT, FF).
class Tokenizer
{
public:
    explicit Tokenizer(std::string_view line) : rest_(line) {}
    //! The next token, or an empty view at the end.
    std::string_view next();
    //! True when only whitespace remains.
    bool at_end();

private:
    std::string_view rest_;
};

//! True for the characters Tokenizer treats as blanks.
bool is_blank(char c);

//! A token quoted for a message, cut after 40 characters: 'abc...'.
std::string quoted(std::string_view token);

//! "1 vertex", "3 vertices": a count with the right noun.
std::string count_of(std::int64_t n, const char* singular, const char* plural);

//! ASCII case-insensitive comparison, independent of the locale (format keywords).
bool equals_ignoring_case(std::string_view a, std::string_view b);

//! \brief Parses a whole token as a double exactly as strtod would (correctly rounded;
//! a leading '+' is accepted), refusing anything else with the token's column.
//! \throw FormatError for text that is not a number, or that is nan, inf or out of range.
double parse_double(const LineReader& reader, std::string_view token, std::string_view what);

//! \brief Parses a whole token as a decimal integer.
//! \throw FormatError for text that is not an integer or outside int64.
std::int64_t parse_integer(const LineReader& reader, std::string_view token, std::string_view what);

} // namespace meshfair::io
