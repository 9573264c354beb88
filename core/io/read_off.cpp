// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_off.h"

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/attributes.h"
#include "core/io/face_builder.h"
#include "core/io/text_reader.h"

namespace meshfair::io {

namespace {

// The shortest vertex line ("0 0 0\n") and face line ("3 0 1 2\n"): a header whose
// counts need more bytes than follow it is refused before anything is allocated.
constexpr std::int64_t kMinVertexBytes = 6;
constexpr std::int64_t kMinFaceBytes = 8;

// The lines of an OFF file that hold data: '#' starts a comment anywhere on a line,
// and lines left blank are skipped.
class OffLines
{
public:
    OffLines(std::string_view data, const std::string& name) : reader_(data, name) {}

    //! Moves to the next line holding data; false at the end of the file.
    bool next()
    {
        while (reader_.next())
        {
            const std::string_view line = reader_.line();
            content_ = line.substr(0, line.find('#'));
            if (!Tokenizer(content_).at_end())
                return true;
        }
        return false;
    }
    //! The current line without its comment; a view into reader().line().
    std::string_view content() const { return content_; }
    const LineReader& reader() const { return reader_; }

private:
    LineReader reader_;
    std::string_view content_;
};

// What the header keyword [ST][C][N]OFF adds to each vertex line, in file order
// (normals, then colours, then texture coordinates).
struct OffVariant
{
    std::string keyword;
    bool has_normals = false;
    bool has_colours = false;
    bool has_texture = false;

    // Values a vertex line needs at least: x y z [nx ny nz] [r g b [a]] [s t].
    int min_values() const
    {
        return 3 + (has_normals ? 3 : 0) + (has_colours ? 3 : 0) + (has_texture ? 2 : 0);
    }
    std::string value_names() const
    {
        std::string s = "x y z";
        if (has_normals)
            s += " nx ny nz";
        if (has_colours)
            s += " r g b";
        if (has_texture)
            s += " s t";
        return s;
    }
};

// Geomview's keyword is [ST][C][N][4][n]OFF; C and N are accepted in either order.
OffVariant parse_keyword(const LineReader& reader, std::string_view token)
{
    OffVariant v;
    v.keyword = std::string(token);
    const auto refuse = [&] {
        reader.fail_at(token,
                       "expected an OFF header keyword ([ST][C][N]OFF), found " + quoted(token));
    };
    if (!token.ends_with("OFF"))
        refuse();
    std::string_view prefix = token.substr(0, token.size() - 3);
    if (prefix.starts_with("ST"))
    {
        v.has_texture = true;
        prefix.remove_prefix(2);
    }
    for (int k = 0; k < 2 && !prefix.empty(); ++k)
    {
        if (prefix.front() == 'C' && !v.has_colours)
            v.has_colours = true;
        else if (prefix.front() == 'N' && !v.has_normals)
            v.has_normals = true;
        else
            break;
        prefix.remove_prefix(1);
    }
    if (prefix == "4" || prefix == "n" || prefix == "4n")
        reader.fail_at(token, quoted(token) + ": " +
                                  (prefix == "4" ? std::string("4-D vertices")
                                                 : std::string("vertices of any dimension")) +
                                  " are not supported (MeshFair reads 3-D OFF)");
    if (!prefix.empty())
        refuse();
    return v;
}

std::int64_t parse_count(const LineReader& reader, std::string_view token, const char* what)
{
    const std::int64_t value = parse_integer(reader, token, what);
    if (value < 0)
        reader.fail_at(token, std::string(what) + " " + std::to_string(value) + " is negative");
    return value;
}

struct OffHeader
{
    OffVariant variant;
    std::int64_t vertices = 0;
    std::int64_t faces = 0;
};

OffHeader parse_header(OffLines& lines, std::string_view data)
{
    const LineReader& reader = lines.reader();
    if (!lines.next())
    {
        const SourceLocation where = SourceLocation::whole(reader.file());
        if (data.empty())
            throw FormatError(where, "empty file");
        throw FormatError(where, "no OFF header (the file holds only comments and blank lines)");
    }
    OffHeader h;
    Tokenizer tokens(lines.content());
    h.variant = parse_keyword(reader, tokens.next());
    // The counts may follow the keyword on its line or come on the next data line.
    std::string_view token = tokens.next();
    if (equals_ignoring_case(token, "BINARY"))
        reader.fail_at(token, "binary OFF ('" + h.variant.keyword +
                                  " BINARY') is not supported; convert it to ASCII OFF");
    if (token.empty())
    {
        if (!lines.next())
            reader.fail("the file ends before the counts 'nv nf ne' that follow the header");
        tokens = Tokenizer(lines.content());
        token = tokens.next();
    }
    const std::string_view vertex_token = token, face_token = tokens.next();
    h.vertices = parse_count(reader, vertex_token, "vertex count");
    h.faces = parse_count(reader, face_token, "face count");
    // The edge count is optional and unused; when present it must still be a count.
    if (const std::string_view edges = tokens.next(); !edges.empty())
        parse_count(reader, edges, "edge count");
    if (!tokens.at_end())
    {
        const std::string_view extra = tokens.next();
        reader.fail_at(extra, "unexpected " + quoted(extra) + " after the counts 'nv nf ne'");
    }
    // The first two tests bound each count by the bytes left, so the sum cannot overflow.
    const auto bytes = static_cast<std::int64_t>(reader.remaining_bytes());
    const bool impossible = h.vertices > (bytes + 1) / kMinVertexBytes ||
                            h.faces > (bytes + 1) / kMinFaceBytes ||
                            (h.vertices + h.faces > 0 &&
                             h.vertices * kMinVertexBytes + h.faces * kMinFaceBytes - 1 > bytes);
    if (impossible)
        reader.fail("header declares " + count_of(h.vertices, "vertex", "vertices") + " and " +
                    count_of(h.faces, "face", "faces") + " but only " +
                    count_of(bytes, "byte follows", "bytes follow") +
                    " (a vertex line takes at least 6 bytes, a face line 8)");
    if (h.vertices > kMaxVertices)
        reader.fail_at(vertex_token, "vertex count " + std::to_string(h.vertices) +
                                         " is more than MeshFair supports (" +
                                         std::to_string(kMaxVertices) + ")");
    if (h.faces > kMaxElements)
        reader.fail_at(face_token, "face count " + std::to_string(h.faces) +
                                       " is more than MeshFair supports (" +
                                       std::to_string(kMaxElements) + ")");
    return h;
}

// Colour values as read, and whether every one was an integer in 0..255 (Geomview's
// integer colours) rather than a fraction in 0..1.
struct ColourColumns
{
    std::vector<double> values[4]; // r g b a, one per row
    bool integers = true;
    std::int64_t with_alpha = 0;

    void add(const LineReader& reader, std::string_view token, int channel, const char* what)
    {
        const double v = parse_double(reader, token, what);
        integers =
            integers && token.find_first_of(".eE") == std::string_view::npos && v >= 0 && v <= 255;
        values[channel].push_back(v);
        if (channel == 3)
            ++with_alpha;
    }
    // Red, green, blue (and alpha, when any row has one: opaque where a row has none)
    // appended to `table`, as uchar for integer colours, else double.
    void keep(Element& table, std::int64_t rows)
    {
        const ValueType type = integers ? ValueType::UInt8 : ValueType::Float64;
        const char* names[] = {"red", "green", "blue", "alpha"};
        for (int c = 0; c < (with_alpha > 0 ? 4 : 3); ++c)
        {
            Property p{names[c], type, false, ValueType::UInt8, std::move(values[c]), {}};
            p.values.resize(static_cast<size_t>(rows), std::numeric_limits<double>::quiet_NaN());
            for (double& v : p.values)
                if (std::isnan(v))
                    v = integers ? 255.0 : 1.0;
            table.properties.push_back(std::move(p));
        }
    }
};

// Remembers how many lines carried something that is ignored, and the first one.
struct Ignored
{
    std::int64_t lines = 0;
    std::string first;
    void add(const LineReader& reader)
    {
        if (lines++ == 0)
            first = reader.here().to_string();
    }
};

[[noreturn]] void fail_truncated(const LineReader& reader, std::int64_t expected,
                                 std::int64_t found, const char* singular, const char* plural)
{
    reader.fail("expected " + count_of(expected, singular, plural) + ", the file ends after " +
                std::to_string(found));
}

void read_vertices(OffLines& lines, const OffHeader& h, Mesh& mesh, Ignored& extra, Element& table)
{
    const LineReader& reader = lines.reader();
    const int needed = h.variant.min_values();
    mesh.positions.reserve(static_cast<size_t>(3 * h.vertices));
    const OffVariant& variant = h.variant;
    std::vector<double> normals[3], texture[2];
    ColourColumns colours;
    std::string_view values[16];
    for (std::int64_t i = 0; i < h.vertices; ++i)
    {
        if (!lines.next())
            fail_truncated(reader, h.vertices, i, "vertex", "vertices");
        Tokenizer tokens(lines.content());
        for (const char* axis : {"x", "y", "z"})
        {
            const std::string_view t = tokens.next();
            if (t.empty())
                reader.fail(std::string("vertex has no ") + axis + " coordinate");
            mesh.positions.push_back(parse_double(reader, t, std::string(axis) + " coordinate"));
        }
        // Normals, colours and texture coordinates after x y z, in that order; every
        // value must be a number, also those beyond what the keyword declares.
        int count = 3;
        for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next(), ++count)
        {
            if (count - 3 < static_cast<int>(std::size(values)))
                values[count - 3] = t;
            else
                parse_double(reader, t, "vertex value");
        }
        if (count < needed)
            reader.fail("vertex has " + std::to_string(count) + " values but " + variant.keyword +
                        " needs at least " + std::to_string(needed) + " (" + variant.value_names() +
                        ")");
        // A colour may have an alpha value; anything beyond that is undeclared.
        const bool alpha = variant.has_colours && count > needed;
        if (count > needed + (alpha ? 1 : 0))
            extra.add(reader);
        int k = 0;
        if (variant.has_normals)
            for (std::vector<double>& n : normals)
                n.push_back(parse_double(reader, values[k++], "normal value"));
        if (variant.has_colours)
            for (int c = 0; c < (alpha ? 4 : 3); ++c)
            {
                if (c == 3) // rows before without alpha: opaque (ColourColumns::keep)
                    colours.values[3].resize(static_cast<size_t>(i),
                                             std::numeric_limits<double>::quiet_NaN());
                colours.add(reader, values[k++], c, "vertex colour value");
            }
        if (variant.has_texture)
            for (std::vector<double>& t : texture)
                t.push_back(parse_double(reader, values[k++], "texture coordinate"));
        for (; k < count - 3 && k < static_cast<int>(std::size(values)); ++k)
            parse_double(reader, values[k], "vertex value");
    }
    table.count = static_cast<Index>(h.vertices);
    const auto keep = [&](const char* name, std::vector<double>& column) {
        table.properties.push_back(
            Property{name, ValueType::Float64, false, ValueType::UInt8, std::move(column), {}});
    };
    if (variant.has_normals)
        for (int a = 0; a < 3; ++a)
            keep(std::array{"nx", "ny", "nz"}[static_cast<size_t>(a)], normals[a]);
    if (variant.has_colours)
        colours.keep(table, h.vertices);
    if (variant.has_texture)
    {
        keep("texture_u", texture[0]);
        keep("texture_v", texture[1]);
    }
}

void read_faces(OffLines& lines, const OffHeader& h, Mesh& mesh, ReadReport& report, Element& table)
{
    const LineReader& reader = lines.reader();
    mesh.face_offsets.reserve(static_cast<size_t>(h.faces + 1));
    mesh.face_vertices.reserve(static_cast<size_t>(3 * h.faces));
    NoteCounter collapsed;
    Ignored coloured;
    // A face's colour: 1 value (a colour map index) or 3 or 4 (r g b [a]); kept when every
    // face gives the same kind.
    ColourColumns colours;
    std::vector<double> colour_index;
    int colour_values = -1; // of the first face; -2 once faces differ
    std::vector<Index> face;
    for (std::int64_t f = 0; f < h.faces; ++f)
    {
        if (!lines.next())
            fail_truncated(reader, h.faces, f, "face", "faces");
        Tokenizer tokens(lines.content());
        const std::string_view size_token = tokens.next();
        const std::int64_t n = parse_integer(reader, size_token, "face vertex count");
        if (n < 0)
            reader.fail_at(size_token, "face vertex count " + std::to_string(n) + " is negative");
        if (n < 3)
            reader.fail_at(size_token, "face has " + count_of(n, "vertex", "vertices") +
                                           " (a face needs at least 3)");
        face.clear();
        for (std::int64_t k = 0; k < n; ++k)
        {
            const std::string_view t = tokens.next();
            if (t.empty())
                reader.fail("face declares " + std::to_string(n) + " vertices but lists " +
                            std::to_string(k));
            const std::int64_t index = parse_integer(reader, t, "vertex index");
            if (index < 0)
                reader.fail_at(t, "vertex index " + std::to_string(index) +
                                      " is negative (OFF indices start at 0)");
            if (index >= h.vertices)
                reader.fail_at(
                    t, "vertex index " + std::to_string(index) + " is out of range (the file has " +
                           count_of(h.vertices, "vertex", "vertices") + ", numbered from 0)");
            face.push_back(static_cast<Index>(index));
        }
        // A face colour (an index or 3-4 values) may follow; it must be numbers.
        int values = 0;
        if (!tokens.at_end())
            coloured.add(reader);
        for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next(), ++values)
        {
            if (values < 4)
                colours.add(reader, t, values, "face colour value");
            else
                parse_double(reader, t, "face colour value");
        }
        colour_values = colour_values == -1 || colour_values == values ? values : -2;
        const auto where = reader.here();
        const FaceCheck check = normalize_face(face);
        if (!check.ok)
            throw FormatError(where, check.problem);
        collapsed.add(check.collapsed, where.to_string());
        if (mesh.face_vertices.size() + face.size() > static_cast<size_t>(kMaxElements))
            reader.fail("more face corners than MeshFair supports");
        mesh.add_face(face);
    }
    report_collapsed(collapsed, report.notes);
    table.count = static_cast<Index>(h.faces);
    if (colour_values == 1)
        table.properties.push_back(Property{"colormap_index",
                                            ValueType::Float64,
                                            false,
                                            ValueType::UInt8,
                                            std::move(colours.values[0]),
                                            {}});
    else if (colour_values == 3 || colour_values == 4)
        colours.keep(table, h.faces);
    else if (coloured.lines > 0)
        report.notes.push_back("ignored the colours of " +
                               count_of(coloured.lines, "face", "faces") + " (first at " +
                               coloured.first + "): faces give " +
                               (colour_values == -2 ? "different numbers of colour values"
                                                    : "other than 1, 3 or 4 colour values") +
                               " (kept when every face gives 1, 3 or 4)");
}

} // namespace

Mesh read_off(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes)
{
    attributes = MeshAttributes{};
    report.format = Format::Off;
    report.encoding = Encoding::Ascii;
    OffLines lines(data, name);
    const OffHeader h = parse_header(lines, data);
    Mesh mesh;
    Ignored extra;
    read_vertices(lines, h, mesh, extra, attributes.vertex);
    read_faces(lines, h, mesh, report, attributes.face);
    for (Element* table : {&attributes.vertex, &attributes.face})
        if (table->properties.empty())
            table->count = 0;
    if (lines.next())
    {
        Tokenizer tokens(lines.content());
        const char* after = h.faces > 0      ? "the last face"
                            : h.vertices > 0 ? "the last vertex"
                                             : "the counts";
        lines.reader().fail_at(tokens.next(), std::string("unexpected data after ") + after +
                                                  " (the header declares " +
                                                  count_of(h.vertices, "vertex", "vertices") +
                                                  " and " + count_of(h.faces, "face", "faces") +
                                                  ")");
    }
    if (extra.lines > 0)
        report.notes.push_back("ignored undeclared extra values on " +
                               count_of(extra.lines, "vertex line", "vertex lines") +
                               " (first at " + extra.first + ")");
    return mesh;
}

} // namespace meshfair::io
