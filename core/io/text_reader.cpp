// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/text_reader.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace meshfair::io {

LineReader::LineReader(std::string_view data, std::string file)
    : data_(data), file_(std::move(file))
{
    if (data_.size() >= 3 && data_.substr(0, 3) == "\xEF\xBB\xBF")
        pos_ = 3;
}

bool LineReader::next()
{
    if (pos_ >= data_.size())
    {
        ended_ = true;
        return false;
    }
    ++line_number_;
    const char* begin = data_.data() + pos_;
    const size_t n = data_.size() - pos_;
    // One pass per line: the terminator search and the NUL check below are both linear.
    size_t len = 0;
    while (len < n && begin[len] != '\n' && begin[len] != '\r')
        ++len;
    line_ = std::string_view(begin, len);
    pos_ += len;
    if (pos_ < data_.size())
    {
        if (data_[pos_] == '\r' && pos_ + 1 < data_.size() && data_[pos_ + 1] == '\n')
            pos_ += 2;
        else
            pos_ += 1;
    }
    if (const void* nul = std::memchr(line_.data(), '\0', line_.size()))
        fail("NUL byte in a text file", static_cast<const char*>(nul) - line_.data() + 1);
    return true;
}

SourceLocation LineReader::here(std::int64_t column) const
{
    SourceLocation loc;
    loc.file = file_;
    loc.line = line_number_;
    loc.column = column;
    if (column == 0 && line_number_ > 0)
    {
        // Every text location has a column: past the end of the last line when the
        // data ran out, else where the line's statement starts.
        size_t first = 0;
        while (!ended_ && first < line_.size() && is_blank(line_[first]))
            ++first;
        loc.column =
            static_cast<std::int64_t>(ended_ || first == line_.size() ? line_.size() : first) + 1;
    }
    return loc;
}

std::int64_t LineReader::column_of(std::string_view token) const
{
    return static_cast<std::int64_t>(token.data() - line_.data()) + 1;
}

void LineReader::fail(const std::string& message, std::int64_t column) const
{
    throw FormatError(here(column), message);
}

void LineReader::fail_at(std::string_view token, const std::string& message) const
{
    throw FormatError(here(column_of(token)), message);
}

bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

std::string_view Tokenizer::next()
{
    size_t a = 0;
    while (a < rest_.size() && is_blank(rest_[a]))
        ++a;
    size_t b = a;
    while (b < rest_.size() && !is_blank(rest_[b]))
        ++b;
    std::string_view token = rest_.substr(a, b - a);
    rest_ = rest_.substr(b);
    return token;
}

bool Tokenizer::at_end()
{
    size_t a = 0;
    while (a < rest_.size() && is_blank(rest_[a]))
        ++a;
    rest_ = rest_.substr(a);
    return rest_.empty();
}

std::string quoted(std::string_view token)
{
    constexpr size_t kMax = 40;
    std::string s(token.substr(0, kMax));
    if (token.size() > kMax)
        s += "...";
    return "'" + s + "'";
}

std::string count_of(std::int64_t n, const char* singular, const char* plural)
{
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

bool equals_ignoring_case(std::string_view a, std::string_view b)
{
    const auto lower = [](char c) {
        return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
    };
    if (a.size() != b.size())
        return false;
    for (size_t k = 0; k < a.size(); ++k)
        if (lower(a[k]) != lower(b[k]))
            return false;
    return true;
}

namespace {

// std::from_chars refuses the leading '+' that strtod accepts; "+-1" stays refused.
std::string_view without_plus(const LineReader& reader, std::string_view token,
                              std::string_view what, const char* kind)
{
    if (token.front() != '+')
        return token;
    const std::string_view rest = token.substr(1);
    if (!rest.empty() && (rest.front() == '+' || rest.front() == '-'))
        reader.fail_at(token, std::string(what) + " " + quoted(token) + " is not " + kind);
    return rest;
}

} // namespace

double parse_double(const LineReader& reader, std::string_view token, std::string_view what)
{
    if (token.empty())
        reader.fail(std::string("missing ") + std::string(what));
    const std::string_view digits = without_plus(reader, token, what, "a number");
    double value = 0;
    // std::from_chars is correctly rounded, like strtod, but never reads a locale.
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range)
        reader.fail_at(
            token, std::string(what) + " " + quoted(token) + " is out of the range of a double");
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
        reader.fail_at(token, std::string(what) + " " + quoted(token) + " is not a number");
    if (!std::isfinite(value))
        reader.fail_at(token, std::string(what) + " " + quoted(token) + " is not finite");
    return value;
}

std::int64_t parse_integer(const LineReader& reader, std::string_view token, std::string_view what)
{
    if (token.empty())
        reader.fail(std::string("missing ") + std::string(what));
    const std::string_view digits = without_plus(reader, token, what, "an integer");
    std::int64_t value = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range)
        reader.fail_at(token, std::string(what) + " " + quoted(token) + " is out of range");
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
        reader.fail_at(token, std::string(what) + " " + quoted(token) + " is not an integer");
    return value;
}

} // namespace meshfair::io
