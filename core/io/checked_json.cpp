// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/checked_json.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace meshfair {

namespace {

// A bound for a message: whole numbers as integers, so "must be >= 0" reads as written.
std::string bound_text(double v)
{
    if (std::abs(v) < 1e15 && v == std::floor(v))
        return std::to_string(static_cast<long long>(v));
    char s[32];
    std::snprintf(s, sizeof s, "%g", v);
    return s;
}

} // namespace

JsonSyntaxError json_syntax_error(const std::string& file, const std::string& what)
{
    // what is "[json.exception.parse_error.101] parse error at line L, column C: why".
    const auto at = what.find(" at line ");
    const auto why = what.find(": ", at == std::string::npos ? 0 : at);
    if (at == std::string::npos || why == std::string::npos)
        return JsonSyntaxError(file, 0, 0, what);
    const std::string place = what.substr(at + 9, why - at - 9); // "L, column C"
    const auto comma = place.find(", column ");
    const long long line = std::atoll(place.c_str());
    const long long column = comma == std::string::npos ? 0 : std::atoll(place.c_str() + comma + 9);
    return JsonSyntaxError(file, line, column, what.substr(why + 2));
}

CheckedJson CheckedJson::parse(std::string_view text, std::string file, std::string root_path)
{
    auto source = std::make_shared<Source>();
    try
    {
        source->document = nlohmann::json::parse(text.begin(), text.end());
    }
    catch (const nlohmann::json::parse_error& e)
    {
        throw json_syntax_error(file, e.what());
    }
    catch (const nlohmann::json::exception& e)
    {
        // e.g. a number too large for a double: "number overflow parsing '1e400'", at no
        // place the parser names. The message without nlohmann's "[json.exception...] ".
        const std::string what = e.what();
        const auto close = what.find("] ");
        throw JsonSyntaxError(file, 0, 0,
                              close == std::string::npos ? what : what.substr(close + 2));
    }
    source->file = std::move(file);
    const nlohmann::json& value = source->document;
    return CheckedJson(std::move(source), value, std::move(root_path));
}

CheckedJson::CheckedJson(const nlohmann::json& value, std::string file, std::string path)
    : CheckedJson(std::make_shared<Source>(Source{{}, std::move(file)}), value, std::move(path))
{
}

CheckedJson::CheckedJson(std::shared_ptr<const Source> source, const nlohmann::json& value,
                         std::string path)
    : source_(std::move(source)), value_(&value), path_(std::move(path))
{
}

CheckedJson CheckedJson::child(const nlohmann::json& value, std::string path) const
{
    return CheckedJson(source_, value, std::move(path));
}

void CheckedJson::fail(const std::string& why) const
{
    throw JsonValueError(path_.empty() ? "(top level)" : path_, why, source_->file);
}

bool CheckedJson::has(std::string_view key) const
{
    return value_->is_object() && value_->contains(key);
}

std::optional<CheckedJson> CheckedJson::find(std::string_view key) const
{
    if (!value_->is_object())
        fail("must be an object");
    const auto it = value_->find(key);
    if (it == value_->end())
        return std::nullopt;
    return child(*it, path_.empty() ? std::string(key) : path_ + "." + std::string(key));
}

CheckedJson CheckedJson::operator[](std::string_view key) const
{
    std::optional<CheckedJson> member = find(key);
    if (!member)
        child(*value_, path_.empty() ? std::string(key) : path_ + "." + std::string(key))
            .fail("is required");
    return std::move(*member);
}

CheckedJson CheckedJson::at(std::size_t k) const
{
    if (!value_->is_array())
        fail("must be an array");
    if (k >= value_->size())
        fail("has no element " + std::to_string(k));
    return child((*value_)[k], path_ + "[" + std::to_string(k) + "]");
}

std::vector<CheckedJson> CheckedJson::elements() const
{
    if (!value_->is_array())
        fail("must be an array");
    std::vector<CheckedJson> out;
    out.reserve(value_->size());
    for (std::size_t k = 0; k < value_->size(); ++k)
        out.push_back(child((*value_)[k], path_ + "[" + std::to_string(k) + "]"));
    return out;
}

std::vector<std::pair<std::string, CheckedJson>> CheckedJson::members() const
{
    if (!value_->is_object())
        fail("must be an object");
    std::vector<std::pair<std::string, CheckedJson>> out;
    out.reserve(value_->size());
    for (const auto& [key, value] : value_->items())
        out.emplace_back(key, child(value, path_.empty() ? key : path_ + "." + key));
    return out;
}

void CheckedJson::only_keys(std::initializer_list<std::string_view> allowed) const
{
    for (const auto& [key, value] : members())
    {
        bool known = false;
        std::string list;
        for (const std::string_view a : allowed)
        {
            known = known || key == a;
            list.append(list.empty() ? "" : ", ").append(a);
        }
        if (!known)
            value.fail(list.empty() ? "unknown key (this section takes none)"
                                    : "unknown key (allowed here: " + list + ")");
    }
}

std::string CheckedJson::describe() const
{
    if (value_->is_array())
        return "an array";
    if (value_->is_object())
        return "an object";
    std::string text = value_->dump();
    if (text.size() > 40)
        text = text.substr(0, 40) + "...";
    return text;
}

std::string CheckedJson::text() const
{
    if (!value_->is_string())
        fail("must be a string (got " + describe() + ")");
    return value_->get<std::string>();
}

bool CheckedJson::boolean() const
{
    if (!value_->is_boolean())
        fail("must be true or false");
    return value_->get<bool>();
}

double CheckedJson::number() const
{
    if (!value_->is_number())
        fail("must be a number");
    const double v = value_->get<double>();
    if (!std::isfinite(v))
        fail("must be finite");
    return v;
}

double CheckedJson::number(double lo, double hi) const
{
    const double v = number();
    if (v < lo || v > hi)
        fail((hi == std::numeric_limits<double>::infinity() ? "must be >= " + bound_text(lo)
              : lo == -std::numeric_limits<double>::infinity()
                  ? "must be <= " + bound_text(hi)
                  : "must be in [" + bound_text(lo) + ", " + bound_text(hi) + "]") +
             " (got " + describe() + ")");
    return v;
}

double CheckedJson::positive() const
{
    const double v = number();
    if (!(v > 0))
        fail("must be > 0 (got " + describe() + ")");
    return v;
}

long long CheckedJson::integer() const
{
    // The parser keeps integers >= 0 as unsigned, those past uint64 as doubles.
    const bool past_int64 =
        (value_->is_number_unsigned() &&
         value_->get<unsigned long long>() > std::numeric_limits<long long>::max()) ||
        (value_->is_number_float() && std::abs(value_->get<double>()) >= 9.2e18);
    if (past_int64)
        fail("is out of range (got " + describe() + ")");
    if (value_->is_number_integer())
        return value_->get<long long>();
    fail("must be an integer (got " + describe() + ")");
}

long long CheckedJson::integer(long long lo, long long hi) const
{
    const long long v = integer();
    if (v < lo || v > hi)
        fail("must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
             "] (got " + describe() + ")");
    return v;
}

std::size_t CheckedJson::choice(std::span<const std::string_view> names) const
{
    std::string listed;
    for (std::size_t k = 0; k < names.size(); ++k)
    {
        if (value_->is_string() && value_->get_ref<const std::string&>() == names[k])
            return k;
        listed.append(k == 0                  ? ""
                      : k + 1 == names.size() ? " or "
                                              : ", ")
            .append("\"")
            .append(names[k])
            .append("\"");
    }
    fail("must be " + listed);
}

std::vector<double> CheckedJson::numbers(double lo, double hi) const
{
    if (!value_->is_array())
        fail("must be an array");
    std::vector<double> out(value_->size());
    for (std::size_t k = 0; k < out.size(); ++k)
    {
        const nlohmann::json& v = (*value_)[k];
        out[k] = v.is_number() ? v.get<double>() : lo;
        if (!v.is_number() || !(out[k] >= lo && out[k] <= hi) || !std::isfinite(out[k]))
            out[k] = at(k).number(lo, hi); // refuses it, naming it
    }
    return out;
}

std::array<double, 3> CheckedJson::vec3() const
{
    if (!value_->is_array() || value_->size() != 3)
        fail("must be an [x, y, z] triple");
    std::array<double, 3> p;
    for (std::size_t a = 0; a < 3; ++a)
    {
        const nlohmann::json& v = (*value_)[a];
        p[a] = v.is_number() ? v.get<double>() : 0;
        if (!v.is_number() || !std::isfinite(p[a]))
            p[a] = at(a).number(); // refuses it, naming it
    }
    return p;
}

} // namespace meshfair
