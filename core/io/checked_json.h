// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/errors.h"

//! \file
//! \brief The one reader of MeshFair's JSON inputs (recipes, recovery and view files):
//! every read checks the value's type and range and refuses it naming the file and the
//! key path to it, in the words docs/recipe.md shows ("must be a number", "must be >= 0
//! (got -1)"). What a reader checks beyond that it says with fail(), at the same path.

namespace meshfair {

//! \brief A JSON value of a named file, at its key path ("actions[3].solver.lambda"; ""
//! for the whole file, named "(top level)" in errors). Cheap to copy: a parsed document
//! is shared by the values taken from it.
class CheckedJson
{
public:
    //! \brief Parses `text`, the content of `file`; the values' paths start at `root_path`.
    //! \throw JsonSyntaxError naming `file`, the line and the column.
    static CheckedJson parse(std::string_view text, std::string file, std::string root_path = "");

    //! \brief A value parsed elsewhere, not copied: `value` must outlive this and every
    //! value taken from it.
    CheckedJson(const nlohmann::json& value, std::string file, std::string path);

    const nlohmann::json& raw() const { return *value_; }
    const std::string& file() const { return source_->file; }
    const std::string& path() const { return path_; }

    //! \brief Refuses this value. \throw JsonValueError naming the file, the path and why.
    [[noreturn]] void fail(const std::string& why) const;

    bool is_object() const { return value_->is_object(); }
    bool is_array() const { return value_->is_array(); }
    bool is_null() const { return value_->is_null(); }
    bool is_string() const { return value_->is_string(); }
    bool is_bool() const { return value_->is_boolean(); }
    bool is_number() const { return value_->is_number(); }
    //! The elements of an array or the members of an object; 0 for null, 1 for a scalar.
    std::size_t size() const { return value_->size(); }

    //! Whether this is an object holding `key`.
    bool has(std::string_view key) const;
    //! \brief The member `key` (path "path.key").
    //! \throw "must be an object"; "is required" at the member's path when it is absent.
    CheckedJson operator[](std::string_view key) const;
    //! The member `key`, or nullopt when absent. \throw "must be an object".
    std::optional<CheckedJson> find(std::string_view key) const;
    //! Element k of an array (path "path[k]"). \throw "must be an array"; "has no element k".
    CheckedJson at(std::size_t k) const;
    //! The elements of an array, in order. \throw "must be an array".
    std::vector<CheckedJson> elements() const;
    //! The members of an object, by key. \throw "must be an object".
    std::vector<std::pair<std::string, CheckedJson>> members() const;
    //! \brief Checks that this is an object of no other members than `allowed`.
    //! \throw "must be an object"; "unknown key (allowed here: a, b)" at the path of the
    //! first other member.
    void only_keys(std::initializer_list<std::string_view> allowed) const;

    //! A string. \throw "must be a string (got 3)".
    std::string text() const;
    //! \throw "must be true or false".
    bool boolean() const;
    //! A finite number. \throw "must be a number", "must be finite".
    double number() const;
    //! \brief A finite number in [lo, hi] (either may be infinite).
    //! \throw as number(); "must be >= lo (got v)", "must be <= hi (got v)" or "must be in
    //! [lo, hi] (got v)".
    double number(double lo, double hi) const;
    //! A finite number > 0. \throw as number(); "must be > 0 (got v)".
    double positive() const;
    //! \brief An integer that fits in 64 bits (1.0 is not one).
    //! \throw "must be an integer (got 1.5)", "is out of range (got 1e+20)".
    long long integer() const;
    //! An integer in [lo, hi]. \throw as integer(); "must be an integer in [lo, hi] (got v)".
    long long integer(long long lo, long long hi) const;
    //! \brief Which of `names` this string is (its index).
    //! \throw "must be \"a\", \"b\" or \"c\"".
    std::size_t choice(std::span<const std::string_view> names) const;
    std::size_t choice(std::initializer_list<std::string_view> names) const
    {
        return choice(std::span<const std::string_view>(names.begin(), names.size()));
    }
    //! The value named by this string in a table of (name, value). \throw as choice(names).
    template <class E, std::size_t N>
    E choice(const std::pair<std::string_view, E> (&table)[N]) const
    {
        std::array<std::string_view, N> names;
        for (std::size_t k = 0; k < N; ++k)
            names[k] = table[k].first;
        return table[choice(std::span<const std::string_view>(names))].second;
    }
    //! \brief An array of finite numbers in [lo, hi], read without a value made for each.
    //! \throw "must be an array"; as number(lo, hi) at "path[k]".
    std::vector<double> numbers(double lo, double hi) const;
    //! \brief A point [x, y, z] of finite numbers.
    //! \throw "must be an [x, y, z] triple"; as number() at "path[k]".
    std::array<double, 3> vec3() const;

    //! This value for a message: a scalar as written (cut at 40 characters), a container
    //! by its kind ("an array"), so that no message grows with what a file nests there.
    std::string describe() const;

private:
    //! What the values of a file share: the document when parsed here, and the file's name.
    // Its destructor is nlohmann::json's, which reserves a stack to free nested values
    // without recursion: were that allocation to fail, std::terminate is the right end.
    // NOLINTNEXTLINE(bugprone-exception-escape)
    struct Source
    {
        nlohmann::json document;
        std::string file;
    };
    CheckedJson(std::shared_ptr<const Source> source, const nlohmann::json& value,
                std::string path);
    CheckedJson child(const nlohmann::json& value, std::string path) const;

    // A value's copy is a reference count and its path: a list of a million elements
    // read one by one copies no file name.
    std::shared_ptr<const Source> source_;
    const nlohmann::json* value_;
    std::string path_;
};

//! \brief The error for JSON text that does not parse, from nlohmann's parse_error message
//! ("... at line L, column C: why"). Shared with the readers not built on CheckedJson.
JsonSyntaxError json_syntax_error(const std::string& file, const std::string& parser_what);

} // namespace meshfair
