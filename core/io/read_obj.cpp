// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_obj.h"

#include <algorithm>
#include <array>
#include <exception>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/attributes.h"
#include "core/io/face_builder.h"
#include "core/io/text_reader.h"
#include "core/parallel/parallel.h"

namespace meshfair::io {

namespace {

// What the scan counts besides the mesh, for the read report.
struct ObjTally
{
    std::int64_t ignored_lines = 0;   // l, p, curves, surfaces
    std::int64_t parameter_lines = 0; // vp
    std::int64_t vertex_extras = 0;   // v lines with a w (or values that are not r g b)
    std::string first_vertex_extra;
    std::int64_t coloured_vertices = 0;          // v lines with r g b after x y z
    std::array<std::int64_t, 2> partial_faces{}; // faces with vt (vn) at only some corners
    std::array<std::string, 2> first_partial;
    std::int64_t unknown_lines = 0;
    std::string first_unknown;
    NoteCounter collapsed;
};

// The three index lists a face corner refers to: vertices (v), texture coordinates (vt)
// and normals (vn).
enum List
{
    kVertex,
    kTexture,
    kNormal
};
constexpr std::string_view kIndexName[] = {"vertex index", "texture coordinate index",
                                           "normal index"};
constexpr const char* kFirst[] = {"vertex", "texture coordinate (vt)", "normal (vn)"};
constexpr const char* kOne[] = {"vertex", "texture coordinate", "normal"};
constexpr const char* kDefined[] = {"vertices", "texture coordinates", "normals"};

// Resolves one index of a face corner ("7" of "7/1/3", or "-2") against the number of
// entries of its list defined so far. Forward references (positive indices past the
// entries read so far) are legal in OBJ and checked against the final count by the
// caller.
// Why index `raw` of `list` is refused (out of the hot path: it builds the message).
[[noreturn, gnu::cold]] void fail_index(const LineReader& reader, std::string_view part, List list,
                                        std::int64_t raw, std::int64_t so_far)
{
    const std::string what(kIndexName[list]);
    if (raw == 0)
        reader.fail_at(part, what + " 0 (OBJ indices start at 1, or count back from -1)");
    if (raw < 0)
        reader.fail_at(part, what + " " + std::to_string(raw) + " reaches before the first " +
                                 kFirst[list] + " (" +
                                 count_of(so_far, kOne[list], kDefined[list]) +
                                 (so_far == 1 ? " is" : " are") + " defined before this line)");
    reader.fail_at(part, what + " " + std::to_string(raw) + " is out of range");
}

inline std::int64_t corner_index(const LineReader& reader, std::string_view part, List list,
                                 std::int64_t so_far)
{
    const std::int64_t raw = parse_integer(reader, part, kIndexName[list]);
    const std::int64_t resolved = raw < 0 ? so_far + raw : raw - 1;
    if (raw == 0 || resolved < 0 || raw > kMaxElements)
        fail_index(reader, part, list, raw, so_far);
    return resolved;
}

// Reads "v x y z [r g b]": the colour, when there, goes to `colours` (three values a
// vertex, zeros for a vertex without one). A w, or any other count of values, is noted.
void read_vertex(const LineReader& reader, Tokenizer& tokens, Mesh& mesh,
                 std::vector<double>& colours, ObjTally& tally)
{
    if (mesh.positions.size() / 3 >= static_cast<size_t>(kMaxVertices))
        reader.fail("more vertices than MeshFair supports");
    // Names for messages, made without a string a line: this runs for every vertex.
    static constexpr std::string_view kCoordinate[] = {"x coordinate", "y coordinate",
                                                       "z coordinate"};
    for (const std::string_view what : kCoordinate)
    {
        const std::string_view t = tokens.next();
        if (t.empty())
            reader.fail("vertex has no " + std::string(what));
        mesh.positions.push_back(parse_double(reader, t, what));
    }
    double extra[3] = {0, 0, 0};
    int extras = 0;
    std::string_view first;
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next(), ++extras)
    {
        const double value = parse_double(reader, t, "vertex value"); // always a number
        if (extras < 3)
            extra[extras] = value;
        if (extras == 0)
            first = t;
    }
    if (extras == 3)
        ++tally.coloured_vertices;
    else if (extras > 0 && tally.vertex_extras++ == 0)
        tally.first_vertex_extra = reader.here(reader.column_of(first)).to_string();
    // Kept for every vertex once one has a colour, so indices stay aligned.
    if (extras == 3 || !colours.empty())
    {
        colours.resize(mesh.positions.size() - 3, 0.0);
        for (int c = 0; c < 3; ++c)
            colours.push_back(extras == 3 ? extra[c] : 0.0);
    }
}

// Reads "vt u [v [w]]" (three values kept, missing ones 0) or "vn x y z".
void read_entry(const LineReader& reader, Tokenizer& tokens, bool is_normal,
                std::vector<double>& values, int& dimension)
{
    const char* names[] = {"u", "v", "w"};
    const char* axes[] = {"x", "y", "z"};
    int n = 0;
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next(), ++n)
    {
        if (n == 3)
            reader.fail_at(t, std::string("unexpected value after the ") +
                                  (is_normal ? "normal's x y z" : "texture coordinate's u v w"));
        values.push_back(parse_double(reader, t,
                                      std::string(is_normal ? "normal " : "texture coordinate ") +
                                          (is_normal ? axes[n] : names[n])));
    }
    if (n == 0 || (is_normal && n < 3))
        reader.fail(is_normal ? "a normal needs x y z (vn x y z)"
                              : "a texture coordinate needs at least u (vt u [v [w]])");
    dimension = std::max(dimension, n);
    for (; n < 3; ++n)
        values.push_back(0.0);
}

void add_notes(const ObjTally& t, ReadReport& report)
{
    report_collapsed(t.collapsed, report.notes);
    if (t.ignored_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.ignored_lines) +
                               " line, point, curve or surface statements");
    if (t.parameter_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.parameter_lines) +
                               " parameter-space vertices (vp), which only curves and surfaces "
                               "use");
    if (t.vertex_extras > 0)
        report.notes.push_back(
            "ignored the values after x y z that are not a colour r g b (a w, "
            "or another count) on " +
            count_of(t.vertex_extras, "vertex line", "vertex lines") + " (first at " +
            t.first_vertex_extra + ")");
    const char* lists[] = {"texture coordinates", "normals"};
    for (int l = 0; l < 2; ++l)
        if (t.partial_faces[l] > 0)
            report.notes.push_back("ignored the " + std::string(lists[l]) + " of " +
                                   count_of(t.partial_faces[l], "face", "faces") +
                                   " that give them at only some corners (first at " +
                                   t.first_partial[l] + ")");
    if (t.unknown_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.unknown_lines) +
                               " lines with unknown keywords (first: " + t.first_unknown + ")");
}

// The largest index into one list and, for a forward reference, where it is.
struct ForwardReference
{
    std::int64_t max_index = -1;
    std::int64_t line = 0;
    std::int64_t column = 0;
};

// The lines of one part of the file, parsed into a mesh of their own. The first part is
// the file's start, so everything in it means what it means in the serial read. A later
// part starts at an unknown vertex count and line number; whatever needs those (a
// negative index, a note that names a line, an error) stops it with RangeNeedsContext or
// a FormatError, and the caller reads the file again serially.
struct ObjPart
{
    Mesh mesh;
    ObjTally tally;
    std::vector<double> colours;               // r g b per vertex, once a vertex has one
    std::array<std::vector<double>, 2> lists;  // vt and vn entries, three values each
    int texture_dimension = 0;                 // the most values a vt line gave
    std::array<std::vector<Index>, 2> corners; // vt and vn index per corner, once a face has one
    std::vector<ObjStatement> statements;
    std::array<ForwardReference, 3> references; // vertices, vt, vn (lines known in the first part)
};

struct RangeNeedsContext
{
};

// The single-spaced text of a statement line.
std::string statement_text(std::string_view keyword, Tokenizer& tokens)
{
    std::string text(keyword);
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next())
    {
        text += ' ';
        text += t;
    }
    return text;
}

// One face line: its corners "v", "v/vt", "v//vn" or "v/vt/vn" into the part.
void read_face(const LineReader& reader, std::string_view keyword, Tokenizer& tokens, ObjPart& part,
               bool first_part, std::array<std::vector<Index>, 3>& face)
{
    Mesh& mesh = part.mesh;
    const std::int64_t so_far[3] = {mesh.vertex_count(),
                                    static_cast<std::int64_t>(part.lists[0].size() / 3),
                                    static_cast<std::int64_t>(part.lists[1].size() / 3)};
    for (std::vector<Index>& f : face)
        f.clear();
    // The index of list l a corner names, its forward reference remembered.
    const auto resolve = [&](std::string_view index_text, int l) {
        const std::int64_t index =
            corner_index(reader, index_text, static_cast<List>(l), so_far[l]);
        ForwardReference& ref = part.references[l];
        if (index >= so_far[l] && index > ref.max_index)
        {
            ref.line = reader.line_number();
            ref.column = reader.column_of(index_text);
        }
        ref.max_index = std::max(ref.max_index, index);
        return static_cast<Index>(index);
    };
    size_t corner_count = 0, given[2] = {0, 0};
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next())
    {
        ++corner_count;
        const size_t slash = t.find('/');
        if (slash == std::string_view::npos) // "7": a vertex alone, the common case
        {
            if (!first_part && t.front() == '-')
                throw RangeNeedsContext{};
            face[kVertex].push_back(resolve(t, kVertex));
            continue;
        }
        if (!first_part && t.find('-') != std::string_view::npos)
            throw RangeNeedsContext{};
        // "v/vt", "v//vn" or "v/vt/vn".
        std::string_view parts[3] = {t.substr(0, slash), t.substr(slash + 1), {}};
        if (const size_t second = parts[1].find('/'); second != std::string_view::npos)
        {
            parts[2] = parts[1].substr(second + 1);
            parts[1] = parts[1].substr(0, second);
            if (parts[2].find('/') != std::string_view::npos)
                reader.fail_at(
                    t, "face corner " + quoted(t) + " has more than three indices (v/vt/vn)");
        }
        if (parts[0].empty())
            reader.fail_at(t, "face corner " + quoted(t) + " has no vertex index");
        face[kVertex].push_back(resolve(parts[0], kVertex));
        for (int l = kTexture; l <= kNormal; ++l)
            if (!parts[l].empty())
            {
                face[l].push_back(resolve(parts[l], l));
                ++given[l - 1];
            }
    }
    if (face[kVertex].size() < 3)
        reader.fail(
            "face has " +
            count_of(static_cast<std::int64_t>(face[kVertex].size()), "vertex", "vertices") +
            " (a face needs at least 3)");
    for (int l = 0; l < 2; ++l)
        if (given[l] > 0 && given[l] < corner_count) // at some corners only: dropped, noted
        {
            if (!first_part)
                throw RangeNeedsContext{};
            if (part.tally.partial_faces[l]++ == 0)
                part.tally.first_partial[l] = reader.here(reader.column_of(keyword)).to_string();
            face[l + 1].clear();
        }
    const FaceCheck check = normalize_face(face[kVertex], &face[kTexture], &face[kNormal]);
    if (!check.ok)
        reader.fail(check.problem, reader.column_of(keyword));
    if (check.collapsed > 0)
    {
        if (!first_part)
            throw RangeNeedsContext{};
        part.tally.collapsed.add(check.collapsed,
                                 reader.here(reader.column_of(keyword)).to_string());
    }
    if (mesh.face_vertices.size() + face[kVertex].size() > static_cast<size_t>(kMaxElements))
        reader.fail("more face corners than MeshFair supports");
    for (int l = 0; l < 2; ++l)
    {
        std::vector<Index>& corners = part.corners[l];
        if (!face[l + 1].empty() || !corners.empty())
        {
            corners.resize(mesh.face_vertices.size(), kInvalidIndex);
            if (face[l + 1].empty())
                corners.resize(corners.size() + face[kVertex].size(), kInvalidIndex);
            else
                corners.insert(corners.end(), face[l + 1].begin(), face[l + 1].end());
        }
    }
    mesh.add_face(face[kVertex]);
}

ObjPart parse_part(std::string_view data, const std::string& name, bool first_part)
{
    ObjPart part;
    ObjTally& tally = part.tally;
    LineReader reader(data, name);
    std::array<std::vector<Index>, 3> face;
    while (reader.next())
    {
        Tokenizer tokens(reader.line());
        const std::string_view keyword = tokens.next();
        if (keyword.empty() || keyword.front() == '#')
            continue;
        // The two keywords of nearly every line, tested first by their one character.
        const bool one_letter = keyword.size() == 1;
        if (one_letter && keyword[0] == 'v')
        {
            read_vertex(reader, tokens, part.mesh, part.colours, tally);
            if (!first_part && tally.vertex_extras > 0)
                throw RangeNeedsContext{};
        }
        else if (one_letter && keyword[0] == 'f')
        {
            read_face(reader, keyword, tokens, part, first_part, face);
        }
        else if (keyword == "vt" || keyword == "vn")
        {
            const bool is_normal = keyword == "vn";
            std::vector<double>& list = part.lists[is_normal ? 1 : 0];
            if (list.size() / 3 >= static_cast<size_t>(kMaxElements))
                reader.fail("more " + std::string(is_normal ? "normals" : "texture coordinates") +
                            " than MeshFair supports");
            int dimension = 0;
            read_entry(reader, tokens, is_normal, list, dimension);
            part.texture_dimension = std::max(part.texture_dimension, is_normal ? 0 : dimension);
        }
        else if (keyword == "g" || keyword == "o" || keyword == "s" || keyword == "usemtl" ||
                 keyword == "mtllib")
        {
            part.statements.push_back({part.mesh.face_count(), statement_text(keyword, tokens)});
        }
        else if (keyword == "l" || keyword == "p" || keyword == "curv" || keyword == "curv2" ||
                 keyword == "surf")
        {
            ++tally.ignored_lines;
        }
        else if (keyword == "vp")
        {
            ++tally.parameter_lines;
        }
        else if (tally.unknown_lines++ == 0)
        {
            if (!first_part)
                throw RangeNeedsContext{};
            tally.first_unknown = "'" + std::string(keyword.substr(0, 20)) + "' at line " +
                                  std::to_string(reader.line_number());
        }
    }
    return part;
}

// Entries of three values as entries of `dimension` values.
std::vector<double> narrowed(const std::vector<double>& triples, int dimension)
{
    if (dimension == 3)
        return triples;
    std::vector<double> out;
    out.reserve(triples.size() / 3 * static_cast<size_t>(dimension));
    for (size_t k = 0; k < triples.size(); k += 3)
        out.insert(out.end(), triples.begin() + static_cast<std::ptrdiff_t>(k),
                   triples.begin() + static_cast<std::ptrdiff_t>(k) + dimension);
    return out;
}

Mesh finish(ObjPart& part, const std::string& name, ReadReport& report, MeshAttributes& attributes)
{
    Mesh& mesh = part.mesh;
    const std::int64_t counts[3] = {mesh.vertex_count(),
                                    static_cast<std::int64_t>(part.lists[0].size() / 3),
                                    static_cast<std::int64_t>(part.lists[1].size() / 3)};
    const char* last[3] = {"the last vertex", "the last texture coordinate (vt)",
                           "the last normal (vn)"};
    for (int l = kVertex; l <= kNormal; ++l)
        if (part.references[l].max_index >= counts[l])
            throw FormatError(
                SourceLocation::text(name, part.references[l].line, part.references[l].column),
                std::string(kIndexName[l]) + " " +
                    std::to_string(part.references[l].max_index + 1) + " is past " + last[l] +
                    " (the file defines " + std::to_string(counts[l]) + ")");
    attributes = MeshAttributes{};
    add_notes(part.tally, report);
    const std::int64_t coloured = part.tally.coloured_vertices;
    if (coloured > 0 && coloured == mesh.vertex_count())
    {
        attributes.vertex.count = mesh.vertex_count();
        const char* names[] = {"red", "green", "blue"};
        for (size_t c = 0; c < 3; ++c)
        {
            Property p{names[c], ValueType::Float64, false, ValueType::UInt8, {}, {}};
            p.values.resize(static_cast<size_t>(mesh.vertex_count()));
            for (size_t v = 0; v < p.values.size(); ++v)
                p.values[v] = part.colours[3 * v + c];
            attributes.vertex.properties.push_back(std::move(p));
        }
    }
    else if (coloured > 0)
        report.notes.push_back("ignored the colours r g b of " + std::to_string(coloured) +
                               " of the " +
                               count_of(mesh.vertex_count(), "vertex line", "vertex lines") +
                               " (colours are kept when every vertex has one)");
    CornerValues* targets[2] = {&attributes.texcoords, &attributes.normals};
    for (int l = 0; l < 2; ++l)
        if (!part.corners[l].empty())
        {
            CornerValues& c = *targets[l];
            c.dimension = l == 0 ? std::max(part.texture_dimension, 1) : 3;
            c.values = narrowed(part.lists[l], c.dimension);
            c.corners = std::move(part.corners[l]);
            c.corners.resize(mesh.face_vertices.size(), kInvalidIndex);
        }
        else if (counts[l + 1] > 0)
            report.notes.push_back("ignored " +
                                   (l == 0
                                        ? count_of(counts[l + 1], "texture coordinate (vt)",
                                                   "texture coordinates (vt)")
                                        : count_of(counts[l + 1], "normal (vn)", "normals (vn)")) +
                                   " that no face uses");
    attributes.statements = std::move(part.statements);
    return std::move(mesh);
}

// Cuts the data just after a line feed near each k/parts of its length, which is always
// a line boundary (LF and CRLF end a line there; a CR alone never precedes the cut).
std::vector<std::string_view> cut_at_lines(std::string_view data, int parts)
{
    std::vector<std::string_view> cuts;
    size_t begin = 0;
    for (int k = 1; k <= parts; ++k)
    {
        size_t end = data.size();
        if (k < parts)
        {
            const size_t target =
                std::max(begin, data.size() / static_cast<size_t>(parts) * static_cast<size_t>(k));
            const size_t lf = data.find('\n', target);
            end = lf == std::string_view::npos ? data.size() : lf + 1;
        }
        if (end > begin)
            cuts.push_back(data.substr(begin, end - begin));
        begin = end;
    }
    return cuts;
}

// `tail` appended to `all`, each first padded to `size` and `tail_size` with `fill` when
// it is empty but the other is not (a part without colours, or without vt, beside one
// with them).
template <typename T>
void append_padded(std::vector<T>& all, size_t size, std::vector<T>& tail, size_t tail_size, T fill)
{
    if (all.empty() && tail.empty())
        return;
    all.resize(size, fill);
    if (tail.empty())
        all.resize(size + tail_size, fill);
    else
        all.insert(all.end(), tail.begin(), tail.end());
    tail = {};
}

// The parts joined in file order into the first one; false when a later part cannot be
// taken as it is (then the serial read decides).
bool join_parts(std::vector<ObjPart>& parts)
{
    ObjPart& all = parts.front();
    size_t nv = all.mesh.positions.size(), nc = all.mesh.face_vertices.size(),
           nf = all.mesh.face_offsets.size(), nl[2] = {all.lists[0].size(), all.lists[1].size()};
    for (size_t k = 1; k < parts.size(); ++k)
    {
        const ObjTally& t = parts[k].tally;
        all.tally.ignored_lines += t.ignored_lines;
        all.tally.parameter_lines += t.parameter_lines;
        all.tally.coloured_vertices += t.coloured_vertices;
        all.texture_dimension = std::max(all.texture_dimension, parts[k].texture_dimension);
        for (int l = 0; l < 3; ++l)
            all.references[l].max_index =
                std::max(all.references[l].max_index, parts[k].references[l].max_index);
        nv += parts[k].mesh.positions.size();
        nc += parts[k].mesh.face_vertices.size();
        nf += parts[k].mesh.face_offsets.size() - 1;
        for (int l = 0; l < 2; ++l)
            nl[l] += parts[k].lists[l].size();
    }
    // The serial read's limits and its forward-reference messages need the whole file.
    if (nv / 3 > static_cast<size_t>(kMaxVertices) || nc > static_cast<size_t>(kMaxElements) ||
        all.references[kVertex].max_index >= static_cast<std::int64_t>(nv / 3) ||
        all.references[kTexture].max_index >= static_cast<std::int64_t>(nl[0] / 3) ||
        all.references[kNormal].max_index >= static_cast<std::int64_t>(nl[1] / 3) ||
        nl[0] / 3 > static_cast<size_t>(kMaxElements) ||
        nl[1] / 3 > static_cast<size_t>(kMaxElements))
        return false;
    Mesh& mesh = all.mesh;
    mesh.positions.reserve(nv);
    mesh.face_vertices.reserve(nc);
    mesh.face_offsets.reserve(nf);
    for (size_t k = 1; k < parts.size(); ++k)
    {
        ObjPart& part = parts[k];
        const Mesh& m = part.mesh;
        const Index base = static_cast<Index>(mesh.face_vertices.size());
        const Index faces_before = mesh.face_count();
        append_padded(all.colours, mesh.positions.size(), part.colours, m.positions.size(), 0.0);
        for (int l = 0; l < 2; ++l)
        {
            all.lists[l].insert(all.lists[l].end(), part.lists[l].begin(), part.lists[l].end());
            append_padded(all.corners[l], mesh.face_vertices.size(), part.corners[l],
                          m.face_vertices.size(), kInvalidIndex);
        }
        for (ObjStatement& s : part.statements)
        {
            s.before_face += faces_before;
            all.statements.push_back(std::move(s));
        }
        mesh.positions.insert(mesh.positions.end(), m.positions.begin(), m.positions.end());
        mesh.face_vertices.insert(mesh.face_vertices.end(), m.face_vertices.begin(),
                                  m.face_vertices.end());
        for (size_t f = 1; f < m.face_offsets.size(); ++f)
            mesh.face_offsets.push_back(base + m.face_offsets[f]);
        part = ObjPart{}; // frees the part as soon as it is copied
    }
    return true;
}

} // namespace

Mesh read_obj(std::string_view data, const std::string& name, ReadReport& report,
              MeshAttributes& attributes)
{
    // One range per thread, for files large enough to pay for waking the threads.
    constexpr size_t kBytesPerRange = size_t{4} << 20;
    const auto ranges = static_cast<int>(
        std::clamp<size_t>(data.size() / kBytesPerRange, 1, static_cast<size_t>(thread_count())));
    return read_obj_in_ranges(data, name, report, attributes, ranges);
}

Mesh read_obj_in_ranges(std::string_view data, const std::string& name, ReadReport& report,
                        MeshAttributes& attributes, int ranges, int* parsed_in)
{
    if (parsed_in)
        *parsed_in = 1;
    report.format = Format::Obj;
    report.encoding = Encoding::Ascii;
    std::vector<std::string_view> pieces = cut_at_lines(data, std::max(ranges, 1));
    // A later range that starts with a byte-order mark would have it skipped as if it
    // were the file's start.
    const bool splittable =
        pieces.size() > 1 && std::none_of(pieces.begin() + 1, pieces.end(), [](std::string_view p) {
            return p.substr(0, 3) == "\xEF\xBB\xBF";
        });
    if (splittable)
    {
        std::vector<ObjPart> parts(pieces.size());
        std::vector<char> stopped(pieces.size(), 0);
        std::vector<std::exception_ptr> other(pieces.size());
        auto parse = [&](Index k) {
            try
            {
                parts[k] = parse_part(pieces[k], name, k == 0);
            }
            catch (const FormatError&)
            {
                stopped[k] = 1;
            }
            catch (const RangeNeedsContext&)
            {
                stopped[k] = 1;
            }
            catch (...)
            {
                other[k] = std::current_exception(); // out of memory: nothing to retry
            }
        };
        // The parts on at most thread_count() threads; one thread parses them in turn.
        const auto parts_count = static_cast<Index>(pieces.size());
        const int threads = std::min(static_cast<int>(parts_count), thread_count());
        if (threads > 1)
            detail::parallel_for_threads(parts_count, threads, parse);
        else
            for (Index k = 0; k < parts_count; ++k)
                parse(k);
        for (const std::exception_ptr& e : other)
            if (e)
                std::rethrow_exception(e);
        if (std::find(stopped.begin(), stopped.end(), 1) == stopped.end() && join_parts(parts))
        {
            if (parsed_in)
                *parsed_in = static_cast<int>(parts.size());
            return finish(parts.front(), name, report, attributes);
        }
    }
    // One pass straight into the mesh: faces are normalized as they are read, so no
    // per-face bookkeeping outlives its line.
    ObjPart whole = parse_part(data, name, true);
    return finish(whole, name, report, attributes);
}

} // namespace meshfair::io
