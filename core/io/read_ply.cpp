// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_ply.h"

#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/errors.h"
#include "core/io/attributes.h"
#include "core/io/byte_reader.h"
#include "core/io/face_builder.h"
#include "core/io/text_reader.h"

namespace meshfair::io {

namespace {

// The eight PLY value types, in the order of kTypes.
using Type = ValueType;

struct TypeInfo
{
    std::string_view name, sized_name; // both spellings PLY writers use
    size_t size;
    bool is_integer;
    std::int64_t min, max; // integer types only
};

constexpr TypeInfo kTypes[] = {
    {"char", "int8", 1, true, -128, 127},
    {"uchar", "uint8", 1, true, 0, 255},
    {"short", "int16", 2, true, -32768, 32767},
    {"ushort", "uint16", 2, true, 0, 65535},
    {"int", "int32", 4, true, -2147483648LL, 2147483647},
    {"uint", "uint32", 4, true, 0, 4294967295LL},
    {"float", "float32", 4, false, 0, 0},
    {"double", "float64", 8, false, 0, 0},
};

const TypeInfo& info(Type type)
{
    return kTypes[static_cast<int>(type)];
}

// Doubles at or above this magnitude round to infinity as a float32 (halfway between
// FLT_MAX and 2^128 rounds to even, which is 2^128).
constexpr double kFloatOverflow = 0x1.ffffffp+127;

enum class Kind
{
    Vertex,
    Face,
    Strips, // 'tristrips': triangle strips, -1 between strips (Stanford's range scans)
    Other
};

struct PropertyDecl
{
    std::string name;
    Type type = Type::Int8; // the scalar type, or the type of a list's items
    std::string type_name;  // as declared, for messages
    bool is_list = false;
    Type count_type = Type::UInt8;
    std::string count_type_name;
    std::int64_t line = 0;    // header line declaring it
    std::int64_t column = 0;  // and the column of its 'property' keyword
    int axis = -1;            // 0, 1, 2 for the vertex coordinates x, y, z
    bool is_indices = false;  // the face's (or the strips') vertex index list
    std::string what;         // names one value in messages: "x coordinate", "'red' value"
    std::string count_what;   // "'vertex_indices' list count"
    Property* kept = nullptr; // where the values go, for a property kept as an attribute
};

struct ElementDecl
{
    std::string name;
    Kind kind = Kind::Other;
    std::int64_t count = 0;
    std::vector<PropertyDecl> properties;
    std::unordered_set<std::string> property_names; // for the duplicate check
    std::int64_t line = 0;                          // header line declaring it
    std::int64_t column = 0;                        // and the column of its 'element' keyword
    std::int64_t count_column = 0;
};

struct Header
{
    Encoding encoding = Encoding::Ascii;
    std::vector<ElementDecl> elements;
    std::vector<std::string> comments; // comment and obj_info lines, as written
    size_t data_offset = 0;            // first byte after end_header's line terminator
};

std::string row_name(const ElementDecl& element, std::int64_t row)
{
    return element.name + " " + std::to_string(row);
}

// Header lines come from a file that may be binary after end_header: a NUL there most
// likely means end_header is missing.
bool next_header_line(LineReader& reader)
{
    try
    {
        return reader.next();
    }
    catch (const FormatError& e)
    {
        throw FormatError(e.where(),
                          e.message() + " (inside the PLY header; is end_header missing?)");
    }
}

Type parse_type(const LineReader& reader, std::string_view token)
{
    for (size_t k = 0; k < std::size(kTypes); ++k)
        if (kTypes[k].name == token || kTypes[k].sized_name == token)
            return static_cast<Type>(k);
    reader.fail_at(token, "unknown property type " + quoted(token));
}

void parse_format(const LineReader& reader, Tokenizer& tokens, Header& h)
{
    const std::string_view kind = tokens.next();
    const std::string_view version = tokens.next();
    const bool is_known =
        kind == "ascii" || kind == "binary_little_endian" || kind == "binary_big_endian";
    if (kind.empty() || !is_known || version != "1.0" || !tokens.at_end())
    {
        std::string_view rest = reader.line().substr(
            kind.empty() ? reader.line().size() : kind.data() - reader.line().data());
        while (!rest.empty() && is_blank(rest.back()))
            rest.remove_suffix(1);
        reader.fail("unknown PLY format " + quoted(rest) +
                        " (expected ascii, binary_little_endian or binary_big_endian, version 1.0)",
                    kind.empty() ? 0 : reader.column_of(kind));
    }
    h.encoding = kind == "ascii"                  ? Encoding::Ascii
                 : kind == "binary_little_endian" ? Encoding::BinaryLittleEndian
                                                  : Encoding::BinaryBigEndian;
}

void parse_element(const LineReader& reader, Tokenizer& tokens, Header& h)
{
    const std::string_view name = tokens.next();
    const std::string_view count = tokens.next();
    if (count.empty() || !tokens.at_end())
        reader.fail("an element line must be 'element NAME COUNT'");
    ElementDecl e;
    e.name = std::string(name);
    e.kind = name == "vertex"      ? Kind::Vertex
             : name == "face"      ? Kind::Face
             : name == "tristrips" ? Kind::Strips
                                   : Kind::Other;
    e.count = parse_integer(reader, count, "element count");
    if (e.count < 0)
        reader.fail_at(count, "element count " + std::to_string(e.count) + " is negative");
    // Only the vertex, face and tristrips elements must be unique: one scan each.
    if (e.kind != Kind::Other)
        for (const ElementDecl& other : h.elements)
            if (other.name == e.name)
                reader.fail_at(name,
                               "second '" + e.name + "' element (a PLY mesh has at most one)");
    e.line = reader.line_number();
    e.column = reader.here().column;
    e.count_column = reader.column_of(count);
    h.elements.push_back(std::move(e));
}

void parse_property(const LineReader& reader, Tokenizer& tokens, ElementDecl& e)
{
    PropertyDecl p;
    p.line = reader.line_number();
    p.column = reader.here().column;
    std::string_view first = tokens.next();
    std::string_view name;
    if (first == "list")
    {
        const std::string_view count_type = tokens.next();
        const std::string_view item_type = tokens.next();
        name = tokens.next();
        if (name.empty() || !tokens.at_end())
            reader.fail("a list property line must be 'property list COUNT_TYPE ITEM_TYPE NAME'");
        p.is_list = true;
        p.count_type = parse_type(reader, count_type);
        p.count_type_name = std::string(count_type);
        if (!info(p.count_type).is_integer)
            reader.fail_at(count_type,
                           "list count type " + quoted(count_type) + " is not an integer type");
        first = item_type;
    }
    else
    {
        name = tokens.next();
        if (name.empty() || !tokens.at_end())
            reader.fail("a property line must be 'property TYPE NAME'");
    }
    p.type = parse_type(reader, first);
    p.type_name = std::string(first);
    p.name = std::string(name);
    // A set, not a scan: headers with many thousands of properties stay linear.
    if (!e.property_names.insert(p.name).second)
        reader.fail_at(name, "element '" + e.name + "' already has a property " + quoted(name));
    p.what = "'" + p.name + "' value";
    p.count_what = "'" + p.name + "' list count";
    e.properties.push_back(std::move(p));
}

Header parse_header(LineReader& reader, std::string_view data)
{
    Header h;
    if (!next_header_line(reader))
        reader.fail("not a PLY file (the file is empty)");
    Tokenizer magic(reader.line());
    if (magic.next() != "ply" || !magic.at_end())
        reader.fail("not a PLY file (the first line must be 'ply')");
    // A header with CR-only line ends may be followed by binary data starting with LF,
    // which LineReader would take for the second half of a CRLF.
    const size_t first_end =
        static_cast<size_t>(reader.line().data() - data.data()) + reader.line().size();
    const bool is_cr_only =
        first_end + 1 < data.size() && data[first_end] == '\r' && data[first_end + 1] != '\n';
    bool has_format = false;
    while (next_header_line(reader))
    {
        Tokenizer tokens(reader.line());
        const std::string_view keyword = tokens.next();
        if (keyword.empty())
            continue;
        if (keyword == "comment" || keyword == "obj_info")
        {
            std::string_view line =
                reader.line().substr(static_cast<size_t>(keyword.data() - reader.line().data()));
            while (!line.empty() && is_blank(line.back()))
                line.remove_suffix(1);
            h.comments.emplace_back(line);
            continue;
        }
        if (keyword == "end_header")
        {
            if (!tokens.at_end())
                reader.fail_at(tokens.next(), "unexpected text after end_header");
            if (!has_format)
                reader.fail("no format line before end_header");
            const size_t end =
                static_cast<size_t>(reader.line().data() - data.data()) + reader.line().size();
            h.data_offset = is_cr_only && end < data.size() ? end + 1 : reader.consumed();
            return h;
        }
        if (keyword == "format")
        {
            if (has_format)
                reader.fail_at(keyword, "second format line");
            parse_format(reader, tokens, h);
            has_format = true;
        }
        else if (keyword == "element")
        {
            if (!has_format)
                reader.fail_at(keyword, "element before the format line");
            parse_element(reader, tokens, h);
        }
        else if (keyword == "property")
        {
            if (h.elements.empty())
                reader.fail_at(keyword, "property before the first element");
            parse_property(reader, tokens, h.elements.back());
        }
        else
        {
            reader.fail_at(keyword, "unknown header keyword " + quoted(keyword));
        }
    }
    reader.fail("no end_header (the file ends inside the header)");
}

// Fails at the header line of `declared` (an ElementDecl or a PropertyDecl).
template <typename Declared>
[[noreturn]] void fail_line(const std::string& file, const Declared& declared,
                            const std::string& message)
{
    throw FormatError(SourceLocation::text(file, declared.line, declared.column), message);
}

// Gives each property of the vertex and face elements its role, refusing elements
// MeshFair cannot read.
void assign_roles(Header& h, const std::string& file)
{
    for (ElementDecl& e : h.elements)
    {
        const auto find = [&](std::string_view name) -> PropertyDecl* {
            for (PropertyDecl& p : e.properties)
                if (p.name == name)
                    return &p;
            return nullptr;
        };
        if (e.kind == Kind::Vertex)
        {
            for (const int axis : {0, 1, 2})
            {
                const std::string name(1, "xyz"[axis]);
                PropertyDecl* p = find(name);
                if (!p)
                    fail_line(file, e, "vertex element has no property '" + name + "'");
                if (p->is_list)
                    fail_line(file, *p,
                              "vertex property '" + p->name + "' is a list, not a coordinate");
                p->axis = axis;
                p->what = p->name + " coordinate";
            }
        }
        else if (e.kind == Kind::Face || e.kind == Kind::Strips)
        {
            PropertyDecl* p = find("vertex_indices");
            PropertyDecl* alias = find("vertex_index");
            if (p && alias)
                fail_line(file, *alias,
                          e.name + " element has both 'vertex_indices' and 'vertex_index'");
            p = p ? p : alias;
            if (!p)
                fail_line(file, e,
                          e.name +
                              " element has no list property 'vertex_indices' (or "
                              "'vertex_index')");
            if (!p->is_list)
                fail_line(file, *p, e.name + " property '" + p->name + "' is not a list");
            if (!info(p->type).is_integer)
                fail_line(file, *p,
                          e.name + " property '" + p->name + "' has item type '" + p->type_name +
                              "' (vertex indices must be integers)");
            p->is_indices = true;
            p->what = "vertex index";
        }
    }
}

std::string rows_of(const ElementDecl& e)
{
    return e.kind == Kind::Vertex ? "vertices"
           : e.kind == Kind::Face ? "faces"
                                  : "rows of element '" + e.name + "'";
}

// Refuses element counts the data cannot hold before anything is allocated for them.
// A row takes at least its scalars and list counts in binary, and in ASCII one
// character and one separator per property (the last row needs no line end).
void check_counts(const Header& h, const std::string& file, size_t available)
{
    for (const ElementDecl& e : h.elements)
    {
        std::uint64_t min_row = 0;
        for (const PropertyDecl& p : e.properties)
            min_row +=
                h.encoding != Encoding::Ascii ? info(p.is_list ? p.count_type : p.type).size : 2;
        const std::uint64_t room = h.encoding == Encoding::Ascii ? available + 1 : available;
        const auto where = SourceLocation::text(file, e.line, e.count_column);
        if (min_row > 0 && static_cast<std::uint64_t>(e.count) > room / min_row)
            throw FormatError(where, "header declares " + std::to_string(e.count) + " " +
                                         rows_of(e) + " but only " + std::to_string(available) +
                                         " bytes follow");
        const std::int64_t limit = e.kind == Kind::Vertex ? kMaxVertices : kMaxElements;
        if (e.count > limit)
            throw FormatError(where, "element '" + e.name + "' has " + std::to_string(e.count) +
                                         " rows (MeshFair supports at most " +
                                         std::to_string(limit) + ")");
    }
}

// Rows of an ASCII body: one row per line, values as whitespace-separated tokens.
class AsciiRows
{
public:
    explicit AsciiRows(LineReader& reader) : reader_(reader) {}

    void begin_row(const ElementDecl& e, std::int64_t row)
    {
        element_ = &e;
        row_ = row;
        do
        {
            if (!reader_.next())
                reader_.fail("file ends before " + row_name(e, row) + " (the header declares " +
                             std::to_string(e.count) + " " + rows_of(e) + ")");
            tokens_ = Tokenizer(reader_.line());
        } while (tokens_.at_end());
    }

    void end_row()
    {
        if (!tokens_.at_end())
        {
            const std::string_view token = tokens_.next();
            reader_.fail_at(token, "unexpected value " + quoted(token) +
                                       " after the last property of " + row_name(*element_, row_));
        }
    }

    std::int64_t count(const PropertyDecl& p)
    {
        const std::int64_t n = integer(p, p.count_type, p.count_type_name, p.count_what);
        if (n < 0)
            reader_.fail_at(last_, p.count_what + " " + std::to_string(n) + " is negative");
        Tokenizer rest = tokens_;
        std::int64_t left = 0;
        while (!rest.next().empty())
            ++left;
        if (n > left)
            reader_.fail_at(last_, p.count_what + " " + std::to_string(n) + " is more than the " +
                                       count_of(left, "value", "values") + " left on the line");
        return n;
    }

    std::int64_t index(const PropertyDecl& p) { return integer(p, p.type, p.type_name, p.what); }

    double number(const PropertyDecl& p)
    {
        if (info(p.type).is_integer)
            return static_cast<double>(integer(p, p.type, p.type_name, p.what));
        const std::string_view token = take(p);
        // An attribute may be NaN or infinite (a scanner's missing confidence), as binary
        // files hold it; MeshFair writes those values so. Coordinates must be finite.
        if (p.axis < 0 && !p.is_indices)
            if (const double special = non_finite(token); special != 0)
                return special;
        const double value = parse_double(reader_, token, p.what);
        if (p.type == Type::Float32 && std::abs(value) >= kFloatOverflow)
            reader_.fail_at(token,
                            p.what + " " + quoted(token) + " does not fit in " + p.type_name);
        return value;
    }

    void skip(const PropertyDecl& p)
    {
        const std::int64_t n = p.is_list ? count(p) : 1;
        for (std::int64_t k = 0; k < n; ++k)
            number(p);
    }

    // Only blank lines may follow the last row. Returns the bytes ignored (none).
    size_t finish()
    {
        while (reader_.next())
        {
            Tokenizer tokens(reader_.line());
            if (!tokens.at_end())
                reader_.fail_at(tokens.next(), "unexpected data after the last element");
        }
        return 0;
    }

    SourceLocation where() const { return reader_.here(reader_.column_of(last_)); }
    SourceLocation row_where() const { return reader_.here(); }
    [[noreturn]] void fail(const std::string& message) const
    {
        throw FormatError(where(), message);
    }

private:
    // The value of "nan", "inf" or "-inf" (any case, with an optional sign), else 0.
    static double non_finite(std::string_view token)
    {
        std::string_view t = token;
        const bool negative = t.starts_with('-');
        if (negative || t.starts_with('+'))
            t.remove_prefix(1);
        if (equals_ignoring_case(t, "nan"))
            return std::numeric_limits<double>::quiet_NaN();
        if (equals_ignoring_case(t, "inf") || equals_ignoring_case(t, "infinity"))
            return negative ? -std::numeric_limits<double>::infinity()
                            : std::numeric_limits<double>::infinity();
        return 0;
    }

    std::string_view take(const PropertyDecl& p)
    {
        const std::string_view token = tokens_.next();
        if (token.empty())
            reader_.fail(row_name(*element_, row_) + " has no value for property '" + p.name + "'",
                         static_cast<std::int64_t>(reader_.line().size()) + 1);
        last_ = token;
        return token;
    }

    std::int64_t integer(const PropertyDecl& p, Type type, const std::string& type_name,
                         const std::string& what)
    {
        const std::string_view token = take(p);
        const std::int64_t value = parse_integer(reader_, token, what);
        if (value < info(type).min || value > info(type).max)
            reader_.fail_at(token,
                            what + " " + std::to_string(value) + " does not fit in " + type_name);
        return value;
    }

    LineReader& reader_;
    Tokenizer tokens_{std::string_view()};
    std::string_view last_;
    const ElementDecl* element_ = nullptr;
    std::int64_t row_ = 0;
};

template <typename T>
std::int64_t read_integer(ByteReader& bytes, ByteOrder order)
{
    return bytes.read<T>(order);
}

// Indexed by Type, for the integer types.
constexpr std::int64_t (*kIntegerReaders[])(ByteReader&, ByteOrder) = {
    read_integer<std::int8_t>,   read_integer<std::uint8_t>, read_integer<std::int16_t>,
    read_integer<std::uint16_t>, read_integer<std::int32_t>, read_integer<std::uint32_t>};

// Rows of a binary body: values back to back in the declared types and byte order.
class BinaryRows
{
public:
    BinaryRows(std::string_view data, const std::string& file, size_t offset, ByteOrder order)
        : bytes_(data, file, offset), order_(order)
    {
    }

    void begin_row(const ElementDecl& e, std::int64_t row)
    {
        element_ = &e;
        row_ = row;
    }
    void end_row() {}

    std::int64_t count(const PropertyDecl& p)
    {
        bytes_.at(element_->name, row_, p.name);
        list_start_ = start_ = bytes_.offset();
        const std::int64_t n = integer(p.count_type);
        if (n < 0)
            fail(p.count_what + " " + std::to_string(n) + " is negative");
        const std::uint64_t needed = static_cast<std::uint64_t>(n) * info(p.type).size;
        if (needed > bytes_.remaining())
            fail(p.count_what + " " + std::to_string(n) + " needs " + std::to_string(needed) +
                 " bytes, more than the " + count_of(bytes_.remaining(), "byte", "bytes") +
                 " left");
        return n;
    }

    std::int64_t index(const PropertyDecl& p)
    {
        start_ = bytes_.offset();
        return integer(p.type);
    }

    double number(const PropertyDecl& p)
    {
        bytes_.at(element_->name, row_, p.name);
        start_ = bytes_.offset();
        switch (p.type)
        {
            case Type::Float32:
                return static_cast<double>(bytes_.read<float>(order_));
            case Type::Float64:
                return bytes_.read<double>(order_);
            default:
                return static_cast<double>(integer(p.type));
        }
    }

    void skip(const PropertyDecl& p)
    {
        if (p.is_list)
        {
            const std::int64_t n = count(p);
            bytes_.skip(static_cast<size_t>(n) * info(p.type).size);
            return;
        }
        bytes_.at(element_->name, row_, p.name);
        start_ = bytes_.offset();
        bytes_.skip(info(p.type).size);
    }

    // Counts that lie leave rows behind, so data after the last row is refused. NUL and
    // line-end bytes are not rows but padding some exporters append: they are ignored,
    // and their number returned for a note.
    size_t finish()
    {
        const std::string_view rest = bytes_.rest();
        for (const char c : rest)
            if (c != '\0' && c != '\n' && c != '\r' && c != ' ')
            {
                bytes_.at("", -1, "");
                bytes_.fail("unexpected data after the last element (" +
                            count_of(static_cast<std::int64_t>(rest.size()), "byte", "bytes") +
                            ")");
            }
        return rest.size();
    }

    SourceLocation where() const { return located(start_); }
    SourceLocation row_where() const { return located(list_start_); }
    [[noreturn]] void fail(const std::string& message) const
    {
        throw FormatError(where(), message);
    }

private:
    // Where the value at `offset` starts, in the element, row and property read last.
    SourceLocation located(size_t offset) const
    {
        SourceLocation loc = bytes_.here();
        loc.byte_offset = static_cast<std::int64_t>(offset);
        return loc;
    }

    std::int64_t integer(Type type)
    {
        assert(info(type).is_integer);
        return kIntegerReaders[static_cast<int>(type)](bytes_, order_);
    }

    ByteReader bytes_;
    ByteOrder order_;
    size_t start_ = 0;      // offset of the value read last
    size_t list_start_ = 0; // offset of the list count read last
    const ElementDecl* element_ = nullptr;
    std::int64_t row_ = 0;
};

struct Body
{
    std::int64_t vertex_count = 0;
    Mesh mesh;
    NoteCounter collapsed;
    std::vector<Index> face;
    size_t padding = 0; // NUL or line-end bytes after the last row of a binary file
    // The tristrips element's strips, the triangles they gave and the degenerate ones
    // dropped (two equal corners: how strips turn corners and join).
    std::int64_t strips = 0, strip_triangles = 0, strip_degenerate = 0;
};

template <typename Rows>
void read_face(Rows& rows, const PropertyDecl& p, std::int64_t row, Body& body)
{
    const std::int64_t n = rows.count(p);
    if (n < 3)
        rows.fail("face " + std::to_string(row) + " has " + count_of(n, "vertex", "vertices") +
                  " (a face needs at least 3)");
    body.face.clear();
    for (std::int64_t k = 0; k < n; ++k)
    {
        const std::int64_t v = rows.index(p);
        if (v < 0)
            rows.fail("face " + std::to_string(row) + " uses vertex index " + std::to_string(v) +
                      " (PLY vertex indices start at 0)");
        if (v >= body.vertex_count)
            rows.fail("face " + std::to_string(row) + " uses vertex index " + std::to_string(v) +
                      " but the file declares " + std::to_string(body.vertex_count) + " vertices");
        body.face.push_back(static_cast<Index>(v));
    }
    const FaceCheck check = normalize_face(body.face);
    if (!check.ok)
        throw FormatError(rows.row_where(), check.problem);
    if (check.collapsed > 0)
        body.collapsed.add(check.collapsed, rows.row_where().to_string());
    if (body.mesh.face_vertices.size() + body.face.size() > static_cast<size_t>(kMaxElements))
        rows.fail("more face corners than MeshFair supports");
    body.mesh.add_face(body.face);
}

// One row of a tristrips element: strips of vertex indices, each ending at a restart (-1,
// or the largest value of an unsigned item type) or at the row's end. A strip's k-th
// index (k >= 2) closes the triangle of the two before it, every other one reversed so
// that all keep the strip's orientation: (s0 s1 s2), (s2 s1 s3), (s2 s3 s4), ...
template <typename Rows>
void read_strips(Rows& rows, const PropertyDecl& p, std::int64_t row, Body& body)
{
    const std::int64_t n = rows.count(p);
    const TypeInfo& type = info(p.type);
    const std::int64_t restart = type.min < 0 ? -1 : type.max;
    std::int64_t in_strip = 0;
    Index a = 0, b = 0;
    for (std::int64_t k = 0; k < n; ++k)
    {
        const std::int64_t v = rows.index(p);
        if (v == restart)
        {
            in_strip = 0;
            continue;
        }
        if (v < 0)
            rows.fail("tristrips " + std::to_string(row) + " uses vertex index " +
                      std::to_string(v) + " at item " + std::to_string(k) +
                      " (PLY vertex indices start at 0; -1 ends a strip)");
        if (v >= body.vertex_count)
            rows.fail("tristrips " + std::to_string(row) + " uses vertex index " +
                      std::to_string(v) + " at item " + std::to_string(k) +
                      " but the file declares " + std::to_string(body.vertex_count) + " vertices");
        const auto c = static_cast<Index>(v);
        if (in_strip == 0)
            ++body.strips;
        if (in_strip >= 2)
        {
            const bool reversed = in_strip % 2 != 0;
            const Index triangle[3] = {reversed ? b : a, reversed ? a : b, c};
            if (a == b || b == c || a == c)
                ++body.strip_degenerate;
            else
            {
                if (body.mesh.face_vertices.size() + 3 > static_cast<size_t>(kMaxElements))
                    rows.fail("more face corners than MeshFair supports");
                body.mesh.add_face(triangle);
                ++body.strip_triangles;
            }
        }
        a = b;
        b = c;
        ++in_strip;
    }
}

// One row's value (or list) of a property kept as an attribute.
// A value of `type`: an ASCII file's decimal text of a float property is the float nearest
// to it, as a binary file would hold it, so that every encoding writes back the same value.
double typed(double value, Type type)
{
    return type == Type::Float32 ? static_cast<double>(static_cast<float>(value)) : value;
}

template <typename Rows>
void keep_value(Rows& rows, const PropertyDecl& p, Property& kept)
{
    if (!p.is_list)
    {
        kept.values.push_back(typed(rows.number(p), p.type));
        return;
    }
    const std::int64_t n = rows.count(p);
    if (static_cast<std::int64_t>(kept.values.size()) + n > kMaxElements)
        rows.fail("more list items in property '" + p.name + "' than MeshFair supports");
    for (std::int64_t k = 0; k < n; ++k)
        kept.values.push_back(typed(rows.number(p), p.type));
    kept.offsets.push_back(static_cast<Index>(kept.values.size()));
}

// Tables in `attributes` for every property MeshFair does not read into the mesh: the
// vertices' and faces' other properties and every other element (not the tristrips'
// other properties, whose rows are strips, not faces).
void prepare_attributes(Header& h, MeshAttributes& attributes)
{
    attributes = MeshAttributes{};
    attributes.comments = h.comments;
    for (ElementDecl& e : h.elements)
    {
        if (e.kind == Kind::Strips)
            continue;
        Element* table = e.kind == Kind::Vertex ? &attributes.vertex
                         : e.kind == Kind::Face ? &attributes.face
                                                : &attributes.other_elements.emplace_back();
        table->name = e.name;
        table->count = static_cast<Index>(e.count);
        for (const PropertyDecl& p : e.properties)
            if (p.axis < 0 && !p.is_indices)
                table->properties.push_back(
                    Property{p.name, p.type, p.is_list, p.count_type, {}, {}});
    }
    // Pointers once no table moves any more.
    size_t other = 0;
    for (ElementDecl& e : h.elements)
    {
        if (e.kind == Kind::Strips)
            continue;
        Element& table = e.kind == Kind::Vertex ? attributes.vertex
                         : e.kind == Kind::Face ? attributes.face
                                                : attributes.other_elements[other++];
        size_t k = 0;
        for (PropertyDecl& p : e.properties)
            if (p.axis < 0 && !p.is_indices)
            {
                Property& kept = table.properties[k++];
                p.kept = &kept;
                if (p.is_list)
                    kept.offsets.reserve(static_cast<size_t>(e.count) + 1);
                else
                    kept.values.reserve(static_cast<size_t>(e.count));
                if (p.is_list)
                    kept.offsets.push_back(0);
            }
        if (table.properties.empty() && e.kind != Kind::Other)
            table.count = 0;
    }
}

template <typename Rows>
void read_rows(Rows& rows, const Header& h, Body& body)
{
    for (const ElementDecl& e : h.elements)
    {
        // Rows without properties hold no bytes, and no tokens to put on a line.
        if (e.properties.empty())
            continue;
        // check_counts bounds these by the size of the data.
        if (e.kind == Kind::Vertex)
            body.mesh.positions.reserve(3 * static_cast<size_t>(e.count));
        if (e.kind == Kind::Face)
            body.mesh.face_offsets.reserve(static_cast<size_t>(e.count) + 1);
        for (std::int64_t row = 0; row < e.count; ++row)
        {
            rows.begin_row(e, row);
            double xyz[3] = {0, 0, 0};
            for (const PropertyDecl& p : e.properties)
            {
                if (p.is_indices && e.kind == Kind::Strips)
                {
                    read_strips(rows, p, row, body);
                }
                else if (p.is_indices)
                {
                    read_face(rows, p, row, body);
                }
                else if (p.kept)
                {
                    keep_value(rows, p, *p.kept);
                }
                else if (p.axis < 0)
                {
                    rows.skip(p);
                }
                else
                {
                    const double value = rows.number(p);
                    if (!std::isfinite(value))
                        rows.fail(row_name(e, row) + " has a non-finite " + p.what + " (" +
                                  std::to_string(value) + ")");
                    xyz[p.axis] = value;
                }
            }
            rows.end_row();
            if (e.kind == Kind::Vertex)
                body.mesh.add_vertex(xyz[0], xyz[1], xyz[2]);
        }
    }
    body.padding = rows.finish();
}

// Names for a note: the first few, then how many more, so a note stays one line
// whatever the header declares.
class NameList
{
public:
    void add(const std::string& item)
    {
        if (count_++ < kShown)
            text_ += (text_.empty() ? "" : ", ") + item;
    }
    std::int64_t count() const { return count_; }
    std::string text() const
    {
        return count_ > kShown ? text_ + " and " + std::to_string(count_ - kShown) + " more"
                               : text_;
    }

private:
    static constexpr std::int64_t kShown = 8;
    std::int64_t count_ = 0;
    std::string text_;
};

void add_notes(const Header& h, ReadReport& report)
{
    for (const ElementDecl& e : h.elements)
    {
        if (e.kind != Kind::Strips)
            continue;
        NameList skipped;
        for (const PropertyDecl& p : e.properties)
            if (!p.is_indices)
                skipped.add("'" + p.name + "'");
        if (skipped.count() > 0)
            report.notes.push_back("skipped " + e.name + " properties " + skipped.text() +
                                   " (a strip's values have no face to go with)");
    }
}

} // namespace

Mesh read_ply(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes)
{
    report.format = Format::Ply;
    LineReader reader(data, name);
    Header h = parse_header(reader, data);
    report.encoding = h.encoding;
    assign_roles(h, name);
    check_counts(h, name, data.size() - h.data_offset);
    prepare_attributes(h, attributes);

    Body body;
    for (const ElementDecl& e : h.elements)
        if (e.kind == Kind::Vertex)
            body.vertex_count = e.count;
    if (h.encoding == Encoding::Ascii)
    {
        AsciiRows rows(reader);
        read_rows(rows, h, body);
    }
    else
    {
        BinaryRows rows(
            data, name, h.data_offset,
            h.encoding == Encoding::BinaryLittleEndian ? ByteOrder::Little : ByteOrder::Big);
        read_rows(rows, h, body);
    }
    add_notes(h, report);
    report_collapsed(body.collapsed, report.notes);
    // The strips' triangles have no row of the face element's other properties.
    if (!attributes.face.properties.empty() && attributes.face.count != body.mesh.face_count())
    {
        NameList names;
        for (const Property& p : attributes.face.properties)
            names.add("'" + p.name + "'");
        report.notes.push_back("skipped face properties " + names.text() +
                               " (the triangles of the strips have no values for them)");
        attributes.face = Element{"face", 0, {}};
    }
    for (const ElementDecl& e : h.elements)
        if (e.kind == Kind::Strips)
        {
            report.notes.push_back("decoded element 'tristrips' (" +
                                   count_of(body.strips, "strip", "strips") + ") into " +
                                   count_of(body.strip_triangles, "triangle", "triangles") +
                                   " (a PLY that MeshFair writes lists them as faces)");
            if (body.strip_degenerate > 0)
                report.notes.push_back(
                    "dropped " +
                    count_of(body.strip_degenerate, "degenerate triangle", "degenerate triangles") +
                    " of the strips (two equal corners, where strips turn or "
                    "join)");
        }
    if (body.padding > 0)
        report.notes.push_back(
            "ignored " +
            count_of(static_cast<std::int64_t>(body.padding), "padding byte", "padding bytes") +
            " (NUL or line ends) after the last element");
    return std::move(body.mesh);
}

} // namespace meshfair::io
