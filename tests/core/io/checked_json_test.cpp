// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/checked_json.h"

#include <doctest/doctest.h>

#include <functional>
#include <limits>
#include <string>

#include "core/errors.h"

using namespace meshfair;

namespace {

// "path: why" of the JsonValueError `read` throws, checked to name the file; "" when it
// throws nothing. (No CHECK in here: it runs inside another's expression.)
std::string error_of(const std::function<void()>& read)
{
    try
    {
        read();
    }
    catch (const JsonValueError& e)
    {
        const std::string at = e.path() + ": " + e.why();
        if (e.file() != "f.json" || std::string(e.what()) != "'f.json': " + at)
            return "another file or message: " + std::string(e.what());
        return at;
    }
    return "";
}

enum class Shade
{
    Light,
    Dark
};

} // namespace

TEST_SUITE("CheckedJson")
{
    TEST_CASE("each typed read gives its value and refuses another type, naming file and path")
    {
        const CheckedJson j = CheckedJson::parse(
            R"({"s": "text", "b": true, "n": 2.5, "i": 7, "v": [1, 2, 3], "o": {}, "z": null})",
            "f.json");
        CHECK(j["s"].text() == "text");
        CHECK(j["b"].boolean());
        CHECK(j["n"].number() == 2.5);
        CHECK(j["i"].integer() == 7);
        CHECK(j["i"].number() == 7);
        CHECK(j["v"].vec3() == std::array<double, 3>{1, 2, 3});
        CHECK(j["z"].is_null());

        CHECK(error_of([&] { (void)j["n"].text(); }) == "n: must be a string (got 2.5)");
        CHECK(error_of([&] { (void)j["o"].text(); }) == "o: must be a string (got an object)");
        CHECK(error_of([&] { (void)j["s"].boolean(); }) == "s: must be true or false");
        CHECK(error_of([&] { (void)j["s"].number(); }) == "s: must be a number");
        CHECK(error_of([&] { (void)j["b"].number(); }) == "b: must be a number");
        CHECK(error_of([&] { (void)j["n"].integer(); }) == "n: must be an integer (got 2.5)");
        CHECK(error_of([&] { (void)j["s"].integer(); }) == "s: must be an integer (got \"text\")");
        CHECK(error_of([&] { (void)j["z"].vec3(); }) == "z: must be an [x, y, z] triple");
        CHECK(error_of([&] { (void)j["s"].choice({"a", "b"}); }) == "s: must be \"a\" or \"b\"");
        CHECK(error_of([&] { (void)j["n"].elements(); }) == "n: must be an array");
        CHECK(error_of([&] { (void)j["v"].members(); }) == "v: must be an object");
        CHECK(error_of([&] { (void)j["v"]["x"]; }) == "v: must be an object");
        CHECK(error_of([&] { (void)j["o"].at(0); }) == "o: must be an array");
        CHECK(error_of([&] { (void)j["v"].at(3); }) == "v: has no element 3");
    }

    TEST_CASE("ranges: numbers and integers out of range are refused with the value given")
    {
        const CheckedJson j =
            CheckedJson::parse(R"({"neg": -1, "zero": 0, "big": 1e20, "huge": 18446744073709551615,
                                   "half": 0.5, "two": 2})",
                               "f.json");
        const double inf = std::numeric_limits<double>::infinity();
        CHECK(j["zero"].number(0, inf) == 0);
        CHECK(j["half"].number(0, 1) == 0.5);
        CHECK(j["half"].positive() == 0.5);
        CHECK(j["two"].integer(0, 2) == 2);
        CHECK(error_of([&] { (void)j["neg"].number(0, inf); }) == "neg: must be >= 0 (got -1)");
        CHECK(error_of([&] { (void)j["two"].number(-inf, 1); }) == "two: must be <= 1 (got 2)");
        CHECK(error_of([&] { (void)j["two"].number(0, 1.5); }) ==
              "two: must be in [0, 1.5] (got 2)");
        CHECK(error_of([&] { (void)j["zero"].positive(); }) == "zero: must be > 0 (got 0)");
        CHECK(error_of([&] { (void)j["neg"].integer(0, 10); }) ==
              "neg: must be an integer in [0, 10] (got -1)");
        CHECK(error_of([&] { (void)j["big"].integer(); }) == "big: is out of range (got 1e+20)");
        CHECK(error_of([&] { (void)j["huge"].integer(); }) ==
              "huge: is out of range (got 18446744073709551615)");
        // A value built in memory may hold what no parsed text does.
        const nlohmann::json nan = std::numeric_limits<double>::quiet_NaN();
        CHECK(error_of([&] { (void)CheckedJson(nan, "f.json", "x").number(); }) ==
              "x: must be finite");
    }

    TEST_CASE("choices: by index, or by a table of names and values")
    {
        const CheckedJson j = CheckedJson::parse(R"(["b", "dark", 3])", "f.json");
        CHECK(j.at(0).choice({"a", "b", "c"}) == 1);
        CHECK(j.at(1).choice<Shade>({{"light", Shade::Light}, {"dark", Shade::Dark}}) ==
              Shade::Dark);
        CHECK(error_of([&] {
                  (void)j.at(2).choice({"a", "b", "c"});
              }) == "[2]: must be \"a\", \"b\" or \"c\"");
    }

    TEST_CASE("nested values are named by their path from the root: a.b[2].c")
    {
        const CheckedJson j = CheckedJson::parse(
            R"({"a": {"b": [{}, {}, {"c": "x", "d": [0, [1, "y"]]}]}})", "f.json");
        const CheckedJson c = j["a"]["b"].at(2)["c"];
        CHECK(c.path() == "a.b[2].c");
        CHECK(c.file() == "f.json");
        CHECK(error_of([&] { (void)c.number(); }) == "a.b[2].c: must be a number");
        CHECK(error_of([&] { (void)j["a"]["b"].at(2)["d"].elements()[1].at(1).number(); }) ==
              "a.b[2].d[1][1]: must be a number");
        CHECK(error_of([&] { (void)j["a"]["b"].at(0)["c"]; }) == "a.b[0].c: is required");
        CHECK(error_of([&] { j["a"]["b"].fail("is wrong"); }) == "a.b: is wrong");
        CHECK(error_of([&] { j.fail("is wrong"); }) == "(top level): is wrong");
        // A root path: the file's values named as parts of a larger whole.
        const CheckedJson rooted = CheckedJson::parse(R"({"sets": [1]})", "f.json", "editor");
        CHECK(error_of([&] { (void)rooted["sets"].at(0).text(); }) ==
              "editor.sets[0]: must be a string (got 1)");
        // A value parsed elsewhere.
        const nlohmann::json raw = {{"k", {1, 2}}};
        CHECK(error_of([&] { (void)CheckedJson(raw, "f.json", "top")["k"].vec3(); }) ==
              "top.k: must be an [x, y, z] triple");
    }

    TEST_CASE("members: has, find, elements, members")
    {
        const CheckedJson j = CheckedJson::parse(R"({"x": 1, "list": [3, 4]})", "f.json");
        CHECK(j.has("x"));
        CHECK_FALSE(j.has("y"));
        CHECK_FALSE(j["x"].has("x")); // not an object: holds nothing
        CHECK(j.find("y") == std::nullopt);
        REQUIRE(j.find("x"));
        CHECK(j.find("x")->integer() == 1);
        CHECK(j.size() == 2);
        const std::vector<CheckedJson> list = j["list"].elements();
        REQUIRE(list.size() == 2);
        CHECK(list[1].path() == "list[1]");
        CHECK(list[1].integer() == 4);
        const auto members = j.members();
        REQUIRE(members.size() == 2);
        CHECK(members[0].first == "list");
        CHECK(members[0].second.path() == "list");
        CHECK(members[1].second.raw() == 1);
    }

    TEST_CASE("only_keys refuses a member not allowed, naming it")
    {
        const CheckedJson j =
            CheckedJson::parse(R"({"a": 1, "b": {"mu": 1, "muu": 2}, "c": {"x": 0}})", "f.json");
        CHECK_NOTHROW(j.only_keys({"a", "b", "c"}));
        CHECK_NOTHROW(j["b"].only_keys({"mu", "muu", "nu"}));
        CHECK(error_of([&] {
                  j["b"].only_keys({"mu", "nu"});
              }) == "b.muu: unknown key (allowed here: mu, nu)");
        CHECK(error_of([&] { j["c"].only_keys({}); }) ==
              "c.x: unknown key (this section takes none)");
        CHECK(error_of([&] { j["a"].only_keys({"a"}); }) == "a: must be an object");
    }

    TEST_CASE("a syntax error names the file, the line and the column")
    {
        try
        {
            (void)CheckedJson::parse("[1,\n 2,,]", "f.json");
            FAIL("parsed");
        }
        catch (const JsonSyntaxError& e)
        {
            CHECK(e.file() == "f.json");
            CHECK(e.line() == 2);
            CHECK(e.column() == 4);
            CHECK(std::string(e.what()) ==
                  "'f.json':2:4: not valid JSON: syntax error while parsing value - unexpected "
                  "','; expected '[', '{', or a literal");
        }
        // A number past a double's range: no place, the parser's words.
        CHECK_THROWS_WITH_AS((void)CheckedJson::parse("[1e400]", "f.json"),
                             "'f.json': not valid JSON: number overflow parsing '1e400'",
                             JsonSyntaxError);
        CHECK_THROWS_AS((void)CheckedJson::parse("", "f.json"), InvalidInputError);
    }

    TEST_CASE("the error is a RecipeError and an InvalidInputError, named by key and message")
    {
        const CheckedJson j = CheckedJson::parse("{}", "f.json", "soft");
        try
        {
            j.fail("is wrong");
        }
        catch (const RecipeError& e)
        {
            CHECK(e.key() == "soft");
            CHECK(e.message() == "is wrong");
        }
        CHECK_THROWS_AS(j.fail("x"), InvalidInputError);
        CHECK(std::string(JsonValueError("k", "why").what()) == "recipe: k: why");
    }
}
