// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_obj.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>

#include "core/errors.h"
#include "core/io/io.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

Mesh parse_obj(const std::string& text, io::ReadReport* report = nullptr)
{
    return test::read_as(text, io::Format::Obj, report);
}

std::string obj_error(const std::string& text)
{
    return test::read_error(text, io::Format::Obj);
}

} // namespace

TEST_SUITE("ReadObj")
{
    TEST_CASE("polygons are kept and groups are concatenated in file order")
    {
        const Mesh m = parse_obj(
            "# comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nvt 0 0\nvn 0 0 1\nvn 0 0 1\n"
            "o first\nf 1 2 3 4\ng second\nf 2 5 3\no third\nf 1/1/1 2//2 -3\n");
        REQUIRE(m.face_count() == 3);
        CHECK(m.face_size(0) == 4);
        CHECK(m.face(1)[1] == 4);
        CHECK(m.face(2)[2] == 2); // -3 with five vertices defined
    }

    TEST_CASE("coordinates are read exactly as strtod reads them")
    {
        const char* values[] = {"0.3",
                                "0.1",
                                "-2.7182818284590451",
                                "1.0000000000000002",
                                "4.9406564584124654e-324",
                                "1.7976931348623157e308",
                                "0.30000000000000004",
                                "123456789.12345678"};
        std::string text;
        for (const char* v : values)
            text += std::string("v ") + v + " " + v + (v[0] == '-' ? " " : " +") + v + "\n";
        const Mesh m = parse_obj(text);
        for (size_t k = 0; k < std::size(values); ++k)
        {
            const double expected = std::strtod(values[k], nullptr);
            CHECK(std::memcmp(&m.positions[3 * k], &expected, sizeof(double)) == 0);
        }
    }

    TEST_CASE("CRLF, CR-only line endings and a byte-order mark are accepted")
    {
        const Mesh a = parse_obj("\xEF\xBB\xBFv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
        const Mesh b = parse_obj("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
        CHECK(a == b);
        CHECK(a.face_count() == 1);
    }

    TEST_CASE("repeated consecutive indices are collapsed and reported")
    {
        io::ReadReport report;
        const Mesh m =
            parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 2 3\nf 1 3 4 1\n", &report);
        CHECK(m.face_size(0) == 3);
        CHECK(m.face_size(1) == 3);
        REQUIRE(report.notes.size() == 1);
        CHECK(report.notes[0].find("collapsed 2") != std::string::npos);
        CHECK(report.notes[0].find("t.obj:5") != std::string::npos);
    }

    TEST_CASE("a file without faces is a point cloud")
    {
        io::ReadReport report;
        const Mesh m = parse_obj("v 0 0 0\nv 1 2 3\n", &report);
        CHECK(m.vertex_count() == 2);
        CHECK(m.face_count() == 0);
        CHECK(report.notes.back().find("point cloud") != std::string::npos);
    }

    TEST_CASE("every malformed input names the line and column")
    {
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nf 1 2 0\n") ==
              "t.obj:3:7: vertex index 0 (OBJ indices start at 1, or count back from -1)");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n") ==
              "t.obj:4:7: vertex index 4 is past the last vertex (the file defines 3)");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nf 1 2 -3\n") ==
              "t.obj:3:7: vertex index -3 reaches before the first vertex (2 vertices are "
              "defined before this line)");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 99999999999999999999\n") ==
              "t.obj:4:7: vertex index '99999999999999999999' is out of range");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3x\n") ==
              "t.obj:4:7: vertex index '3x' is not an integer");
        CHECK(obj_error("v 0 0 0\nv 1 0\n") == "t.obj:2:1: vertex has no z coordinate");
        CHECK(obj_error("v 0 0 0\nv a b c\n") == "t.obj:2:3: x coordinate 'a' is not a number");
        CHECK(obj_error("v 0 nan 0\n") == "t.obj:1:5: y coordinate 'nan' is not finite");
        CHECK(obj_error("v 0 0 inf\n") == "t.obj:1:7: z coordinate 'inf' is not finite");
        CHECK(obj_error("v 1e400 0 0\n") ==
              "t.obj:1:3: x coordinate '1e400' is out of the range of a double");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nf 1 2\n") ==
              "t.obj:3:1: face has 2 vertices (a face needs at least 3)");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 2\n") ==
              "t.obj:4:1: face has 2 distinct vertices (a face needs at least 3)");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 2 2\nf 1 2 1 3\n") ==
              "t.obj:5:1: face uses vertex 0 at two corners that are not adjacent");
        CHECK(obj_error(std::string("v 0 0 0\nv 1 \0 0\n", 17)) ==
              "t.obj:2:5: NUL byte in a text file");
        CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 /2 3\n") ==
              "t.obj:4:5: face corner '/2' has no vertex index");
    }

    TEST_CASE("a zero-byte file is refused, a file without vertices is an empty mesh")
    {
        CHECK(obj_error("") == "t.obj: empty file");
        io::ReadReport report;
        const Mesh m = parse_obj("# exported nothing\n", &report);
        CHECK(m.vertex_count() == 0);
        CHECK(m.face_count() == 0);
        CHECK(report.notes ==
              std::vector<std::string>{"no vertices: the file holds an empty mesh"});
    }

    TEST_CASE("the bundled bunny loads with the documented counts")
    {
        const Mesh m = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        CHECK(m.vertex_count() == 34835);
        CHECK(m.face_count() == 69666);
    }
}
