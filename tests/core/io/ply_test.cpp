// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_ply.h"

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "core/io/text_writer.h"
#include "core/io/write_ply.h"
#include "tests/allocation_counter.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

using io::Encoding;

constexpr Encoding kEncodings[] = {Encoding::Ascii, Encoding::BinaryLittleEndian,
                                   Encoding::BinaryBigEndian};

Mesh parse_ply(const std::string& data, io::ReadReport* report = nullptr)
{
    return test::read_as(data, io::Format::Ply, report);
}

io::MeshAttributes ply_attributes(const std::string& data)
{
    io::MeshAttributes attributes;
    io::read_mesh_data(data, io::Format::Ply, "t.ply", nullptr, &attributes);
    return attributes;
}

io::Property list_column(const char* name, io::ValueType count_type, io::ValueType type,
                         std::vector<std::vector<double>> rows)
{
    io::Property p{name, type, true, count_type, {}, {0}};
    for (const std::vector<double>& row : rows)
    {
        p.values.insert(p.values.end(), row.begin(), row.end());
        p.offsets.push_back(static_cast<Index>(p.values.size()));
    }
    return p;
}

std::string ply_error(const std::string& data)
{
    return test::read_error(data, io::Format::Ply);
}

// Appends values in one byte order, to assemble binary bodies byte by byte.
struct Bytes
{
    bool is_big_endian = false;
    std::string data;

    template <typename T>
    Bytes& put(T value)
    {
        char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        if (is_big_endian != (std::endian::native == std::endian::big))
            for (size_t k = 0; k < sizeof(T) / 2; ++k)
                std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
        data.append(bytes, sizeof(T));
        return *this;
    }
};

// One value of a body row: its declared PLY type and its value.
struct Value
{
    std::string_view type;
    double value;
};
using Row = std::vector<Value>;

template <typename T>
std::vector<T> operator+(std::vector<T> a, const std::vector<T>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// The body of `rows` in an encoding: ASCII rows are lines of shortest decimals.
std::string body(Encoding encoding, const std::vector<Row>& rows)
{
    std::string text;
    Bytes b{encoding == Encoding::BinaryBigEndian, {}};
    for (const Row& row : rows)
        for (size_t k = 0; k < row.size(); ++k)
        {
            const auto [type, value] = row[k];
            if (encoding == Encoding::Ascii)
            {
                io::append_double(text, value);
                text += k + 1 < row.size() ? ' ' : '\n';
            }
            else if (type == "char" || type == "int8")
                b.put(static_cast<std::int8_t>(value));
            else if (type == "uchar" || type == "uint8")
                b.put(static_cast<std::uint8_t>(value));
            else if (type == "short" || type == "int16")
                b.put(static_cast<std::int16_t>(value));
            else if (type == "ushort" || type == "uint16")
                b.put(static_cast<std::uint16_t>(value));
            else if (type == "int" || type == "int32")
                b.put(static_cast<std::int32_t>(value));
            else if (type == "uint" || type == "uint32")
                b.put(static_cast<std::uint32_t>(value));
            else if (type == "float" || type == "float32")
                b.put(static_cast<float>(value));
            else
                b.put(value);
        }
    return encoding == Encoding::Ascii ? text : b.data;
}

std::string header(Encoding encoding, const std::string& declarations)
{
    return "ply\nformat " + std::string(io::encoding_name(encoding)) + " 1.0\n" + declarations +
           "end_header\n";
}

std::string ply(Encoding encoding, const std::string& declarations, const std::vector<Row>& rows)
{
    return header(encoding, declarations) + body(encoding, rows);
}

// "element vertex N" with x, y, z of one type (4 header lines).
std::string vertex_decl(int n, std::string_view type = "float")
{
    std::string s = "element vertex " + std::to_string(n) + "\n";
    for (const char* axis : {"x", "y", "z"})
        s += "property " + std::string(type) + " " + axis + "\n";
    return s;
}

// "element face N" with its index list (2 header lines).
std::string face_decl(int n, std::string_view count_type = "uchar",
                      std::string_view item_type = "int")
{
    return "element face " + std::to_string(n) + "\nproperty list " + std::string(count_type) +
           " " + std::string(item_type) + " vertex_indices\n";
}

// A list: its count, then its items.
Row list(std::string_view count_type, std::string_view item_type, std::vector<double> items)
{
    Row r{{count_type, static_cast<double>(items.size())}};
    for (double x : items)
        r.push_back({item_type, x});
    return r;
}

Row xyz(double x, double y, double z, std::string_view type = "float")
{
    return {{type, x}, {type, y}, {type, z}};
}

Row tri(double a, double b, double c)
{
    return list("uchar", "int", {a, b, c});
}

// Two triangles on four vertices, as file rows and as the mesh they make.
const std::vector<Row> kVertexRows = {xyz(0, 0, 0), xyz(1, 0, 0), xyz(1, 1, 0.5), xyz(0, 1, 0)};
const std::vector<Row> kFaceRows = {tri(0, 1, 2), tri(0, 2, 3)};
const std::string kTwoTriangles = vertex_decl(4) + face_decl(2);

Mesh two_triangles()
{
    return test::make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
}

// One triangle: its binary little-endian header (the body starts right after it).
const std::string kBinaryHeader =
    header(Encoding::BinaryLittleEndian, vertex_decl(3) + face_decl(1));
const std::string kFace0 = " (face 0, property vertex_indices): ";

std::string binary_triangle_error(const Row& face)
{
    return ply_error(kBinaryHeader + body(Encoding::BinaryLittleEndian,
                                          {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0), face}));
}

std::string at_byte(size_t offset, const std::string& rest)
{
    return "t.ply: byte " + std::to_string(kBinaryHeader.size() + offset) + rest;
}

std::string swap_order(std::string data)
{
    const std::string from = "binary_big_endian";
    return data.replace(data.find(from), from.size(), "binary_little_endian");
}

} // namespace

TEST_SUITE("ReadPly")
{
    TEST_CASE("ASCII, little- and big-endian bodies give the same mesh")
    {
        for (const Encoding encoding : kEncodings)
        {
            CAPTURE(io::encoding_name(encoding));
            io::ReadReport report;
            CHECK(parse_ply(ply(encoding, kTwoTriangles, kVertexRows + kFaceRows), &report) ==
                  two_triangles());
            CHECK(report.format == io::Format::Ply);
            CHECK(report.encoding == encoding);
            CHECK(report.notes.empty());
        }
    }

    TEST_CASE("ASCII coordinates are read exactly as strtod reads them")
    {
        const char* values[] = {"0.3",
                                "-2.7182818284590451",
                                "1.0000000000000002",
                                "4.9406564584124654e-324",
                                "1.7976931348623157e308",
                                "0.30000000000000004",
                                "+123456789.12345678"};
        std::string text = header(Encoding::Ascii, vertex_decl(7, "double"));
        for (const char* v : values)
            text += std::string(v) + " " + v + " " + v + "\n";
        const Mesh m = parse_ply(text);
        for (size_t k = 0; k < std::size(values); ++k)
        {
            const double expected = std::strtod(values[k], nullptr);
            CHECK(std::memcmp(&m.positions[3 * k], &expected, sizeof(double)) == 0);
        }
    }

    TEST_CASE("float32 vertices are converted to double exactly")
    {
        const float values[] = {0.1f, -1e-30f, 3.4028235e38f, 1e-45f, -0.0f, 16777217.0f};
        for (const Encoding encoding : {Encoding::BinaryLittleEndian, Encoding::BinaryBigEndian})
        {
            Bytes b{encoding == Encoding::BinaryBigEndian, {}};
            for (const float v : values)
                b.put(v).put(v).put(-v);
            const Mesh m = parse_ply(header(encoding, vertex_decl(6, "float32")) + b.data);
            for (size_t k = 0; k < std::size(values); ++k)
            {
                const double expected = static_cast<double>(values[k]);
                CHECK(std::memcmp(&m.positions[3 * k], &expected, sizeof(double)) == 0);
                CHECK(m.positions[3 * k + 2] == -expected);
            }
        }
        // ASCII float properties keep the decimal's double value, as strtod reads it.
        const Mesh m = parse_ply(header(Encoding::Ascii, vertex_decl(1)) + "0.1 3.4028235e38 -7\n");
        CHECK(m.position(0) == Vec3{0.1, 3.4028235e38, -7});
    }

    TEST_CASE("extra vertex and face properties are kept in their types in every encoding")
    {
        const std::string declarations =
            "element vertex 3\nproperty float nx\nproperty double x\nproperty float ny\n"
            "property short y\nproperty double z\nproperty float nz\nproperty uchar red\n"
            "property uchar green\nproperty uchar blue\nproperty list uchar float texcoord\n"
            "element face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
            "property list ushort float uv\nproperty int material\n";
        const auto vertex = [](double x, double y, double z, std::vector<double> uv) {
            return Row{{"float", 0.25}, {"double", x},  {"float", -1}, {"short", y}, {"double", z},
                       {"float", 0},    {"uchar", 255}, {"uchar", 0},  {"uchar", 17}} +
                   list("uchar", "float", std::move(uv));
        };
        const std::vector<Row> rows = {
            vertex(0.1, -300, 0.3, {0.5, 0.75}), vertex(-1, 0, 1e-300, {}), vertex(3, 4, 5, {1, 2}),
            Row{{"uchar", 7}} + tri(2, 1, 0) + list("ushort", "float", {}) + Row{{"int", -5}},
            Row{{"uchar", 0}} + tri(0, 1, 2) + list("ushort", "float", {1, 2, 3, 4, 5, 6}) +
                Row{{"int", 1 << 20}}};
        const Mesh expected =
            test::make_mesh({{0.1, -300, 0.3}, {-1, 0, 1e-300}, {3, 4, 5}}, {{2, 1, 0}, {0, 1, 2}});
        for (const Encoding encoding : kEncodings)
        {
            CAPTURE(io::encoding_name(encoding));
            io::ReadReport report;
            const std::string data = ply(encoding, declarations, rows);
            CHECK(parse_ply(data, &report) == expected);
            CHECK(report.notes.empty());
            using T = io::ValueType;
            const io::MeshAttributes a = ply_attributes(data);
            CHECK(a.vertex.count == 3);
            CHECK(a.vertex.properties ==
                  std::vector<io::Property>{
                      test::property("nx", T::Float32, {0.25, 0.25, 0.25}),
                      test::property("ny", T::Float32, {-1, -1, -1}),
                      test::property("nz", T::Float32, {0, 0, 0}),
                      test::property("red", T::UInt8, {255, 255, 255}),
                      test::property("green", T::UInt8, {0, 0, 0}),
                      test::property("blue", T::UInt8, {17, 17, 17}),
                      list_column("texcoord", T::UInt8, T::Float32, {{0.5, 0.75}, {}, {1, 2}})});
            CHECK(a.face.count == 2);
            CHECK(a.face.properties ==
                  std::vector<io::Property>{
                      test::property("flags", T::UInt8, {7, 0}),
                      list_column("uv", T::UInt16, T::Float32, {{}, {1, 2, 3, 4, 5, 6}}),
                      test::property("material", T::Int32, {-5, 1 << 20})});
            CHECK(a.other_elements.empty());
        }
    }

    TEST_CASE("other elements before, between and after are kept whole")
    {
        const std::string declarations =
            "element material 2\nproperty uchar ambient_red\nproperty float power\n" +
            vertex_decl(4) +
            "element edge 2\nproperty int vertex1\nproperty int vertex2\n"
            "property list uchar int chain\nelement nothing 5\n" +
            face_decl(2) + "element range_grid 1\nproperty list uchar int vertex_indices\n";
        const std::vector<Row> rows =
            std::vector<Row>{{{"uchar", 1}, {"float", 2.5}}, {{"uchar", 3}, {"float", 4}}} +
            kVertexRows +
            std::vector<Row>{Row{{"int", 0}, {"int", 1}} + list("uchar", "int", {0, 1, 2, 3}),
                             Row{{"int", 2}, {"int", 3}} + list("uchar", "int", {})} +
            kFaceRows + std::vector<Row>{list("uchar", "int", {0})};
        for (const Encoding encoding : kEncodings)
        {
            CAPTURE(io::encoding_name(encoding));
            io::ReadReport report;
            const std::string data = ply(encoding, declarations, rows);
            CHECK(parse_ply(data, &report) == two_triangles());
            CHECK(report.notes.empty());
            using T = io::ValueType;
            const io::MeshAttributes a = ply_attributes(data);
            CHECK(a.vertex.properties.empty());
            CHECK(a.face.properties.empty());
            CHECK(
                a.other_elements ==
                std::vector<io::Element>{
                    {"material",
                     2,
                     {test::property("ambient_red", T::UInt8, {1, 3}),
                      test::property("power", T::Float32, {2.5, 4})}},
                    {"edge",
                     2,
                     {test::property("vertex1", T::Int32, {0, 2}),
                      test::property("vertex2", T::Int32, {1, 3}),
                      list_column("chain", T::UInt8, T::Int32, {{0, 1, 2, 3}, {}})}},
                    {"nothing", 5, {}},
                    {"range_grid", 1, {list_column("vertex_indices", T::UInt8, T::Int32, {{0}})}}});
        }
    }

    TEST_CASE("list counts and indices of every integer type and width are read")
    {
        const char* types[] = {"char",   "int8",   "uchar", "uint8", "short", "int16",
                               "ushort", "uint16", "int",   "int32", "uint",  "uint32"};
        // 300 vertices, so that wide index types carry indices beyond a byte.
        std::vector<Row> vertex_rows;
        Mesh expected;
        for (int i = 0; i < 300; ++i)
        {
            vertex_rows.push_back(xyz(i, -i, 0, "int"));
            expected.add_vertex(i, -i, 0);
        }
        expected.add_face(std::vector<Index>{0, 1, 2});
        for (const std::string count_type : types)
            for (const std::string item_type : types)
            {
                const double top = item_type == "char" || item_type == "int8"     ? 127
                                   : item_type == "uchar" || item_type == "uint8" ? 255
                                                                                  : 299;
                Mesh m = expected;
                m.add_face(std::vector<Index>{static_cast<Index>(top), 5, 3});
                const std::vector<Row> rows =
                    vertex_rows + std::vector<Row>{list(count_type, item_type, {0, 1, 2}),
                                                   list(count_type, item_type, {top, 5, 3})};
                for (const Encoding encoding : kEncodings)
                {
                    CAPTURE(count_type);
                    CAPTURE(item_type);
                    CAPTURE(io::encoding_name(encoding));
                    CHECK(
                        parse_ply(ply(encoding,
                                      vertex_decl(300, "int") + face_decl(2, count_type, item_type),
                                      rows)) == m);
                }
            }
    }

    TEST_CASE("faces may come before vertices, and vertex_index names the list too")
    {
        const std::string declarations =
            "element face 2\nproperty list uchar uint vertex_index\n" + vertex_decl(4);
        for (const Encoding encoding : kEncodings)
            CHECK(parse_ply(ply(encoding, declarations, kFaceRows + kVertexRows)) ==
                  two_triangles());
    }

    TEST_CASE("a file without a face element is a point cloud")
    {
        for (const Encoding encoding : kEncodings)
        {
            io::ReadReport report;
            const Mesh m = parse_ply(ply(encoding, vertex_decl(4), kVertexRows), &report);
            CHECK(m.vertex_count() == 4);
            CHECK(m.face_count() == 0);
            CHECK(report.notes ==
                  std::vector<std::string>{"no faces: read as a point cloud of 4 vertices"});
        }
        CHECK(parse_ply("ply\nformat ascii 1.0\ncomment nothing\nend_header\n") == Mesh{});
    }

    TEST_CASE(
        "tristrips are decoded into triangles, -1 restarting a strip, degenerate ones "
        "dropped")
    {
        // Strip 0 gives (0 1 2) and (2 1 3), the second reversed to keep the strip's
        // orientation; strip 1's repeated 4 makes two degenerate triangles between (2 3 4)
        // and nothing after it; strip 2 doubles back on its first vertex (a third).
        const std::string decl = vertex_decl(6) +
                                 "element tristrips 1\n"
                                 "property list int int vertex_indices\n";
        const std::vector<Row> rows = {
            xyz(0, 0, 0),
            xyz(1, 0, 0),
            xyz(0, 1, 0),
            xyz(1, 1, 0),
            xyz(0, 2, 0),
            xyz(1, 2, 0),
            list("int", "int", {0, 1, 2, 3, -1, 2, 3, 4, 4, 5, -1, 0, 1, 0})};
        for (const Encoding encoding : kEncodings)
        {
            CAPTURE(io::encoding_name(encoding));
            io::ReadReport report;
            const Mesh m = parse_ply(ply(encoding, decl, rows), &report);
            CHECK(m == test::make_mesh(
                           {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}, {1, 2, 0}},
                           {{0, 1, 2}, {2, 1, 3}, {2, 3, 4}}));
            CHECK(report.notes ==
                  std::vector<std::string>{
                      "decoded element 'tristrips' (3 strips) into 3 triangles (a PLY that "
                      "MeshFair writes lists them as faces)",
                      "dropped 3 degenerate triangles of the strips (two equal corners, where "
                      "strips turn or join)"});
        }
    }

    TEST_CASE("a long strip over a grid gives triangles that all face one way")
    {
        // Two rows of n vertices zigzagged into one strip, as range-scan strips run:
        // 0 n 1 n+1 2 n+2 ...; every triangle must face the way the first one does: (0 n 1)
        // turns clockwise seen from +z, so all face -z.
        constexpr int n = 50;
        std::vector<Row> rows;
        for (int row = 0; row < 2; ++row)
            for (int i = 0; i < n; ++i)
                rows.push_back(xyz(i, row, 0.01 * ((i * 7) % 5)));
        std::vector<double> strip;
        for (int i = 0; i < n; ++i)
        {
            strip.push_back(i);
            strip.push_back(n + i);
        }
        rows.push_back(list("int", "int", strip));
        const Mesh m = parse_ply(ply(Encoding::Ascii,
                                     vertex_decl(2 * n) + "element tristrips 1\n"
                                                          "property list int int vertex_indices\n",
                                     rows));
        REQUIRE(m.face_count() == 2 * n - 2);
        for (Index f = 0; f < m.face_count(); ++f)
        {
            CAPTURE(f);
            CHECK(face_normal(m, m.positions, f)[2] < -0.9);
        }
    }

    TEST_CASE("an unsigned strip list restarts at its type's largest value")
    {
        for (const auto& type : {std::pair<std::string, double>{"uchar", 255},
                                 {"ushort", 65535},
                                 {"uint", 4294967295.0}})
        {
            const std::string& item = type.first;
            const double restart = type.second;
            CAPTURE(item);
            const std::string decl = vertex_decl(4) + "element tristrips 1\nproperty list int " +
                                     item + " vertex_indices\n";
            for (const Encoding encoding : kEncodings)
            {
                CAPTURE(io::encoding_name(encoding));
                const Mesh m =
                    parse_ply(ply(encoding, decl,
                                  kVertexRows + std::vector<Row>{list(
                                                    "int", item, {0, 1, 2, restart, 0, 2, 3})}));
                CHECK(m == two_triangles());
            }
        }
    }

    TEST_CASE("faces and tristrips in one file give both, in element order")
    {
        const std::string decl = vertex_decl(4) + face_decl(1) +
                                 "element tristrips 1\nproperty list int int vertex_indices\n";
        const Mesh m = parse_ply(
            ply(Encoding::Ascii, decl,
                kVertexRows + std::vector<Row>{tri(0, 1, 2), list("int", "int", {0, 2, 3})}));
        CHECK(m == two_triangles());
    }

    TEST_CASE("tristrips errors name the row, the item and the vertex count")
    {
        const std::string decl = vertex_decl(3) +
                                 "element tristrips 1\n"
                                 "property list int int vertex_indices\n";
        const std::vector<Row> vertices = {xyz(0, 0, 0), xyz(1, 0, 0), xyz(0, 1, 0)};
        CHECK(ply_error(ply(Encoding::Ascii, decl,
                            vertices + std::vector<Row>{list("int", "int", {0, 1, 2, -2})})) ==
              "t.ply:13:9: tristrips 0 uses vertex index -2 at item 3 (PLY vertex indices start "
              "at 0; -1 ends a strip)");
        CHECK(ply_error(ply(Encoding::Ascii, decl,
                            vertices + std::vector<Row>{list("int", "int", {0, 1, 3})})) ==
              "t.ply:13:7: tristrips 0 uses vertex index 3 at item 2 but the file declares 3 "
              "vertices");
        CHECK(
            ply_error(header(Encoding::Ascii, vertex_decl(3) + "element tristrips 1\n"
                                                               "property int vertex_indices\n")) ==
            "t.ply:8:1: tristrips property 'vertex_indices' is not a list");
        CHECK(
            ply_error(header(Encoding::Ascii, vertex_decl(3) + "element tristrips 1\n"
                                                               "property list int int strip\n")) ==
            "t.ply:7:1: tristrips element has no list property 'vertex_indices' (or "
            "'vertex_index')");
        CHECK(ply_error(header(Encoding::Ascii, vertex_decl(3) +
                                                    "element tristrips 1\nproperty list int int "
                                                    "vertex_indices\nelement tristrips 0\n")) ==
              "t.ply:9:9: second 'tristrips' element (a PLY mesh has at most one)");
    }

    TEST_CASE("a tristrips mesh written as PLY reads back as the same faces")
    {
        const std::string decl = vertex_decl(4) +
                                 "element tristrips 1\n"
                                 "property list int int vertex_indices\n";
        const Mesh m =
            parse_ply(ply(Encoding::BinaryLittleEndian, decl,
                          kVertexRows + std::vector<Row>{list("int", "int", {1, 2, 0, 3})}));
        REQUIRE(m.face_count() == 2);
        for (const Encoding encoding : kEncodings)
        {
            std::string out;
            out = io::write_mesh_data(m, io::Format::Ply, {encoding});
            io::ReadReport report;
            CHECK(parse_ply(out, &report) == m);
            CHECK(report.notes.empty());
        }
    }

    TEST_CASE("CRLF and CR-only headers are accepted, with binary data right after them")
    {
        std::string crlf;
        for (const char c : ply(Encoding::Ascii, kTwoTriangles, kVertexRows + kFaceRows))
            crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
        CHECK(parse_ply("\xEF\xBB\xBF" + crlf) == two_triangles());

        // The body starts with byte 10 (LF): it is data, not the end of a CRLF.
        const std::string declarations =
            "element vertex 1\nproperty uchar flags\nproperty float x\nproperty float y\n"
            "property float z\n";
        const std::string data =
            body(Encoding::BinaryLittleEndian, {Row{{"uchar", 10}} + xyz(1, 2, 3)});
        for (const std::string end : {"\r\n", "\r"})
        {
            CAPTURE(end.size());
            std::string head;
            for (const char c : header(Encoding::BinaryLittleEndian, declarations))
                head += c == '\n' ? end : std::string(1, c);
            CHECK(parse_ply(head + data).position(0) == Vec3{1, 2, 3});
        }
    }

    TEST_CASE("comments, obj_info and blank lines are ignored")
    {
        const Mesh m = parse_ply(
            "ply\ncomment made by hand\nformat ascii 1.0\nobj_info x\nelement vertex 3\n"
            "comment between properties\nproperty float x\nproperty float y\nproperty float "
            "z\n\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0\n1 0 0\n\n0 1 0\n3 0 1 2\n\n");
        CHECK(m == test::make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
    }

    TEST_CASE("repeated consecutive indices are collapsed and reported")
    {
        const std::vector<Row> rows =
            kVertexRows + std::vector<Row>{list("uchar", "int", {0, 1, 1, 2}),
                                           list("uchar", "int", {0, 2, 3, 0})};
        const std::string note = "collapsed 2 consecutive repeated vertex indices in 2 faces ";
        io::ReadReport report;
        CHECK(parse_ply(ply(Encoding::Ascii, kTwoTriangles, rows), &report) == two_triangles());
        CHECK(report.notes == std::vector<std::string>{note + "(first at t.ply:14:1)"});
        const std::string data = ply(Encoding::BinaryBigEndian, kTwoTriangles, rows);
        CHECK(parse_ply(data, &report) == two_triangles());
        CHECK(report.notes == std::vector<std::string>{note + "(first at t.ply: byte " +
                                                       std::to_string(data.size() - 2 * 17) +
                                                       " (face 0, property vertex_indices))"});
    }

    TEST_CASE("header counts the data cannot hold are refused before allocating")
    {
        const test::AllocationScope scope;
        CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float "
                        "x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 1 1\n") ==
              "t.ply:3:16: header declares 1000000000000 vertices but only 12 bytes follow");
        CHECK(ply_error(header(Encoding::BinaryBigEndian,
                               vertex_decl(0) + "element face 1000000000000\nproperty list uchar "
                                                "int vertex_indices\n") +
                        std::string(12, '\0')) ==
              "t.ply:7:14: header declares 1000000000000 faces but only 12 bytes follow");
        CHECK(ply_error(header(Encoding::BinaryLittleEndian,
                               "element edge 4\nproperty int a\nproperty list uint int b\n") +
                        std::string(31, '\0')) ==
              "t.ply:3:14: header declares 4 rows of element 'edge' but only 31 bytes follow");
        CHECK(ply_error(header(Encoding::BinaryLittleEndian, "element nothing 3000000000\n")) ==
              "t.ply:3:17: element 'nothing' has 3000000000 rows (MeshFair supports at most "
              "2147483647)");
        // Nothing reserved for what the header promises: no request over 64 KiB.
        CHECK(scope.largest() <= 65536);
    }

    TEST_CASE("header errors name the line and column")
    {
        const std::string a = "ply\nformat ascii 1.0\n", v = a + "element vertex 0\n";
        const std::string f = a + vertex_decl(0) + "element face 0\n";
        const std::string hint =
            " (expected ascii, binary_little_endian or binary_big_endian, version 1.0)";
        CHECK(ply_error("") == "t.ply: empty file");
        CHECK(ply_error("PLY\n" + a.substr(4)) ==
              "t.ply:1:1: not a PLY file (the first line must be 'ply')");
        CHECK(ply_error("ply\nformat binary 1.0\n") ==
              "t.ply:2:8: unknown PLY format 'binary 1.0'" + hint);
        CHECK(ply_error("ply\nformat ascii 2.0 \n") ==
              "t.ply:2:8: unknown PLY format 'ascii 2.0'" + hint);
        CHECK(ply_error(a + "format ascii 1.0\n") == "t.ply:3:1: second format line");
        CHECK(ply_error("ply\nelement vertex 0\n") == "t.ply:2:1: element before the format line");
        CHECK(ply_error("ply\ncomment\nend_header\n") ==
              "t.ply:3:1: no format line before end_header");
        CHECK(ply_error(v + "property float x\n") ==
              "t.ply:4:17: no end_header (the file ends inside the header)");
        CHECK(ply_error("ply\nformat binary_little_endian 1.0\n" + vertex_decl(1) +
                        std::string("\x01\x00\x00\x00", 4)) ==
              "t.ply:7:2: NUL byte in a text file (inside the PLY header; is end_header missing?)");
        CHECK(ply_error(a + "end_header extra\n") ==
              "t.ply:3:12: unexpected text after end_header");
        CHECK(ply_error(a + "element vertex\n") ==
              "t.ply:3:1: an element line must be 'element NAME COUNT'");
        CHECK(ply_error(a + "element vertex -1\n") == "t.ply:3:16: element count -1 is negative");
        CHECK(ply_error(a + "element vertex 2.5\n") ==
              "t.ply:3:16: element count '2.5' is not an integer");
        CHECK(ply_error(a + "property float x\n") ==
              "t.ply:3:1: property before the first element");
        CHECK(ply_error(v + "property int64 x\n") == "t.ply:4:10: unknown property type 'int64'");
        CHECK(ply_error(v + "property float\n") ==
              "t.ply:4:1: a property line must be 'property TYPE NAME'");
        CHECK(ply_error(v + "property list uchar int\n") ==
              "t.ply:4:1: a list property line must be 'property list COUNT_TYPE ITEM_TYPE NAME'");
        CHECK(ply_error(v + "property list float int vertex_indices\n") ==
              "t.ply:4:15: list count type 'float' is not an integer type");
        CHECK(ply_error(v + "property float x\nproperty double x\n") ==
              "t.ply:5:17: element 'vertex' already has a property 'x'");
        CHECK(ply_error(v + "property float x\nproperty float z\nend_header\n") ==
              "t.ply:3:1: vertex element has no property 'y'");
        CHECK(ply_error(v + "property float y\nproperty float z\nend_header\n") ==
              "t.ply:3:1: vertex element has no property 'x'");
        CHECK(ply_error(v + "property float x\nproperty float y\nend_header\n") ==
              "t.ply:3:1: vertex element has no property 'z'");
        CHECK(ply_error(v + "property float x\nproperty float y\nproperty list uchar float "
                            "z\nend_header\n") ==
              "t.ply:6:1: vertex property 'z' is a list, not a coordinate");
        CHECK(ply_error(a + vertex_decl(0) + "element vertex 0\n") ==
              "t.ply:7:9: second 'vertex' element (a PLY mesh has at most one)");
        CHECK(ply_error(a + vertex_decl(0) + face_decl(0) + face_decl(0)) ==
              "t.ply:9:9: second 'face' element (a PLY mesh has at most one)");
        CHECK(ply_error(f + "property int vertex_indices\nend_header\n") ==
              "t.ply:8:1: face property 'vertex_indices' is not a list");
        CHECK(ply_error(f + "property list uchar float vertex_indices\nend_header\n") ==
              "t.ply:8:1: face property 'vertex_indices' has item type 'float' (vertex indices "
              "must be integers)");
        CHECK(ply_error(f + "property list uchar int verts\nend_header\n") ==
              "t.ply:7:1: face element has no list property 'vertex_indices' (or 'vertex_index')");
        CHECK(ply_error(f + "property list uchar int vertex_index\nproperty list uchar int "
                            "vertex_indices\nend_header\n") ==
              "t.ply:8:1: face element has both 'vertex_indices' and 'vertex_index'");
        CHECK(ply_error(v + "vertex 1 2 3\n") == "t.ply:4:1: unknown header keyword 'vertex'");
    }

    TEST_CASE("ASCII body errors name the line and column")
    {
        // Three vertices (body lines 10 to 12) and one face (line 13).
        const std::string h = header(Encoding::Ascii, vertex_decl(3, "double") + face_decl(1));
        const auto face_error = [&](const std::string& face) {
            return ply_error(h + "0 0 0\n1 0 0\n0 1 0\n" + face);
        };
        const auto vertex_error = [&](const std::string& vertex) {
            return ply_error(h + "0 0 0\n" + vertex + "0 1 0\n3 0 1 2\n");
        };
        CHECK(vertex_error("1 nan 0\n") == "t.ply:11:3: y coordinate 'nan' is not finite");
        CHECK(vertex_error("1 0 -inf\n") == "t.ply:11:5: z coordinate '-inf' is not finite");
        CHECK(vertex_error("1e400 0 0\n") ==
              "t.ply:11:1: x coordinate '1e400' is out of the range of a double");
        CHECK(vertex_error("one 0 0\n") == "t.ply:11:1: x coordinate 'one' is not a number");
        CHECK(vertex_error("1 0\n") == "t.ply:11:4: vertex 1 has no value for property 'z'");
        CHECK(vertex_error("1 0 0 7\n") ==
              "t.ply:11:7: unexpected value '7' after the last property of vertex 1");
        CHECK(face_error("3 0 1 2 0\n") ==
              "t.ply:13:9: unexpected value '0' after the last property of face 0");
        CHECK(face_error("5 0 1 2\n") ==
              "t.ply:13:1: 'vertex_indices' list count 5 is more "
              "than the 3 values left on the line");
        CHECK(face_error("300 0 1 2\n") ==
              "t.ply:13:1: 'vertex_indices' list count 300 does not fit in uchar");
        CHECK(face_error("3 0 1 3\n") ==
              "t.ply:13:7: face 0 uses vertex index 3 but the file declares 3 vertices");
        CHECK(face_error("3 0 -1 2\n") ==
              "t.ply:13:5: face 0 uses vertex index -1 (PLY vertex indices start at 0)");
        CHECK(face_error("3 0 1.5 2\n") == "t.ply:13:5: vertex index '1.5' is not an integer");
        CHECK(face_error("3 0 1 4294967296\n") ==
              "t.ply:13:7: vertex index 4294967296 does not fit in int");
        CHECK(face_error("2 0 1\n") ==
              "t.ply:13:1: face 0 has 2 vertices (a face needs at least 3)");
        CHECK(face_error("3 0 1 1\n") ==
              "t.ply:13:1: face has 2 distinct vertices (a face needs at least 3)");
        CHECK(face_error("4 0 1 0 2\n") ==
              "t.ply:13:1: face uses vertex 0 at two corners that are not adjacent");
        CHECK(face_error("3 0 1 2\n\n  \n3 0 1 2\n") ==
              "t.ply:16:1: unexpected data after the last element");
        CHECK(ply_error(h + "0.000000 0 0\n1.000000 0 0\n") ==
              "t.ply:11:13: file ends before vertex 2 (the header declares 3 vertices)");
        // One vertex (line 8) with other types.
        CHECK(ply_error(header(Encoding::Ascii, vertex_decl(1)) + "0 1e39 0\n") ==
              "t.ply:8:3: y coordinate '1e39' does not fit in float");
        CHECK(ply_error(header(Encoding::Ascii, vertex_decl(1, "uchar")) + "0 256 0\n") ==
              "t.ply:8:3: y coordinate 256 does not fit in uchar");
        const std::string feature =
            header(Encoding::Ascii, vertex_decl(1) + "property list char int feature\n");
        CHECK(ply_error(feature + "0 0 0 -1\n") ==
              "t.ply:9:7: 'feature' list count -1 is negative");
        CHECK(ply_error(feature + "0 0 0 2 4 x\n") ==
              "t.ply:9:11: 'feature' value 'x' is not an integer");
    }

    TEST_CASE("binary body errors name the byte offset, element, row and property")
    {
        // Three 12-byte vertices, then the face: count at byte 36, indices at 37, 41, 45.
        CHECK(binary_triangle_error(tri(0, 1, 3)) ==
              at_byte(45, kFace0 + "face 0 uses vertex index 3 but the file declares 3 vertices"));
        CHECK(binary_triangle_error(tri(0, -7, 2)) ==
              at_byte(41, kFace0 + "face 0 uses vertex index -7 (PLY vertex indices start at 0)"));
        CHECK(binary_triangle_error(list("uchar", "int", {0, 1})) ==
              at_byte(36, kFace0 + "face 0 has 2 vertices (a face needs at least 3)"));
        CHECK(binary_triangle_error(tri(0, 1, 1)) ==
              at_byte(36, kFace0 + "face has 2 distinct vertices (a face needs at least 3)"));
        CHECK(binary_triangle_error(Row{{"uchar", 4}, {"int", 0}, {"int", 1}, {"int", 2}}) ==
              at_byte(36, kFace0 + "'vertex_indices' list count 4 needs 16 bytes, more than the "
                                   "12 bytes left"));
        // NUL and line-end bytes after the last row are padding; anything else is a row
        // the counts do not declare.
        CHECK(binary_triangle_error(tri(0, 1, 2) + Row{{"uchar", 0}}) == "accepted");
        CHECK(binary_triangle_error(tri(0, 1, 2) + Row{{"uchar", 7}}) ==
              at_byte(49, ": unexpected data after the last element (1 byte)"));
        Bytes b;
        for (const float x : {0.0f, 0.0f, 0.0f, 1.0f, std::numeric_limits<float>::quiet_NaN()})
            b.put(x);
        CHECK(ply_error(kBinaryHeader + b.data + std::string(17, '\0')) ==
              at_byte(16, " (vertex 1, property y): vertex 1 has a non-finite y coordinate (nan)"));
        b = {};
        b.put<std::uint8_t>(3).put(0).put(1).put(2147483648u);
        CHECK(ply_error(header(Encoding::BinaryLittleEndian,
                               vertex_decl(3) + face_decl(1, "uchar", "uint32")) +
                        std::string(36, '\0') + b.data)
                  .ends_with("face 0 uses vertex index 2147483648 but the file declares 3 "
                             "vertices"));

        // Truncated inside a vertex: faces come first, so the vertex count fits the data.
        const std::string faces_first =
            header(Encoding::BinaryLittleEndian, face_decl(1) + vertex_decl(4));
        b = {};
        b.put<std::uint8_t>(3).put(0).put(1).put(2);
        b.data += std::string(39, '\0');
        CHECK(ply_error(faces_first + b.data) ==
              "t.ply: byte " + std::to_string(faces_first.size() + 49) +
                  " (vertex 3, property x): file ends inside this value (needs 4 bytes, 3 left)");

        // Truncated inside a face: the property after the list is cut.
        const std::string material = header(Encoding::BinaryLittleEndian,
                                            vertex_decl(4) + face_decl(2) + "property ushort m\n");
        const std::string cut =
            body(Encoding::BinaryLittleEndian,
                 kVertexRows + std::vector<Row>{tri(0, 1, 2) + Row{{"ushort", 9}},
                                                tri(0, 2, 3) + Row{{"uchar", 9}}});
        CHECK(ply_error(material + cut) ==
              "t.ply: byte " + std::to_string(material.size() + 48 + 15 + 13) +
                  " (face 1, property m): file ends inside this value (needs 2 bytes, 1 left)");

        // A list on a skipped element whose count runs past the data.
        const std::string edges =
            header(Encoding::BinaryBigEndian, "element edge 2\nproperty list ushort double c\n");
        b = {true, {}};
        b.put<std::uint16_t>(1).put(1.0).put<std::uint16_t>(300).put(2.0);
        CHECK(ply_error(edges + b.data) == "t.ply: byte " + std::to_string(edges.size() + 10) +
                                               " (edge 1, property c): 'c' list count 300 needs "
                                               "2400 bytes, more than the 8 bytes left");
    }

    TEST_CASE("a big-endian body declared little-endian is refused")
    {
        const std::string data =
            swap_order(ply(Encoding::BinaryBigEndian, kTwoTriangles, kVertexRows + kFaceRows));
        const size_t faces = data.find("end_header\n") + 11 + 48;
        CHECK(ply_error(data) == "t.ply: byte " + std::to_string(faces + 5) + kFace0 +
                                     "face 0 uses vertex index 16777216 but the file declares 4 "
                                     "vertices");
        // With a uint list count, the swapped count runs past the data instead.
        const std::string wide =
            swap_order(ply(Encoding::BinaryBigEndian, vertex_decl(4) + face_decl(2, "uint"),
                           kVertexRows + std::vector<Row>{list("uint", "int", {0, 1, 2}),
                                                          list("uint", "int", {0, 2, 3})}));
        CHECK(ply_error(wide) == "t.ply: byte " +
                                     std::to_string(wide.find("end_header\n") + 11 + 48) + kFace0 +
                                     "'vertex_indices' list count 50331648 needs 201326592 "
                                     "bytes, more than the 28 bytes left");
    }
}

TEST_SUITE("WritePly")
{
    TEST_CASE("every encoding round-trips mixed polygons bit-exactly")
    {
        Mesh m = test::mixed_polygons();
        test::perturb(m, 0.37, 11); // 17 significant digits
        m.positions[0] = -0.0;
        m.positions[1] = 5e-324;
        m.positions[2] = -1.7976931348623157e308;
        for (const Encoding encoding : kEncodings)
        {
            CAPTURE(io::encoding_name(encoding));
            std::string out;
            out = io::write_mesh_data(m, io::Format::Ply, {encoding});
            io::ReadReport report;
            const Mesh back = io::read_mesh_data(out, io::Format::Ply, "round-trip", &report);
            CHECK(back == m);
            CHECK(std::memcmp(back.positions.data(), m.positions.data(),
                              m.positions.size() * sizeof(double)) == 0);
            CHECK(report.encoding == encoding);
            CHECK(report.notes.empty());
        }
    }

    TEST_CASE("the ASCII file holds the documented header and shortest decimals")
    {
        const Mesh m = test::make_mesh({{0.1, -2, 1e-7}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                                       {{0, 1, 3, 2}, {0, 1, 2}});
        std::string out;
        out = io::write_mesh_data(m, io::Format::Ply, {Encoding::Ascii});
        CHECK(out == "ply\nformat ascii 1.0\ncomment MeshFair\n" + vertex_decl(4, "double") +
                         face_decl(2) +
                         "end_header\n0.1 -2 1e-07\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n3 0 1 2\n");
    }

    TEST_CASE("binary files hold doubles and int32 in the requested byte order")
    {
        const Mesh m = test::make_mesh({{1.5, -2, 0}, {0, 1, 0}, {0, 0, 1}}, {{2, 0, 1}});
        for (const Encoding encoding : {Encoding::BinaryLittleEndian, Encoding::BinaryBigEndian})
        {
            std::string out;
            out = io::write_mesh_data(m, io::Format::Ply, {encoding});
            Bytes expected{encoding == Encoding::BinaryBigEndian, {}};
            for (double x : m.positions)
                expected.put(x);
            expected.put<std::uint8_t>(3).put(2).put(0).put(1);
            CHECK(out ==
                  header(encoding, "comment MeshFair\n" + vertex_decl(3, "double") + face_decl(1)) +
                      expected.data);
        }
    }

    TEST_CASE("faces with more than 255 vertices get a uint count")
    {
        Mesh m;
        std::vector<Index> polygon;
        for (int k = 0; k < 300; ++k)
        {
            m.add_vertex(std::cos(k * 0.02), std::sin(k * 0.02), k * 1e-3);
            polygon.push_back(k);
        }
        m.add_face(polygon);
        m.add_face(std::vector<Index>{0, 5, 299});
        for (const Encoding encoding : kEncodings)
        {
            CAPTURE(io::encoding_name(encoding));
            std::string out;
            out = io::write_mesh_data(m, io::Format::Ply, {encoding});
            CHECK(out.find(face_decl(2, "uint") + "end_header\n") != std::string::npos);
            io::ReadReport report;
            CHECK(io::read_mesh_data(out, io::Format::Ply, "long.ply", &report) == m);
        }
    }

    TEST_CASE("meshes without faces still declare the face element")
    {
        for (const Mesh& m : {Mesh{}, test::make_mesh({{1, 2, 3}}, {})})
            for (const Encoding encoding : kEncodings)
            {
                std::string out;
                out = io::write_mesh_data(m, io::Format::Ply, {encoding});
                CHECK(out.find(face_decl(0) + "end_header\n") != std::string::npos);
                CHECK(parse_ply(out) == m);
            }
    }
}
