// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_stl.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/errors.h"
#include "core/io/attributes.h"
#include "core/io/byte_reader.h"
#include "core/io/face_builder.h"
#include "core/io/text_reader.h"

namespace meshfair::io {

namespace {

constexpr size_t kBinaryHeaderBytes = 84;   // 80-byte comment + uint32 triangle count
constexpr size_t kBinaryTriangleBytes = 50; // 12 float32 + uint16 attribute

// Gives each distinct position one vertex, numbered in order of first appearance.
// Positions are compared bit for bit, except that -0.0 equals +0.0; the first
// appearance's coordinates are the ones kept.
class Welder
{
public:
    Welder(Mesh& mesh, size_t expected_corners) : mesh_(mesh)
    {
        // Closed triangle meshes have about half as many vertices as triangles.
        map_.reserve(expected_corners / 6);
    }

    Index add(double x, double y, double z)
    {
        ++corners_;
        const Key key{bits(x), bits(y), bits(z)};
        const auto [it, is_new] = map_.try_emplace(key, mesh_.vertex_count());
        if (is_new)
            mesh_.add_vertex(x, y, z);
        return it->second;
    }

    std::int64_t corners() const { return corners_; }

private:
    using Key = std::array<std::uint64_t, 3>;
    struct KeyHash
    {
        size_t operator()(const Key& k) const
        {
            // splitmix64-style mixing: coordinates often differ only in low bits.
            std::uint64_t h = 0x9E3779B97F4A7C15ull;
            for (const std::uint64_t v : k)
            {
                h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
                h ^= h >> 31;
                h *= 0xBF58476D1CE4E5B9ull;
            }
            return static_cast<size_t>(h ^ (h >> 29));
        }
    };
    static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); }

    Mesh& mesh_;
    std::unordered_map<Key, Index, KeyHash> map_;
    std::int64_t corners_ = 0;
};

void report_welding(const Welder& welder, const Mesh& mesh, ReadReport& report)
{
    if (mesh.face_count() > 0) // an empty mesh is noted by read_mesh_data
        report.notes.push_back("welded " + std::to_string(welder.corners()) + " corners into " +
                               count_of(mesh.vertex_count(), "vertex", "vertices") +
                               " by exact position");
}

bool is_space(char c)
{
    return is_blank(c) || c == '\n' || c == '\r';
}

// True when the first word, after an optional UTF-8 byte-order mark and white space,
// is "solid" in any case.
bool starts_with_solid(std::string_view data)
{
    size_t k = data.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    while (k < data.size() && is_space(data[k]))
        ++k;
    const std::string_view rest = data.substr(k);
    return rest.size() >= 5 && equals_ignoring_case(rest.substr(0, 5), "solid") &&
           (rest.size() == 5 || is_space(rest[5]));
}

// ---- binary -------------------------------------------------------------------------

// The file is neither ASCII STL (`why`) nor binary STL of a consistent size.
[[noreturn]] void fail_binary_size(std::string_view data, const std::string& name,
                                   const std::string& why)
{
    if (data.size() < kBinaryHeaderBytes)
        throw FormatError(SourceLocation::whole(name),
                          "file too short for a binary STL header (" +
                              count_of(static_cast<std::int64_t>(data.size()), "byte", "bytes") +
                              ", needs 84); " + why);
    ByteReader bytes(data, name, 80);
    const std::uint32_t count = bytes.read<std::uint32_t>(ByteOrder::Little);
    ByteReader at_count(data, name, 80);
    at_count.at("header", -1, "triangle count");
    at_count.fail("binary STL header declares " + count_of(count, "triangle", "triangles") + " (" +
                  std::to_string(kBinaryHeaderBytes + kBinaryTriangleBytes * std::uint64_t{count}) +
                  " bytes) but the file has " + std::to_string(data.size()) + " bytes; " + why);
}

Mesh read_binary(std::string_view data, const std::string& name, std::uint32_t count,
                 ReadReport& report, MeshAttributes& attributes)
{
    report.encoding = Encoding::BinaryLittleEndian;
    if (3 * std::int64_t{count} > kMaxVertices) // welded vertices <= corners
    {
        ByteReader bytes(data, name, 80);
        bytes.at("header", -1, "triangle count");
        bytes.fail("binary STL declares " + std::to_string(count) +
                   " triangles, more than MeshFair supports");
    }
    Mesh mesh;
    // The caller checked the file size against the count, so these are bounded by it.
    mesh.face_offsets.reserve(size_t{count} + 1);
    mesh.face_vertices.reserve(3 * size_t{count});
    Welder welder(mesh, 3 * size_t{count});
    ByteReader bytes(data, name, kBinaryHeaderBytes);
    // The two attribute bytes of each triangle (some exporters store a colour there),
    // kept when any is not zero.
    std::vector<double> attribute_bytes;
    attribute_bytes.reserve(count);
    bool any_attribute = false;
    std::vector<Index> face(3);
    for (std::int64_t t = 0; t < count; ++t)
    {
        const size_t start = bytes.offset();
        face.resize(3);
        bytes.skip(12); // the normal is recomputed from the corners by anyone who needs it
        for (int k = 0; k < 3; ++k)
        {
            float p[3];
            for (int c = 0; c < 3; ++c)
            {
                p[c] = bytes.read<float>(ByteOrder::Little);
                if (!std::isfinite(p[c]))
                {
                    ByteReader here(data, name, bytes.offset() - sizeof(float));
                    here.at("triangle", t, "vertex " + std::to_string(k) + " " + "xyz"[c]);
                    here.fail(std::string("coordinate is ") +
                              (std::isnan(p[c]) ? "NaN" : "infinite"));
                }
            }
            face[static_cast<size_t>(k)] = welder.add(p[0], p[1], p[2]);
        }
        const std::uint16_t attribute = bytes.read<std::uint16_t>(ByteOrder::Little);
        any_attribute = any_attribute || attribute != 0;
        attribute_bytes.push_back(attribute);
        const FaceCheck check = normalize_face(face);
        if (!check.ok)
        {
            ByteReader at_start(data, name, start);
            at_start.at("triangle", t, "");
            at_start.fail(check.problem + " once equal positions are welded");
        }
        mesh.add_face(face);
    }
    report_welding(welder, mesh, report);
    if (any_attribute)
    {
        attributes.face.count = static_cast<Index>(count);
        attributes.face.properties.push_back(Property{std::string(kStlAttribute),
                                                      ValueType::UInt16,
                                                      false,
                                                      ValueType::UInt8,
                                                      std::move(attribute_bytes),
                                                      {}});
    }
    return mesh;
}

// ---- ASCII --------------------------------------------------------------------------

// The whitespace-separated tokens of a text file across lines; errors name the line
// and column of the current token.
class TokenStream
{
public:
    TokenStream(std::string_view data, const std::string& name) : reader_(data, name) {}

    //! The next token, or an empty view at the end of the file.
    std::string_view next()
    {
        for (;;)
        {
            const std::string_view t = tokens_.next();
            if (!t.empty())
                return t;
            if (!reader_.next())
                return {};
            tokens_ = Tokenizer(reader_.line());
        }
    }
    //! Drops what is left of the current line (a solid's name).
    void skip_line() { tokens_ = Tokenizer({}); }
    const LineReader& reader() const { return reader_; }

private:
    LineReader reader_;
    Tokenizer tokens_{{}};
};

// Normals are ignored; exporters write nan for degenerate facets, so any spelling of a
// number is accepted here.
void skip_normal_value(const LineReader& reader, std::string_view token)
{
    std::string_view s = token;
    if (!s.empty() && (s.front() == '+' || s.front() == '-'))
        s.remove_prefix(1);
    if (equals_ignoring_case(s, "nan") || equals_ignoring_case(s, "inf") ||
        equals_ignoring_case(s, "infinity"))
        return;
    parse_double(reader, token, "normal component");
}

class AsciiStl
{
public:
    AsciiStl(std::string_view data, const std::string& name, ReadReport& report)
        : tokens_(data, name), reader_(tokens_.reader()), welder_(mesh_, 0), report_(report)
    {
    }

    Mesh read()
    {
        std::int64_t solids = 0;
        for (std::string_view t = tokens_.next(); !t.empty(); t = tokens_.next())
        {
            if (!equals_ignoring_case(t, "solid"))
                reader_.fail_at(t, "expected 'solid' or the end of the file, found " + quoted(t));
            ++solids;
            tokens_.skip_line();
            while (read_facet())
            {
            }
        }
        report_welding(welder_, mesh_, report_);
        if (solids > 1)
            report_.notes.push_back("concatenated " + std::to_string(solids) +
                                    " solids in file order");
        return std::move(mesh_);
    }

private:
    // Reads one facet; false after the solid's 'endsolid'.
    bool read_facet()
    {
        const std::string_view t = tokens_.next();
        if (t.empty())
            reader_.fail("file ends inside solid (no endsolid)");
        if (equals_ignoring_case(t, "endsolid"))
        {
            tokens_.skip_line();
            return false;
        }
        if (!equals_ignoring_case(t, "facet"))
            reader_.fail_at(t, "expected 'facet' or 'endsolid', found " + quoted(t));
        const std::int64_t facet = mesh_.face_count(), line = reader_.line_number(),
                           column = reader_.column_of(t);
        expect("normal", facet);
        for (int c = 0; c < 3; ++c)
            skip_normal_value(reader_, in_facet(facet));
        expect("outer", facet);
        expect("loop", facet);
        face_.clear();
        for (std::string_view k = in_facet(facet); !equals_ignoring_case(k, "endloop");
             k = in_facet(facet))
        {
            if (!equals_ignoring_case(k, "vertex"))
                reader_.fail_at(k, "expected 'vertex' or 'endloop', found " + quoted(k));
            // An STL facet is a triangle (every exporter writes three corners): a fourth
            // is a damaged or hand-edited file, not a polygon to guess the meaning of.
            if (face_.size() == 3)
                reader_.fail_at(k, "facet " + std::to_string(facet) +
                                       " has more than 3 vertices (an STL facet is a triangle)");
            const double x = parse_double(reader_, in_facet(facet), "x coordinate");
            const double y = parse_double(reader_, in_facet(facet), "y coordinate");
            const double z = parse_double(reader_, in_facet(facet), "z coordinate");
            if (mesh_.face_vertices.size() + face_.size() >= static_cast<size_t>(kMaxVertices))
                reader_.fail("more facet corners than MeshFair supports");
            face_.push_back(welder_.add(x, y, z));
        }
        if (face_.size() < 3)
            reader_.fail("facet " + std::to_string(facet) + " has " +
                         count_of(static_cast<std::int64_t>(face_.size()), "vertex", "vertices") +
                         " (an STL facet is a triangle)");
        expect("endfacet", facet);
        const auto where = SourceLocation::text(reader_.file(), line, column);
        // Of a triangle's corners, a repeated one leaves fewer than three: refused, never
        // collapsed.
        const FaceCheck check = normalize_face(face_);
        if (!check.ok)
            throw FormatError(where, "facet " + std::to_string(facet) + ": " + check.problem +
                                         " once equal positions are welded");
        mesh_.add_face(face_);
        return true;
    }

    std::string_view in_facet(std::int64_t facet)
    {
        const std::string_view t = tokens_.next();
        if (t.empty())
            reader_.fail("file ends inside facet " + std::to_string(facet) + " (no endfacet)");
        return t;
    }

    void expect(std::string_view keyword, std::int64_t facet)
    {
        const std::string_view t = in_facet(facet);
        if (!equals_ignoring_case(t, keyword))
            reader_.fail_at(t, "expected " + quoted(keyword) + ", found " + quoted(t));
    }

    TokenStream tokens_;
    const LineReader& reader_;
    Mesh mesh_;
    Welder welder_;
    ReadReport& report_;
    std::vector<Index> face_;
};

} // namespace

Mesh read_stl(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes)
{
    attributes = MeshAttributes{};
    report.format = Format::Stl;
    report.encoding = Encoding::Ascii;
    if (data.empty())
        throw FormatError(SourceLocation::whole(name), "empty file");
    // Binary files often start with "solid" too: a size that matches the declared
    // triangle count decides first.
    if (data.size() >= kBinaryHeaderBytes)
    {
        const auto count = ByteReader(data, name, 80).read<std::uint32_t>(ByteOrder::Little);
        if (data.size() == kBinaryHeaderBytes + kBinaryTriangleBytes * std::uint64_t{count})
            return read_binary(data, name, count, report, attributes);
    }
    if (!starts_with_solid(data))
        fail_binary_size(data, name,
                         "the file does not start with 'solid', so it is not ASCII STL");
    // Binary headers are usually padded with NUL bytes and the triangle count almost
    // always holds one; text never does. Such a file is binary with a wrong size. A NUL
    // further on is left to the text reader, which names its line.
    if (std::memchr(data.data(), '\0', std::min(data.size(), kBinaryHeaderBytes)) != nullptr)
        fail_binary_size(data, name, "the file holds NUL bytes, so it is not ASCII STL");
    return AsciiStl(data, name, report).read();
}

} // namespace meshfair::io
