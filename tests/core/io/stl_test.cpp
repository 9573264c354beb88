// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_stl.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/io.h"
#include "core/io/write_stl.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

Mesh parse_stl(const std::string& data, io::ReadReport* report = nullptr)
{
    return test::read_as(data, io::Format::Stl, report);
}

std::string stl_error(const std::string& data)
{
    return test::read_error(data, io::Format::Stl);
}

std::vector<Index> corners(const Mesh& m, Index f)
{
    return {m.face(f).begin(), m.face(f).end()};
}

// Little-endian binary STL assembled byte by byte.
struct BinaryStl
{
    std::string bytes;

    explicit BinaryStl(std::uint32_t count, std::string header = "binary test")
    {
        header.resize(80, ' ');
        bytes = header;
        append(count);
    }
    template <typename T>
    void append(T value)
    {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        if constexpr (std::endian::native == std::endian::big)
            std::reverse(raw, raw + sizeof(T));
        bytes.append(raw, sizeof(T));
    }
    //! One triangle: the normal 0 0 1, then three corners.
    BinaryStl& triangle(const std::array<float, 9>& p, std::uint16_t attribute = 0)
    {
        for (float n : {0.0f, 0.0f, 1.0f})
            append(n);
        for (float v : p)
            append(v);
        append(attribute);
        return *this;
    }
};

// Two triangles sharing the edge (1 0 0)-(0 1 0).
std::string two_triangles_stl(std::string header = "binary test")
{
    return BinaryStl(2, std::move(header))
        .triangle({0, 0, 0, 1, 0, 0, 0, 1, 0})
        .triangle({1, 0, 0, 1, 1, 0, 0, 1, 0})
        .bytes;
}

std::string ascii_facet(const std::string& corners)
{
    return "facet normal 0 0 1\n outer loop\n" + corners + " endloop\nendfacet\n";
}

const std::string kAsciiTwoTriangles =
    "solid two\n" + ascii_facet("vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n") +
    ascii_facet("vertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n") + "endsolid two\n";

// `mesh` with its vertices renumbered in order of first use by the faces, as an STL
// reader numbers them; vertices no face uses are dropped.
Mesh in_order_of_first_use(const Mesh& mesh)
{
    Mesh out;
    std::vector<Index> renumbered(static_cast<size_t>(mesh.vertex_count()), kInvalidIndex);
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        std::vector<Index> face;
        for (Index v : mesh.face(f))
        {
            Index& r = renumbered[static_cast<size_t>(v)];
            if (r == kInvalidIndex)
            {
                const Vec3 p = mesh.position(v);
                r = out.add_vertex(p[0], p[1], p[2]);
            }
            face.push_back(r);
        }
        out.add_face(face);
    }
    return out;
}

// `mesh` with every polygon split into the fan of its first corner.
Mesh fan_triangulated(const Mesh& mesh)
{
    Mesh out;
    out.positions = mesh.positions;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const auto face = mesh.face(f);
        for (size_t k = 1; k + 1 < face.size(); ++k)
        {
            const std::vector<Index> tri{face[0], face[k], face[k + 1]};
            out.add_face(tri);
        }
    }
    return out;
}

template <typename T>
T read_le(const std::string& bytes, size_t offset)
{
    char raw[sizeof(T)];
    std::memcpy(raw, bytes.data() + offset, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
        std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
}

} // namespace

TEST_SUITE("ReadStl")
{
    TEST_CASE("binary triangles are welded in order of first appearance")
    {
        io::ReadReport report;
        const Mesh m = parse_stl(two_triangles_stl(), &report);
        CHECK(report.format == io::Format::Stl);
        CHECK(report.encoding == io::Encoding::BinaryLittleEndian);
        REQUIRE(m.vertex_count() == 4);
        CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
        REQUIRE(m.face_count() == 2);
        CHECK(corners(m, 0) == std::vector<Index>{0, 1, 2});
        CHECK(corners(m, 1) == std::vector<Index>{1, 3, 2});
        CHECK(report.notes ==
              std::vector<std::string>{"welded 6 corners into 4 vertices by exact position"});
    }

    TEST_CASE("a binary file whose header starts with 'solid' is still binary")
    {
        const Mesh expected = parse_stl(two_triangles_stl());
        io::ReadReport report;
        CHECK(parse_stl(two_triangles_stl("solid exported by some CAD tool"), &report) == expected);
        CHECK(report.encoding == io::Encoding::BinaryLittleEndian);
        // Even with a text-like body after the header.
        CHECK(parse_stl(two_triangles_stl("\n  solid x\nfacet normal 0 0 1\n")) == expected);
    }

    TEST_CASE("ASCII facets are welded like binary ones")
    {
        io::ReadReport report;
        const Mesh m = parse_stl(kAsciiTwoTriangles, &report);
        CHECK(report.encoding == io::Encoding::Ascii);
        CHECK(m == parse_stl(two_triangles_stl()));
        CHECK(report.notes ==
              std::vector<std::string>{"welded 6 corners into 4 vertices by exact position"});
    }

    TEST_CASE("-0.0 and +0.0 weld into one vertex that keeps the first value")
    {
        const Mesh a = parse_stl(BinaryStl(2)
                                     .triangle({-0.0f, 0, 0, 1, 0, 0, 0, 1, 0})
                                     .triangle({1, 0, 0, 0, -0.0f, 0, 0, 0, 1})
                                     .bytes);
        CHECK(a.vertex_count() == 4);
        CHECK(corners(a, 1) == std::vector<Index>{1, 0, 3});
        CHECK(std::signbit(a.positions[0]));
        const Mesh b =
            parse_stl("solid\n" + ascii_facet("vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n") +
                      ascii_facet("vertex -0 -0 -0\nvertex 0 1 0\nvertex 0 0 1\n") + "endsolid\n");
        CHECK(b.vertex_count() == 4);
        CHECK(corners(b, 1) == std::vector<Index>{0, 2, 3});
        CHECK(!std::signbit(b.positions[0]));
    }

    TEST_CASE("positions that differ in the last bit stay apart")
    {
        const Mesh m =
            parse_stl("solid\n" + ascii_facet("vertex 0.1 0 0\nvertex 1 0 0\nvertex 0 1 0\n") +
                      ascii_facet("vertex 0.10000000000000002 0 0\nvertex 0 1 0\n"
                                  "vertex 1 0 0\n") +
                      "endsolid\n");
        CHECK(m.vertex_count() == 4);
        CHECK(m.positions[9] == 0.10000000000000002);
    }

    TEST_CASE("a facet with a fourth vertex is refused at that vertex's line")
    {
        // Facet 1's loop has four corners: the error names its fourth 'vertex' keyword.
        const std::string text = "solid quad\n" +
                                 ascii_facet("vertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n") +
                                 ascii_facet(
                                     "vertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
                                     "  vertex 0 1 0\nvertex 0 1 1\n") +
                                 "endsolid quad\n";
        // Lines 1 (solid), 2-8 (facet 0), 9-10 (facet 1's header), 11-13, then the fourth.
        CHECK(stl_error(text) ==
              "t.stl:14:3: facet 1 has more than 3 vertices (an STL facet is a triangle)");
    }

    TEST_CASE("several solids are concatenated in file order")
    {
        io::ReadReport report;
        const std::string second = "solid b\n" +
                                   ascii_facet("vertex 5 5 5\nvertex 1 0 0\nvertex 6 5 5\n") +
                                   "endsolid b\n";
        const Mesh m = parse_stl(kAsciiTwoTriangles + second, &report);
        REQUIRE(m.face_count() == 3);
        CHECK(m.vertex_count() == 6);
        CHECK(corners(m, 2) == std::vector<Index>{4, 1, 5});
        CHECK(report.notes ==
              std::vector<std::string>{"welded 9 corners into 6 vertices by exact position",
                                       "concatenated 2 solids in file order"});
    }

    TEST_CASE("keywords in any case, tokens across lines, CRLF and nan normals are accepted")
    {
        const Mesh m = parse_stl(
            "\r\n  SOLID Part 1 (mm)\r\nFacet Normal nan -nan NaN\r\nOUTER\r\nloop vertex 0\r\n0 0 "
            "vertex 1 0 0 vertex 0 1 0 ENDLOOP ENDFACET\r\n"
            "facet normal 0 0 1 outer loop\r\n\tvertex 1 0 0\r\n\tvertex 1 1 0\r\n"
            "\tvertex 0 1 0\r\nendloop endfacet EndSolid Part 1 (mm)\r\n\r\n");
        CHECK(m == parse_stl(two_triangles_stl()));
        CHECK(parse_stl("\xEF\xBB\xBF" + kAsciiTwoTriangles) == m);
    }

    TEST_CASE("a solid without facets, or binary STL without triangles, is an empty mesh")
    {
        io::ReadReport report;
        CHECK(parse_stl(BinaryStl(0).bytes, &report) == Mesh{});
        CHECK(report.notes ==
              std::vector<std::string>{"no vertices: the file holds an empty mesh"});
        CHECK(parse_stl("solid empty\nendsolid empty\n", &report) == Mesh{});
        CHECK(report.notes ==
              std::vector<std::string>{"no vertices: the file holds an empty mesh"});
    }

    TEST_CASE("non-zero attribute bytes are kept as the face property stl_attribute")
    {
        io::ReadReport report;
        const std::string coloured = BinaryStl(2)
                                         .triangle({0, 0, 0, 1, 0, 0, 0, 1, 0}, 0x7C00)
                                         .triangle({1, 0, 0, 1, 1, 0, 0, 1, 0})
                                         .bytes;
        parse_stl(coloured, &report);
        CHECK(report.notes == std::vector<std::string>{"welded 6 corners into 4 vertices by exact "
                                                       "position"});
        io::MeshAttributes a;
        io::read_mesh_data(coloured, io::Format::Stl, "t.stl", nullptr, &a);
        CHECK(a.face.count == 2);
        CHECK(a.face.properties == std::vector<io::Property>{{"stl_attribute",
                                                              io::ValueType::UInt16,
                                                              false,
                                                              io::ValueType::UInt8,
                                                              {0x7C00, 0},
                                                              {}}});
        // Written back into the attribute bytes of a binary STL, on every triangle of a face.
        const std::string again = io::write_mesh_data(
            io::read_mesh_data(coloured, io::Format::Stl, "t.stl"), io::Format::Stl, {}, &a);
        CHECK(again.substr(84 + 48, 2) == std::string("\x00\x7C", 2));
        CHECK(again.substr(84 + 50 + 48, 2) == std::string("\0\0", 2));
        // All zeros: nothing kept.
        io::read_mesh_data(BinaryStl(1).triangle({0, 0, 0, 1, 0, 0, 0, 1, 0}).bytes,
                           io::Format::Stl, "t.stl", nullptr, &a);
        CHECK(a.empty());
    }

    TEST_CASE("ASCII coordinates are read exactly as strtod reads them")
    {
        const Mesh m = parse_stl("solid\n" +
                                 ascii_facet("vertex 0.3 -2.7182818284590451 1.0000000000000002\n"
                                             "vertex 4.9406564584124654e-324 1e308 +7\n"
                                             "vertex 0.30000000000000004 0 0\n") +
                                 "endsolid\n");
        const char* values[] = {"0.3",
                                "-2.7182818284590451",
                                "1.0000000000000002",
                                "4.9406564584124654e-324",
                                "1e308",
                                "7",
                                "0.30000000000000004",
                                "0",
                                "0"};
        for (size_t k = 0; k < std::size(values); ++k)
        {
            const double expected = std::strtod(values[k], nullptr);
            CHECK(std::memcmp(&m.positions[k], &expected, sizeof(double)) == 0);
        }
    }

    TEST_CASE("files that are neither ASCII nor well-sized binary STL are refused")
    {
        CHECK(stl_error("") == "t.stl: empty file");
        CHECK(stl_error("\n \t\n") ==
              "t.stl: file too short for a binary STL header (4 bytes, "
              "needs 84); the file does not start with 'solid', so it is "
              "not ASCII STL");
        CHECK(stl_error("facet normal 0 0 1\n") ==
              "t.stl: file too short for a binary STL header (19 bytes, needs 84); the file does "
              "not start with 'solid', so it is not ASCII STL");
        std::string truncated = two_triangles_stl();
        truncated.pop_back();
        CHECK(stl_error(truncated) ==
              "t.stl: byte 80 (header, property triangle count): binary STL header declares 2 "
              "triangles (184 bytes) but the file has 183 bytes; the file does not start with "
              "'solid', so it is not ASCII STL");
        CHECK(stl_error(two_triangles_stl() + "x") ==
              "t.stl: byte 80 (header, property triangle count): binary STL header declares 2 "
              "triangles (184 bytes) but the file has 185 bytes; the file does not start with "
              "'solid', so it is not ASCII STL");
        // A lying count must not make the reader allocate for it.
        CHECK(stl_error(BinaryStl(4000000000u).bytes) ==
              "t.stl: byte 80 (header, property triangle count): binary STL header declares "
              "4000000000 triangles (200000000084 bytes) but the file has 84 bytes; the file "
              "does not start with 'solid', so it is not ASCII STL");
        // A truncated binary file whose header starts with "solid" is not taken for text.
        std::string solid = two_triangles_stl("solid part");
        solid.resize(150);
        CHECK(stl_error(solid) ==
              "t.stl: byte 80 (header, property triangle count): binary STL header declares 2 "
              "triangles (184 bytes) but the file has 150 bytes; the file holds NUL bytes, so "
              "it is not ASCII STL");
    }

    TEST_CASE("a non-finite binary coordinate names the triangle, property and byte")
    {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        const float inf = std::numeric_limits<float>::infinity();
        CHECK(stl_error(BinaryStl(2)
                            .triangle({0, 0, 0, 1, 0, 0, 0, 1, 0})
                            .triangle({1, 0, 0, 1, 1, 0, 0, nan, 0})
                            .bytes) ==
              "t.stl: byte 174 (triangle 1, property vertex 2 y): coordinate is NaN");
        CHECK(stl_error(BinaryStl(1).triangle({-inf, 0, 0, 1, 0, 0, 0, 1, 0}).bytes) ==
              "t.stl: byte 96 (triangle 0, property vertex 0 x): coordinate is infinite");
        // The normal is ignored, whatever it holds.
        BinaryStl nan_normal(1);
        for (int k = 0; k < 3; ++k)
            nan_normal.append(nan);
        for (float v : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f})
            nan_normal.append(v);
        nan_normal.append(std::uint16_t{0});
        CHECK(parse_stl(nan_normal.bytes).face_count() == 1);
    }

    TEST_CASE("degenerate facets are refused, not dropped")
    {
        CHECK(stl_error(BinaryStl(2)
                            .triangle({0, 0, 0, 1, 0, 0, 0, 1, 0})
                            .triangle({1, 0, 0, 1, 0, 0, 0, 1, 0})
                            .bytes) ==
              "t.stl: byte 134 (triangle 1): face has 2 distinct vertices (a face needs at "
              "least 3) once equal positions are welded");
        CHECK(stl_error("solid\n" + ascii_facet("vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n") +
                        ascii_facet("vertex 0 0 0\nvertex -0 0 0\nvertex 0 0 0\n") +
                        "endsolid\n") ==
              "t.stl:9:1: facet 1: face has 1 distinct vertex (a face needs at least 3) once "
              "equal positions are welded");
        // A repeated corner leaves a triangle two vertices (no polygon to collapse it in).
        CHECK(stl_error("solid\n" + ascii_facet("vertex 0 0 0\nvertex 1 0 0\nvertex 1 0 0\n") +
                        "endsolid\n") ==
              "t.stl:2:1: facet 0: face has 2 distinct vertices (a face needs at least 3) once "
              "equal positions are welded");
    }

    TEST_CASE("malformed ASCII STL names the line, the column and what was expected")
    {
        const std::string facet = ascii_facet("vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n");
        CHECK(stl_error("solid x\n" + facet) == "t.stl:8:9: file ends inside solid (no endsolid)");
        CHECK(stl_error("solid x\n") == "t.stl:1:8: file ends inside solid (no endsolid)");
        CHECK(stl_error("solid x\nfacet normal 0 0 1\n outer loop\nvertex 0 0 0\n") ==
              "t.stl:4:13: file ends inside facet 0 (no endfacet)");
        CHECK(stl_error("solid x\nfacet normal 0 0 1\nvertex 0 0 0\n") ==
              "t.stl:3:1: expected 'outer', found 'vertex'");
        CHECK(stl_error("solid x\nfacet 0 0 1\n") == "t.stl:2:7: expected 'normal', found '0'");
        CHECK(stl_error("solid x\n" + facet + "vertex 1 1 1\n") ==
              "t.stl:9:1: expected 'facet' or 'endsolid', found 'vertex'");
        CHECK(stl_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendfacet\n") ==
              "t.stl:5:1: expected 'vertex' or 'endloop', found 'endfacet'");
        CHECK(stl_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                        "endloop\nendfacet\nendsolid x\n") ==
              "t.stl:6:1: facet 0 has 2 vertices (an STL facet is a triangle)");
        CHECK(stl_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                        "vertex 0 1 0\nendloop\nendloop\n") ==
              "t.stl:8:1: expected 'endfacet', found 'endloop'");
        CHECK(stl_error("solid x\n" + facet + "endsolid x\nfacet normal 0 0 1\n") ==
              "t.stl:10:1: expected 'solid' or the end of the file, found 'facet'");
        CHECK(stl_error("solid x\nfacet normal 0 0 up\n") ==
              "t.stl:2:18: normal component 'up' is not a number");
    }

    TEST_CASE("bad ASCII coordinates are refused with line and column")
    {
        const auto with_vertex = [](const std::string& v) {
            return stl_error("solid\n" + ascii_facet("vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n") +
                             "facet normal 0 0 1\nouter loop\nvertex 0 0 0\n" + v +
                             "\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
        };
        CHECK(with_vertex("vertex 1 0 abc") == "t.stl:12:12: z coordinate 'abc' is not a number");
        CHECK(with_vertex("vertex 1 nan 0") == "t.stl:12:10: y coordinate 'nan' is not finite");
        CHECK(with_vertex("vertex inf 0 0") == "t.stl:12:8: x coordinate 'inf' is not finite");
        CHECK(with_vertex("vertex 1e400 0 0") ==
              "t.stl:12:8: x coordinate '1e400' is out of the range of a double");
        CHECK(with_vertex("vertex 1 0") == "t.stl:13:1: z coordinate 'vertex' is not a number");
        CHECK(with_vertex(std::string("vertex 1 0 \0", 12)) ==
              "t.stl:12:12: NUL byte in a text file");
    }
}

TEST_SUITE("WriteStl")
{
    TEST_CASE("ASCII STL of a triangle mesh round-trips positions and faces exactly")
    {
        Mesh m = test::icosphere(1);
        test::perturb(m, 0.01, 3);
        std::string out;
        out = io::write_mesh_data(m, io::Format::Stl, {io::Encoding::Ascii});
        CHECK(out.starts_with("solid meshfair\n  facet normal "));
        CHECK(out.ends_with("    endloop\n  endfacet\nendsolid meshfair\n"));
        const Mesh back = parse_stl(out);
        const Mesh expected = in_order_of_first_use(m);
        CHECK(back.vertex_count() == m.vertex_count());
        REQUIRE(back.positions.size() == expected.positions.size());
        CHECK(std::memcmp(back.positions.data(), expected.positions.data(),
                          expected.positions.size() * sizeof(double)) == 0);
        CHECK(back.face_offsets == expected.face_offsets);
        CHECK(back.face_vertices == expected.face_vertices);
    }

    TEST_CASE("binary STL round-trips float-representable coordinates exactly")
    {
        Mesh m = test::icosphere(2);
        test::perturb(m, 0.01, 5);
        for (double& x : m.positions)
            x = static_cast<float>(x);
        for (const io::Encoding e :
             {io::Encoding::BinaryLittleEndian, io::Encoding::BinaryBigEndian})
        {
            std::string out;
            out = io::write_mesh_data(m, io::Format::Stl, {e});
            CHECK(out.size() == 84 + 50 * static_cast<size_t>(m.face_count()));
            CHECK(parse_stl(out) == in_order_of_first_use(m));
        }
    }

    TEST_CASE("polygons come back as the fan of their first corner")
    {
        Mesh m = test::mixed_polygons();
        test::perturb(m, 0.1, 9);
        const std::vector<Index> hexagon_like{0, 1, 2, 6, 10, 9, 8, 4};
        m.add_face(hexagon_like);
        for (const io::Encoding e : {io::Encoding::Ascii, io::Encoding::BinaryLittleEndian})
        {
            Mesh input = m;
            if (e != io::Encoding::Ascii)
                for (double& x : input.positions)
                    x = static_cast<float>(x);
            std::string out;
            out = io::write_mesh_data(input, io::Format::Stl, {e});
            CHECK(parse_stl(out) == in_order_of_first_use(fan_triangulated(input)));
        }
    }

    TEST_CASE("binary layout: header without 'solid', count, unit normals, zero attributes")
    {
        const Mesh m = test::quad_cube();
        std::string out;
        out = io::write_mesh_data(m, io::Format::Stl, {io::Encoding::BinaryLittleEndian});
        REQUIRE(out.size() == 84 + 12 * 50);
        CHECK(out.substr(0, 80) == "MeshFair binary STL" + std::string(61, ' '));
        CHECK(read_le<std::uint32_t>(out, 80) == 12);
        // The first face {0, 3, 2, 1} of the cube is its bottom, facing -z.
        CHECK(read_le<float>(out, 84) == 0.0f);
        CHECK(read_le<float>(out, 88) == 0.0f);
        CHECK(read_le<float>(out, 92) == -1.0f);
        CHECK(read_le<float>(out, 96 + 12) == 0.0f); // corner 1 = vertex 3 = (0 1 0)
        CHECK(read_le<float>(out, 96 + 16) == 1.0f);
        for (size_t t = 0; t < 12; ++t)
            CHECK(read_le<std::uint16_t>(out, 84 + 50 * t + 48) == 0);
    }

    TEST_CASE("facet normals are unit vectors, or zero for a triangle without area")
    {
        Mesh m;
        m.add_vertex(0, 0, 0);
        m.add_vertex(3, 0, 0);
        m.add_vertex(0, 0, 2);
        m.add_vertex(6, 0, 0);
        const std::vector<Index> tri{0, 1, 2}, flat{0, 1, 3};
        m.add_face(tri);
        m.add_face(flat);
        std::string out;
        out = io::write_mesh_data(m, io::Format::Stl, {io::Encoding::Ascii});
        CHECK(out.find("facet normal 0 -1 0\n") != std::string::npos);
        CHECK(out.find("facet normal 0 0 0\n") != std::string::npos);
    }

    TEST_CASE("an empty mesh writes a valid empty file in both encodings")
    {
        std::string ascii, binary;
        ascii = io::write_mesh_data(Mesh{}, io::Format::Stl, {io::Encoding::Ascii});
        binary = io::write_mesh_data(Mesh{}, io::Format::Stl, {io::Encoding::BinaryLittleEndian});
        CHECK(ascii == "solid meshfair\nendsolid meshfair\n");
        CHECK(binary.size() == 84);
        CHECK(parse_stl(ascii) == Mesh{});
        CHECK(parse_stl(binary) == Mesh{});
    }

    TEST_CASE("coordinates beyond float32 are refused for binary STL only")
    {
        Mesh m = test::tetrahedron();
        m.positions[4] = 1e300;
        std::string out;
        CHECK_THROWS_WITH_AS(
            out = io::write_mesh_data(m, io::Format::Stl, {io::Encoding::BinaryLittleEndian}),
            "write_stl: vertex 1 has a coordinate beyond the float32 range of "
            "binary STL; write ASCII STL instead",
            InvalidInputError);
        out = io::write_mesh_data(m, io::Format::Stl, {io::Encoding::Ascii});
        CHECK(parse_stl(out).positions[3 * 1 + 1] == 1e300);
    }
}
