// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_off.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/io.h"
#include "core/io/write_off.h"
#include "tests/allocation_counter.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

Mesh parse_off(const std::string& text, io::ReadReport* report = nullptr)
{
    return test::read_as(text, io::Format::Off, report);
}

std::string off_error(const std::string& text)
{
    return test::read_error(text, io::Format::Off);
}

io::MeshAttributes off_attributes(const std::string& text)
{
    io::ReadReport report;
    io::MeshAttributes attributes;
    io::read_off(text, "t.off", report, attributes);
    return attributes;
}

using OffColumns = std::vector<std::pair<std::string, std::vector<double>>>;

// The names and values of a table's properties.
OffColumns off_columns(const io::Element& table)
{
    OffColumns c;
    for (const io::Property& p : table.properties)
        c.emplace_back(p.name, p.values);
    return c;
}

std::vector<std::string> notes_of(const std::string& text)
{
    // read_off itself: read_mesh_data adds a note for meshes without faces.
    io::ReadReport report;
    io::MeshAttributes attributes;
    io::read_off(text, "t.off", report, attributes);
    return report.notes;
}

// A unit square split into a quad and a triangle: 5 vertices, 2 faces.
const std::string kVertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n";
const std::string kFaces = "4 0 1 2 3\n3 1 4 2\n";

Mesh square()
{
    return parse_off("OFF\n5 2 0\n" + kVertices + kFaces);
}

} // namespace

TEST_SUITE("ReadOff")
{
    TEST_CASE("vertices and polygons are read in file order")
    {
        io::ReadReport report;
        const Mesh m = parse_off("OFF\n5 2 0\n" + kVertices + kFaces, &report);
        CHECK(report.format == io::Format::Off);
        CHECK(report.encoding == io::Encoding::Ascii);
        CHECK(report.notes.empty());
        REQUIRE(m.vertex_count() == 5);
        REQUIRE(m.face_count() == 2);
        CHECK(m.position(4) == Vec3{2, 0, 0});
        CHECK(std::vector<Index>(m.face(0).begin(), m.face(0).end()) ==
              std::vector<Index>{0, 1, 2, 3});
        CHECK(std::vector<Index>(m.face(1).begin(), m.face(1).end()) ==
              std::vector<Index>{1, 4, 2});
    }

    TEST_CASE("coordinates are read exactly as strtod reads them")
    {
        const char* values[] = {"0.3",
                                "-2.7182818284590451",
                                "1.0000000000000002",
                                "4.9406564584124654e-324",
                                "1.7976931348623157e308",
                                "+0.30000000000000004",
                                "-0"};
        std::string text = "OFF\n" + std::to_string(std::size(values)) + " 0 0\n";
        for (const char* v : values)
            text += std::string(v) + " " + v + " " + v + "\n";
        const Mesh m = parse_off(text);
        for (size_t k = 0; k < std::size(values); ++k)
        {
            const double expected = std::strtod(values[k], nullptr);
            for (int c = 0; c < 3; ++c)
                CHECK(std::memcmp(&m.positions[3 * k + c], &expected, sizeof(double)) == 0);
        }
    }

    TEST_CASE("the counts may share the keyword's line and the edge count may be missing")
    {
        const Mesh m = square();
        CHECK(parse_off("OFF 5 2 0\n" + kVertices + kFaces) == m);
        CHECK(parse_off("OFF\n5 2\n" + kVertices + kFaces) == m);
        CHECK(parse_off("OFF 5 2\n" + kVertices + kFaces) == m);
    }

    TEST_CASE("comments and blank lines may appear anywhere")
    {
        const Mesh m = parse_off(
            "# exported by hand\n\nOFF # the keyword\n  # indented comment\n5 2 12 # counts\n"
            "0 0 0\n\n1 0 0 # vertex 1\n1 1 0\n#\n0 1 0\n2 0 0#glued\n"
            "# faces\n4 0 1 2 3 # quad\n\n3 1 4 2\n# trailing comment\n\n");
        CHECK(m == square());
    }

    TEST_CASE("CRLF, CR-only line endings, tabs and a byte-order mark are accepted")
    {
        const Mesh m = square();
        std::string crlf = "\xEF\xBB\xBFOFF\r\n5 2 0\r\n" + kVertices + kFaces;
        std::string cr = "OFF\r5\t2\t0\r" + kVertices + kFaces;
        for (size_t k = 0; k < crlf.size(); ++k)
            if (crlf[k] == '\n' && crlf[k - 1] != '\r')
                crlf.insert(k++, "\r");
        for (char& c : cr)
            if (c == '\n')
                c = '\r';
        CHECK(parse_off(crlf) == m);
        CHECK(parse_off(cr) == m);
    }

    TEST_CASE("COFF vertex colours are kept, as integers or fractions, alpha where given")
    {
        const std::string text =
            "COFF\n5 2 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n1 1 0 0 0 255 255\n"
            "0 1 0 0.5 0.5 0.5 1\n2 0 0 10 20 30\n" +
            kFaces;
        io::ReadReport report;
        CHECK(parse_off(text, &report) == square());
        CHECK(report.notes.empty());
        const io::MeshAttributes a = off_attributes(text);
        // A fraction makes them all fractions (double); the row without alpha is opaque.
        CHECK(off_columns(a.vertex) == OffColumns{{"red", {255, 0, 0, 0.5, 10}},
                                                  {"green", {0, 255, 0, 0.5, 20}},
                                                  {"blue", {0, 0, 255, 0.5, 30}},
                                                  {"alpha", {255, 255, 255, 1, 1}}});
        CHECK(a.vertex.properties[0].type == io::ValueType::Float64);
        CHECK(a.vertex.count == 5);
        // Integers only: uchar, and no alpha column when no row has one.
        const io::MeshAttributes ints = off_attributes("COFF\n2 0 0\n0 0 0 1 2 3\n1 0 0 4 5 6\n");
        CHECK(off_columns(ints.vertex) ==
              OffColumns{{"red", {1, 4}}, {"green", {2, 5}}, {"blue", {3, 6}}});
        CHECK(ints.vertex.properties[0].type == io::ValueType::UInt8);
        // Alpha on a later row only: the rows before and after are opaque.
        const io::MeshAttributes late =
            off_attributes("COFF\n3 0 0\n0 0 0 1 2 3\n1 0 0 4 5 6 7\n2 0 0 8 9 10\n");
        CHECK(off_columns(late.vertex).back() ==
              std::pair<std::string, std::vector<double>>{"alpha", {255, 7, 255}});
    }

    TEST_CASE("NOFF normals and every combination of ST, C and N are accepted")
    {
        CHECK(parse_off("NOFF\n5 2 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n"
                        "2 0 0 0 0 1\n" +
                        kFaces) == square());
        CHECK(notes_of("NOFF\n1 0 0\n0 0 0 0 0 1\n").empty());
        CHECK(off_columns(off_attributes("NOFF\n1 0 0\n0 0 0 0 0 1\n").vertex) ==
              OffColumns{{"nx", {0}}, {"ny", {0}}, {"nz", {1}}});
        // Normals, then colours, then texture coordinates, whatever the keyword's order.
        const OffColumns ncolour{{"nx", {0}},  {"ny", {0}},    {"nz", {1}},
                                 {"red", {1}}, {"green", {0}}, {"blue", {0}}};
        OffColumns with_alpha = ncolour;
        with_alpha.emplace_back("alpha", std::vector<double>{1});
        CHECK(off_columns(off_attributes("CNOFF\n1 0 0\n0 0 0 0 0 1 1 0 0 1\n").vertex) ==
              with_alpha);
        CHECK(off_columns(off_attributes("NCOFF\n1 0 0\n0 0 0 0 0 1 1 0 0\n").vertex) == ncolour);
        CHECK(off_columns(off_attributes("STOFF\n1 0 0\n0 0 0 0.5 0.25\n").vertex) ==
              OffColumns{{"texture_u", {0.5}}, {"texture_v", {0.25}}});
        OffColumns all = with_alpha;
        all.emplace_back("texture_u", std::vector<double>{0.5});
        all.emplace_back("texture_v", std::vector<double>{0.25});
        CHECK(off_columns(
                  off_attributes("STCNOFF\n1 0 0\n0 0 0 0 0 1 1 0 0 1 0.5 0.25\n").vertex) == all);
        CHECK(notes_of("STCNOFF\n1 0 0\n0 0 0 0 0 1 1 0 0 1 0.5 0.25\n").empty());
    }

    TEST_CASE("face colours are kept when every face gives the same kind, else noted")
    {
        const std::string rgba =
            "OFF\n5 2 0\n" + kVertices + "4 0 1 2 3 0 255 0 1\n3 1 4 2 255 0 0 0.5\n";
        io::ReadReport report;
        CHECK(parse_off(rgba, &report) == square());
        CHECK(report.notes.empty());
        CHECK(off_columns(off_attributes(rgba).face) ==
              OffColumns{
                  {"red", {0, 255}}, {"green", {255, 0}}, {"blue", {0, 0}}, {"alpha", {1, 0.5}}});
        CHECK(off_columns(
                  off_attributes("OFF\n5 2 0\n" + kVertices + "4 0 1 2 3 7\n3 1 4 2 2\n").face) ==
              OffColumns{{"colormap_index", {7, 2}}});
        // Some faces without a colour, or with another kind: one note naming the first.
        const std::string some = "OFF\n5 2 0\n" + kVertices + "4 0 1 2 3\n3 1 4 2 255 0 0 0.5\n";
        CHECK(notes_of(some) ==
              std::vector<std::string>{
                  "ignored the colours of 1 face (first at t.off:9:1): faces give different "
                  "numbers of colour values (kept when every face gives 1, 3 or 4)"});
        CHECK(off_attributes(some).face.properties.empty());
        CHECK(notes_of("OFF\n5 2 0\n" + kVertices + "4 0 1 2 3 7\n3 1 4 2 1 1 1\n") ==
              std::vector<std::string>{
                  "ignored the colours of 2 faces (first at t.off:8:1): faces give different "
                  "numbers of colour values (kept when every face gives 1, 3 or 4)"});
    }

    TEST_CASE("undeclared values after a vertex are ignored with a note")
    {
        CHECK(notes_of("OFF\n3 0 0\n0 0 0\n1 0 0 9 9 9\n0 1 0 9\n") ==
              std::vector<std::string>{
                  "ignored undeclared extra values on 2 vertex lines (first at t.off:4:1)"});
        // A colour may have an alpha value; one more value is undeclared.
        CHECK(notes_of("COFF\n1 0 0\n0 0 0 1 1 1 1\n").empty());
        CHECK(notes_of("COFF\n1 0 0\n0 0 0 1 1 1 1 1\n").size() == 1);
    }

    TEST_CASE("repeated consecutive indices are collapsed and reported")
    {
        io::ReadReport report;
        const Mesh m = parse_off("OFF\n5 2 0\n" + kVertices + "5 0 1 1 2 3\n4 1 4 2 1\n", &report);
        CHECK(m == square());
        CHECK(report.notes ==
              std::vector<std::string>{"collapsed 2 consecutive repeated vertex indices in 2 "
                                       "faces (first at t.off:8:1)"});
    }

    TEST_CASE("zero counts give an empty mesh and vertices without faces a point cloud")
    {
        const Mesh empty = parse_off("OFF\n0 0 0\n");
        CHECK(empty.vertex_count() == 0);
        CHECK(empty.face_count() == 0);
        io::ReadReport report;
        const Mesh cloud = parse_off("OFF\n2 0 0\n0 0 0\n1 2 3\n", &report);
        CHECK(cloud.vertex_count() == 2);
        CHECK(report.notes.back().find("point cloud") != std::string::npos);
    }

    TEST_CASE("malformed headers are refused with the place and the reason")
    {
        CHECK(off_error("") == "t.off: empty file");
        CHECK(off_error("# only a comment\n\n") ==
              "t.off: no OFF header (the file holds only comments and blank lines)");
        CHECK(off_error("PLY\n3 1 0\n") ==
              "t.off:1:1: expected an OFF header keyword ([ST][C][N]OFF), found 'PLY'");
        CHECK(off_error("off\n0 0 0\n") ==
              "t.off:1:1: expected an OFF header keyword ([ST][C][N]OFF), found 'off'");
        CHECK(off_error("CCOFF\n0 0 0\n") ==
              "t.off:1:1: expected an OFF header keyword ([ST][C][N]OFF), found 'CCOFF'");
        CHECK(off_error("  4OFF\n0 0 0\n") ==
              "t.off:1:3: '4OFF': 4-D vertices are not supported (MeshFair reads 3-D OFF)");
        CHECK(off_error("nOFF\n3\n0 0 0\n") ==
              "t.off:1:1: 'nOFF': vertices of any dimension "
              "are not supported (MeshFair reads 3-D OFF)");
        CHECK(off_error("OFF BINARY\n") ==
              "t.off:1:5: binary OFF ('OFF BINARY') is not supported; convert it to ASCII OFF");
        CHECK(off_error("OFF\n") ==
              "t.off:1:4: the file ends before the counts 'nv nf ne' that follow the header");
        CHECK(off_error("OFF\n# none\n5\n") == "t.off:3:1: missing face count");
        CHECK(off_error("OFF\n5 x 0\n") == "t.off:2:3: face count 'x' is not an integer");
        CHECK(off_error("OFF\n5.0 2 0\n") == "t.off:2:1: vertex count '5.0' is not an integer");
        CHECK(off_error("OFF\n-1 2 0\n") == "t.off:2:1: vertex count -1 is negative");
        CHECK(off_error("OFF\n0 -2 0\n") == "t.off:2:3: face count -2 is negative");
        CHECK(off_error("OFF\n0 0 -1\n") == "t.off:2:5: edge count -1 is negative");
        CHECK(off_error("OFF 0 0 0 0\n") ==
              "t.off:1:11: unexpected '0' after the counts 'nv nf ne'");
    }

    TEST_CASE("counts that cannot fit in the rest of the file fail fast without allocating")
    {
        const test::AllocationScope scope;
        CHECK(off_error("OFF\n1000000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
              "t.off:2:1: header declares 1000000000000 vertices and 1 face but only 26 bytes "
              "follow (a vertex line takes at least 6 bytes, a face line 8)");
        CHECK(off_error("OFF\n3 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
              "t.off:2:1: header declares 3 vertices and 2000000000 faces but only 26 bytes "
              "follow (a vertex line takes at least 6 bytes, a face line 8)");
        CHECK(off_error("OFF\n9223372036854775807 9223372036854775807\n") ==
              "t.off:2:1: header declares 9223372036854775807 vertices and 9223372036854775807 "
              "faces but only 0 bytes follow (a vertex line takes at least 6 bytes, a face "
              "line 8)");
        // One byte short of the smallest possible body; the last line has no newline.
        CHECK(off_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1") ==
              "t.off:2:1: header declares 3 vertices and 1 face but only 23 bytes follow (a "
              "vertex line takes at least 6 bytes, a face line 8)");
        CHECK(parse_off("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2").face_count() == 1);
        // Nothing reserved for what the header promises: no request over 64 KiB.
        CHECK(scope.largest() <= 65536);
    }

    TEST_CASE("counts that promise more than the file holds name where it ends")
    {
        CHECK(off_error("OFF\n8 0 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 2\n# end\n1 1 1 1 1 1 1\n"
                        "1 1\n") == "t.off:10:1: vertex has no z coordinate");
        CHECK(off_error("OFF\n8 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 2 2\n# 3 more lines\n"
                        "# to make room\n# for the counts\n") ==
              "t.off:10:17: expected 8 vertices, the file ends after 5");
        CHECK(off_error("OFF\n3 4 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n# short\n# file\n") ==
              "t.off:9:7: expected 4 faces, the file ends after 2");
    }

    TEST_CASE("data after the last face is refused")
    {
        CHECK(off_error("OFF\n5 2 0\n" + kVertices + kFaces + "\n# ok\n3 0 1 2\n") ==
              "t.off:12:1: unexpected data after the last face (the header declares 5 "
              "vertices and 2 faces)");
        CHECK(off_error("OFF\n1 0 0\n0 0 0\n1 1 1\n") ==
              "t.off:4:1: unexpected data after the last vertex (the header declares 1 vertex "
              "and 0 faces)");
        CHECK(off_error("OFF 0 0\n  x\n") ==
              "t.off:2:3: unexpected data after the counts (the header declares 0 vertices and "
              "0 faces)");
    }

    TEST_CASE("malformed vertices are refused with line and column")
    {
        // The padding comment keeps the short lines from failing the size check first.
        const std::string head = "OFF\n3 0 0\n0 0 0\n";
        const std::string tail = "0 1 0\n# padding\n";
        CHECK(off_error(head + "1 nan 0\n" + tail) ==
              "t.off:4:3: y coordinate 'nan' is not finite");
        CHECK(off_error(head + "1 0 -inf\n" + tail) ==
              "t.off:4:5: z coordinate '-inf' is not finite");
        CHECK(off_error(head + "1e400 0 0\n" + tail) ==
              "t.off:4:1: x coordinate '1e400' is out of the range of a double");
        CHECK(off_error(head + "abc 0 0\n" + tail) ==
              "t.off:4:1: x coordinate 'abc' is not a number");
        CHECK(off_error(head + "1 0 0 red\n" + tail) ==
              "t.off:4:7: vertex value 'red' is not a number");
        CHECK(off_error(head + "1 0\n" + tail) == "t.off:4:1: vertex has no z coordinate");
        CHECK(off_error("NOFF\n1 0 0\n0 0 0 0 1\n") ==
              "t.off:3:1: vertex has 5 values but NOFF needs at least 6 (x y z nx ny nz)");
        CHECK(off_error("STCOFF\n1 0 0\n0 0 0 1 1 1 0\n") ==
              "t.off:3:1: vertex has 7 values but STCOFF needs at least 8 (x y z r g b s t)");
        CHECK(off_error(std::string("OFF\n1 0 0\n0 \0 0\n", 16)) ==
              "t.off:3:3: NUL byte in a text file");
    }

    TEST_CASE("malformed faces are refused with line and column")
    {
        const std::string head = "OFF\n5 1 0\n" + kVertices;
        const std::string tail = "# padding\n";
        CHECK(off_error(head + "0\n" + tail) ==
              "t.off:8:1: face has 0 vertices (a face needs at least 3)");
        CHECK(off_error(head + "1 0\n" + tail) ==
              "t.off:8:1: face has 1 vertex (a face needs at least 3)");
        CHECK(off_error(head + " 2 0 1\n" + tail) ==
              "t.off:8:2: face has 2 vertices (a face needs at least 3)");
        CHECK(off_error(head + "-3 0 1 2\n" + tail) ==
              "t.off:8:1: face vertex count -3 is negative");
        CHECK(off_error(head + "3.0 0 1 2\n" + tail) ==
              "t.off:8:1: face vertex count '3.0' is not an integer");
        CHECK(off_error(head + "4 0 1 2\n" + tail) ==
              "t.off:8:1: face declares 4 vertices but lists 3");
        CHECK(off_error(head + "1000000000000 0 1 2\n" + tail) ==
              "t.off:8:1: face declares 1000000000000 vertices but lists 3");
        CHECK(off_error(head + "3 0 1 5\n" + tail) ==
              "t.off:8:7: vertex index 5 is out of range (the file has 5 vertices, numbered "
              "from 0)");
        CHECK(off_error(head + "3 0 -1 2\n" + tail) ==
              "t.off:8:5: vertex index -1 is negative (OFF indices start at 0)");
        CHECK(off_error(head + "3 0 1 2.5\n" + tail) ==
              "t.off:8:7: vertex index '2.5' is not an integer");
        CHECK(off_error(head + "3 0 1 2 red\n" + tail) ==
              "t.off:8:9: face colour value 'red' is not a number");
        CHECK(off_error(head + "3 0 1 1\n" + tail) ==
              "t.off:8:1: face has 2 distinct vertices (a face needs at least 3)");
        CHECK(off_error(head + "4 0 1 0 2\n" + tail) ==
              "t.off:8:1: face uses vertex 0 at two corners that are not adjacent");
    }

    TEST_CASE("a file that ends in the middle of a line is read like one that does not")
    {
        CHECK(parse_off("OFF\n5 2 0\n" + kVertices + "4 0 1 2 3\n3 1 4 2") == square());
    }
}

TEST_SUITE("WriteOff")
{
    TEST_CASE("writes keyword, counts, vertices and faces in shortest round-trip form")
    {
        Mesh m;
        m.add_vertex(0, 0.1, -0.0);
        m.add_vertex(1e300, -2.5, 1.0 / 3.0);
        m.add_vertex(5e-324, 3, 0);
        m.add_vertex(1, 1, 1);
        const std::vector<Index> quad{0, 1, 2, 3}, tri{3, 2, 1};
        m.add_face(quad);
        m.add_face(tri);
        std::string out;
        out = io::write_mesh_data(m, io::Format::Off);
        CHECK(out ==
              "OFF\n4 2 0\n0 0.1 -0\n1e+300 -2.5 0.3333333333333333\n5e-324 3 0\n1 1 1\n"
              "4 0 1 2 3\n3 3 2 1\n");
        const Mesh back = parse_off(out);
        CHECK(back == m);
        CHECK(std::signbit(back.positions[2]));
    }

    TEST_CASE("mixed polygons with 17-digit coordinates round-trip bit-exactly")
    {
        Mesh m = test::mixed_polygons();
        test::perturb(m, 0.37, 11);
        const std::string data = io::write_mesh_data(m, io::Format::Off);
        const Mesh back = parse_off(data);
        REQUIRE(back.positions.size() == m.positions.size());
        CHECK(std::memcmp(back.positions.data(), m.positions.data(),
                          m.positions.size() * sizeof(double)) == 0);
        CHECK(back.face_offsets == m.face_offsets);
        CHECK(back.face_vertices == m.face_vertices);
        // Writing the result again gives the same bytes.
        CHECK(io::write_mesh_data(back, io::Format::Off) == data);
    }

    TEST_CASE("a point cloud and an empty mesh round-trip")
    {
        Mesh cloud;
        cloud.add_vertex(1, 2, 3);
        CHECK(parse_off(io::write_mesh_data(cloud, io::Format::Off)) == cloud);
        CHECK(io::write_mesh_data(Mesh{}, io::Format::Off) == "OFF\n0 0 0\n");
        CHECK(parse_off("OFF\n0 0 0\n") == Mesh{});
    }

    TEST_CASE("a file written to disk reads back the same")
    {
        Mesh m = test::quad_torus(8, 5, 2.0, 0.5);
        const auto path = (test::temp_dir() / "torus.off").string();
        io::write_mesh(m, path);
        CHECK(io::read_mesh(path) == m);
    }
}
