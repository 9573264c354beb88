// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/read_obj.h"

#include <algorithm>
#include <exception>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/face_builder.h"
#include "core/io/text_reader.h"
#include "core/solver/parallel.h"

namespace meshfair::io {

namespace {

// What the scan counts besides the mesh, for the read report.
struct ObjTally
{
    std::int64_t ignored_lines = 0;   // l, p, curves, surfaces
    std::int64_t attribute_lines = 0; // vt, vn, vp
    std::int64_t grouping_lines = 0;  // g, o, s
    std::int64_t material_lines = 0;  // mtllib, usemtl
    std::int64_t vertex_extras = 0;   // v lines with w or a colour after x y z
    std::string first_vertex_extra;
    std::int64_t unknown_lines = 0;
    std::string first_unknown;
    NoteCounter collapsed;
};

// Resolves one face corner token ("7", "7/1", "7//3", "-2/1/1") against the number of
// vertices defined so far. Forward references (positive indices past the vertices
// read so far) are legal in OBJ and checked against the final count by the caller.
std::int64_t corner_index(const LineReader& reader, std::string_view token,
                          std::int64_t vertices_so_far)
{
    const std::string_view vertex_part = token.substr(0, token.find('/'));
    if (vertex_part.empty())
        reader.fail_at(token, "face corner '" + std::string(token) + "' has no vertex index");
    const std::int64_t raw = parse_integer(reader, vertex_part, "vertex index");
    if (raw == 0)
        reader.fail_at(token, "vertex index 0 (OBJ indices start at 1, or count back from -1)");
    if (raw < 0)
    {
        const std::int64_t resolved = vertices_so_far + raw;
        if (resolved < 0)
            reader.fail_at(token, "vertex index " + std::to_string(raw) +
                                      " reaches before the first vertex (" +
                                      std::to_string(vertices_so_far) +
                                      " vertices are defined before this line)");
        return resolved;
    }
    if (raw > kMaxElements)
        reader.fail_at(token, "vertex index " + std::to_string(raw) + " is out of range");
    return raw - 1;
}

void read_vertex(const LineReader& reader, Tokenizer& tokens, Mesh& mesh, ObjTally& tally)
{
    if (mesh.positions.size() / 3 >= static_cast<size_t>(kMaxVertices))
        reader.fail("more vertices than MeshFair supports");
    for (const char* axis : {"x", "y", "z"})
    {
        const std::string_view t = tokens.next();
        if (t.empty())
            reader.fail(std::string("vertex has no ") + axis + " coordinate");
        mesh.positions.push_back(parse_double(reader, t, std::string(axis) + " coordinate"));
    }
    // An optional w or r g b may follow; they must still be numbers.
    std::string_view t = tokens.next();
    if (!t.empty() && tally.vertex_extras++ == 0)
        tally.first_vertex_extra = reader.here(reader.column_of(t)).to_string();
    for (; !t.empty(); t = tokens.next())
        parse_double(reader, t, "vertex value");
}

void add_notes(const ObjTally& t, ReadReport& report)
{
    report_collapsed(t.collapsed, report.notes);
    if (t.ignored_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.ignored_lines) +
                               " line, point, curve or surface statements");
    if (t.vertex_extras > 0)
        report.notes.push_back("ignored the values after x y z (w or a colour) on " +
                               count_of(t.vertex_extras, "vertex line", "vertex lines") +
                               " (first at " + t.first_vertex_extra + ")");
    if (t.attribute_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.attribute_lines) +
                               " texture-coordinate, normal and parameter lines (vt, vn, vp) and "
                               "the faces' texture and normal indices");
    if (t.grouping_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.grouping_lines) +
                               " group, object and smoothing-group lines (g, o, s); faces keep "
                               "the file's order");
    if (t.material_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.material_lines) +
                               " material lines (mtllib, usemtl); no material file is opened");
    if (t.unknown_lines > 0)
        report.notes.push_back("ignored " + std::to_string(t.unknown_lines) +
                               " lines with unknown keywords (first: " + t.first_unknown + ")");
}

// The lines of one part of the file, parsed into a mesh of their own. The first part is
// the file's start, so everything in it means what it means in the serial read. A later
// part starts at an unknown vertex count and line number; whatever needs those (a
// negative index, a note that names a line, an error) stops it with RangeNeedsContext or
// a FormatError, and the caller reads the file again serially.
struct ObjPart
{
    Mesh mesh;
    ObjTally tally;
    std::int64_t max_index = -1;   // the largest corner index, forward references included
    std::int64_t forward_line = 0; // where the largest forward reference is (first part)
    std::int64_t forward_column = 0;
};

struct RangeNeedsContext
{
};

ObjPart parse_part(std::string_view data, const std::string& name, bool first_part)
{
    ObjPart part;
    Mesh& mesh = part.mesh;
    ObjTally& tally = part.tally;
    LineReader reader(data, name);
    std::vector<Index> face;
    std::int64_t forward_max = -1;
    while (reader.next())
    {
        Tokenizer tokens(reader.line());
        const std::string_view keyword = tokens.next();
        if (keyword.empty() || keyword.front() == '#')
            continue;
        if (keyword == "v")
        {
            read_vertex(reader, tokens, mesh, tally);
            if (!first_part && tally.vertex_extras > 0)
                throw RangeNeedsContext{};
        }
        else if (keyword == "f")
        {
            const std::int64_t nv = mesh.vertex_count();
            face.clear();
            for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next())
            {
                if (!first_part && t.front() == '-')
                    throw RangeNeedsContext{};
                const std::int64_t index = corner_index(reader, t, nv);
                part.max_index = std::max(part.max_index, index);
                if (index >= nv && index > forward_max)
                {
                    forward_max = index;
                    part.forward_line = reader.line_number();
                    part.forward_column = reader.column_of(t);
                }
                face.push_back(static_cast<Index>(index));
            }
            if (face.size() < 3)
                reader.fail("face has " +
                            count_of(static_cast<std::int64_t>(face.size()), "vertex", "vertices") +
                            " (a face needs at least 3)");
            const FaceCheck check = normalize_face(face);
            if (!check.ok)
                reader.fail(check.problem, reader.column_of(keyword));
            if (check.collapsed > 0)
            {
                if (!first_part)
                    throw RangeNeedsContext{};
                tally.collapsed.add(check.collapsed,
                                    reader.here(reader.column_of(keyword)).to_string());
            }
            if (mesh.face_vertices.size() + face.size() > static_cast<size_t>(kMaxElements))
                reader.fail("more face corners than MeshFair supports");
            mesh.add_face(face);
        }
        else if (keyword == "l" || keyword == "p" || keyword == "curv" || keyword == "curv2" ||
                 keyword == "surf")
        {
            ++tally.ignored_lines;
        }
        else if (keyword == "vt" || keyword == "vn" || keyword == "vp")
        {
            ++tally.attribute_lines;
        }
        else if (keyword == "g" || keyword == "o" || keyword == "s")
        {
            ++tally.grouping_lines;
        }
        else if (keyword == "mtllib" || keyword == "usemtl")
        {
            ++tally.material_lines;
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

Mesh finish(ObjPart& part, const std::string& name, ReadReport& report)
{
    if (part.max_index >= part.mesh.vertex_count())
        throw FormatError(SourceLocation::text(name, part.forward_line, part.forward_column),
                          "vertex index " + std::to_string(part.max_index + 1) +
                              " is past the last vertex (the file defines " +
                              std::to_string(part.mesh.vertex_count()) + ")");
    add_notes(part.tally, report);
    return std::move(part.mesh);
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

// The parts joined in file order into the first one; false when a later part cannot be
// taken as it is (then the serial read decides).
bool join_parts(std::vector<ObjPart>& parts)
{
    ObjPart& all = parts.front();
    size_t nv = all.mesh.positions.size(), nc = all.mesh.face_vertices.size(),
           nf = all.mesh.face_offsets.size();
    for (size_t k = 1; k < parts.size(); ++k)
    {
        const ObjTally& t = parts[k].tally;
        all.tally.ignored_lines += t.ignored_lines;
        all.tally.attribute_lines += t.attribute_lines;
        all.tally.grouping_lines += t.grouping_lines;
        all.tally.material_lines += t.material_lines;
        all.max_index = std::max(all.max_index, parts[k].max_index);
        nv += parts[k].mesh.positions.size();
        nc += parts[k].mesh.face_vertices.size();
        nf += parts[k].mesh.face_offsets.size() - 1;
    }
    // The serial read's limits and its forward-reference message need the whole file.
    if (nv / 3 > static_cast<size_t>(kMaxVertices) || nc > static_cast<size_t>(kMaxElements) ||
        all.max_index >= static_cast<std::int64_t>(nv / 3))
        return false;
    Mesh& mesh = all.mesh;
    mesh.positions.reserve(nv);
    mesh.face_vertices.reserve(nc);
    mesh.face_offsets.reserve(nf);
    for (size_t k = 1; k < parts.size(); ++k)
    {
        const Mesh& m = parts[k].mesh;
        const Index base = static_cast<Index>(mesh.face_vertices.size());
        mesh.positions.insert(mesh.positions.end(), m.positions.begin(), m.positions.end());
        mesh.face_vertices.insert(mesh.face_vertices.end(), m.face_vertices.begin(),
                                  m.face_vertices.end());
        for (size_t f = 1; f < m.face_offsets.size(); ++f)
            mesh.face_offsets.push_back(base + m.face_offsets[f]);
        parts[k].mesh = Mesh{}; // frees the part as soon as it is copied
    }
    return true;
}

} // namespace

Mesh read_obj(std::string_view data, const std::string& name, ReadReport& report)
{
    // One range per thread, for files large enough to pay for waking the threads.
    constexpr size_t kBytesPerRange = size_t{4} << 20;
    const auto ranges = static_cast<int>(
        std::clamp<size_t>(data.size() / kBytesPerRange, 1, static_cast<size_t>(thread_count())));
    return read_obj_in_ranges(data, name, report, ranges);
}

Mesh read_obj_in_ranges(std::string_view data, const std::string& name, ReadReport& report,
                        int ranges, int* parsed_in)
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
            return finish(parts.front(), name, report);
        }
    }
    // One pass straight into the mesh: faces are normalized as they are read, so no
    // per-face bookkeeping outlives its line.
    ObjPart whole = parse_part(data, name, true);
    return finish(whole, name, report);
}

} // namespace meshfair::io
