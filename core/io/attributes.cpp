// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/attributes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/io/text_reader.h"

namespace meshfair::io {

namespace {

struct TypeFacts
{
    std::string_view name;
    size_t size;
    bool is_integer;
};

constexpr TypeFacts kTypeFacts[] = {
    {"char", 1, true}, {"uchar", 1, true}, {"short", 2, true},  {"ushort", 2, true},
    {"int", 4, true},  {"uint", 4, true},  {"float", 4, false}, {"double", 8, false},
};

const TypeFacts& facts(ValueType type)
{
    return kTypeFacts[static_cast<int>(type)];
}

} // namespace

std::string_view value_type_name(ValueType type)
{
    return facts(type).name;
}

size_t value_type_size(ValueType type)
{
    return facts(type).size;
}

bool is_integer_type(ValueType type)
{
    return facts(type).is_integer;
}

const Property* Element::find(std::span<const std::string_view> names) const
{
    for (const std::string_view wanted : names)
        for (const Property& p : properties)
            if (p.name == wanted && !p.is_list)
                return &p;
    return nullptr;
}

bool MeshAttributes::empty() const
{
    return vertex.properties.empty() && face.properties.empty() && other_elements.empty() &&
           texcoords.empty() && normals.empty() && statements.empty() && comments.empty();
}

bool Channels::contains(const Property* p) const
{
    const Property* all[] = {rgb[0],    rgb[1],    rgb[2], alpha, normal[0],
                             normal[1], normal[2], uv[0],  uv[1]};
    return p != nullptr && std::find(std::begin(all), std::end(all), p) != std::end(all);
}

Channels find_channels(const Element& table)
{
    Channels c;
    const Property* rgb[3] = {table.find(kRed), table.find(kGreen), table.find(kBlue)};
    if (rgb[0] && rgb[1] && rgb[2])
    {
        std::copy(std::begin(rgb), std::end(rgb), c.rgb);
        c.alpha = table.find(kAlpha);
    }
    const Property* n[3] = {table.find(kNormalX), table.find(kNormalY), table.find(kNormalZ)};
    if (n[0] && n[1] && n[2])
        std::copy(std::begin(n), std::end(n), c.normal);
    const Property* u = table.find(kTextureU);
    const Property* v = table.find(kTextureV);
    if (u && v)
    {
        c.uv[0] = u;
        c.uv[1] = v;
    }
    return c;
}

namespace {

void check_table(const Element& table, Index rows, const std::string& what)
{
    if (table.properties.empty())
        return;
    if (table.count != rows)
        throw InvalidInputError(what + " has " + std::to_string(table.count) +
                                " rows for a mesh with " + std::to_string(rows));
    for (const Property& p : table.properties)
    {
        const bool fits = p.is_list ? p.offsets.size() == static_cast<size_t>(rows) + 1 &&
                                          p.offsets.front() == 0 &&
                                          std::is_sorted(p.offsets.begin(), p.offsets.end()) &&
                                          static_cast<size_t>(p.offsets.back()) == p.values.size()
                                    : p.values.size() == static_cast<size_t>(rows);
        if (!fits)
            throw InvalidInputError(what + " property '" + p.name + "' does not have " +
                                    std::to_string(rows) + " rows");
    }
}

void check_corners(const Mesh& mesh, const CornerValues& c, const std::string& what)
{
    if (c.empty())
        return;
    if (c.corners.size() != static_cast<size_t>(mesh.corner_count()) || c.dimension <= 0 ||
        c.values.size() % static_cast<size_t>(c.dimension) != 0)
        throw InvalidInputError(what + " do not fit the mesh's corners");
    const Index entries = c.entry_count();
    for (const Index k : c.corners)
        if (k != kInvalidIndex && (k < 0 || k >= entries))
            throw InvalidInputError(what + " name entry " + std::to_string(k) + " of " +
                                    std::to_string(entries));
}

} // namespace

void check_attributes(const Mesh& mesh, const MeshAttributes& attributes)
{
    check_table(attributes.vertex, mesh.vertex_count(), "the vertex attributes");
    check_table(attributes.face, mesh.face_count(), "the face attributes");
    for (const Element& e : attributes.other_elements)
        check_table(e, e.count, "element '" + e.name + "'");
    check_corners(mesh, attributes.texcoords, "the texture coordinates");
    check_corners(mesh, attributes.normals, "the normals");
    for (const ObjStatement& s : attributes.statements)
        if (s.before_face < 0 || s.before_face > mesh.face_count())
            throw InvalidInputError("OBJ statement '" + s.text + "' is placed before face " +
                                    std::to_string(s.before_face) + " of " +
                                    std::to_string(mesh.face_count()));
}

namespace {

// The area vectors of every face: normals are sums of them.
std::vector<Vec3> area_vectors(const Mesh& mesh)
{
    std::vector<Vec3> a(static_cast<size_t>(mesh.face_count()));
    for (Index f = 0; f < mesh.face_count(); ++f)
        a[static_cast<size_t>(f)] = face_area_vector(mesh, mesh.positions, f);
    return a;
}

// `sum` normalized into `out`, which keeps its value when the sum has no direction.
void set_unit(const Vec3& sum, double* out[3])
{
    const double length = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    if (!(length > 0) || !std::isfinite(length))
        return;
    for (int a = 0; a < 3; ++a)
        *out[a] = sum[a] / length;
}

// The normals `nx ny nz` of `table` (found as `channels`) set to the unit vectors of `sums`,
// one per row.
void set_normals(Element& table, const Channels& channels, const std::vector<Vec3>& sums)
{
    Property* n[3];
    for (size_t a = 0; a < 3; ++a)
        n[a] = &table.properties[static_cast<size_t>(channels.normal[a] - table.properties.data())];
    for (size_t r = 0; r < sums.size(); ++r)
    {
        double* out[3] = {&n[0]->values[r], &n[1]->values[r], &n[2]->values[r]};
        set_unit(sums[r], out);
    }
}

} // namespace

void recompute_normals(const Mesh& mesh, MeshAttributes& attributes)
{
    const Channels vertex = find_channels(attributes.vertex);
    const Channels face = find_channels(attributes.face);
    if (!vertex.has_normal() && !face.has_normal() && attributes.normals.empty())
        return;
    const std::vector<Vec3> area = area_vectors(mesh);

    if (vertex.has_normal())
    {
        std::vector<Vec3> sum(static_cast<size_t>(mesh.vertex_count()), Vec3{0, 0, 0});
        for (Index f = 0; f < mesh.face_count(); ++f)
            for (const Index v : mesh.face(f))
                for (int a = 0; a < 3; ++a)
                    sum[static_cast<size_t>(v)][a] += area[static_cast<size_t>(f)][a];
        set_normals(attributes.vertex, vertex, sum);
    }
    if (face.has_normal())
        set_normals(attributes.face, face, area);
    CornerValues& normals = attributes.normals;
    if (!normals.empty() && normals.dimension == 3)
    {
        // One new entry per (vertex, old entry) pair, in order of first use.
        std::map<std::pair<Index, Index>, Index> entry_of;
        std::vector<Index> new_corners(normals.corners.size(), kInvalidIndex);
        std::vector<Vec3> sums;
        std::vector<Index> old_entry;
        for (Index f = 0; f < mesh.face_count(); ++f)
            for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
            {
                const Index old = normals.corners[static_cast<size_t>(k)];
                if (old == kInvalidIndex)
                    continue;
                const auto key = std::make_pair(mesh.face_vertices[static_cast<size_t>(k)], old);
                const auto [it, added] = entry_of.emplace(key, static_cast<Index>(sums.size()));
                if (added)
                {
                    sums.push_back(Vec3{0, 0, 0});
                    old_entry.push_back(old);
                }
                new_corners[static_cast<size_t>(k)] = it->second;
                for (int a = 0; a < 3; ++a)
                    sums[static_cast<size_t>(it->second)][a] += area[static_cast<size_t>(f)][a];
            }
        std::vector<double> values(3 * sums.size());
        for (size_t e = 0; e < sums.size(); ++e)
        {
            double* out[3] = {&values[3 * e], &values[3 * e + 1], &values[3 * e + 2]};
            for (int a = 0; a < 3; ++a)
                *out[a] =
                    normals.values[3 * static_cast<size_t>(old_entry[e]) + static_cast<size_t>(a)];
            set_unit(sums[e], out);
        }
        normals.values = std::move(values);
        normals.corners = std::move(new_corners);
    }
}

bool values_per_vertex(const Mesh& mesh, const CornerValues& corners,
                       std::vector<double>& per_vertex)
{
    const auto d = static_cast<size_t>(corners.dimension);
    per_vertex.assign(d * static_cast<size_t>(mesh.vertex_count()), 0.0);
    std::vector<char> seen(static_cast<size_t>(mesh.vertex_count()), 0);
    for (size_t k = 0; k < corners.corners.size(); ++k)
    {
        const Index e = corners.corners[k];
        if (e == kInvalidIndex)
            return false;
        const auto v = static_cast<size_t>(mesh.face_vertices[k]);
        const double* value = corners.values.data() + d * static_cast<size_t>(e);
        if (!seen[v])
        {
            std::copy(value, value + d, per_vertex.data() + d * v);
            seen[v] = 1;
        }
        else if (!std::equal(value, value + d, per_vertex.data() + d * v))
            return false;
    }
    return true;
}

std::vector<double> per_vertex_normals(const Mesh& mesh, const CornerValues& normals,
                                       std::int64_t& hard)
{
    hard = 0;
    std::vector<double> per_vertex;
    if (values_per_vertex(mesh, normals, per_vertex))
        return per_vertex;
    const auto nv = static_cast<size_t>(mesh.vertex_count());
    per_vertex.assign(3 * nv, 0.0);
    std::vector<char> differs(nv, 0);
    std::vector<Index> first(nv, kInvalidIndex);
    for (size_t k = 0; k < normals.corners.size(); ++k)
    {
        const Index e = normals.corners[k];
        if (e == kInvalidIndex)
            continue;
        const auto v = static_cast<size_t>(mesh.face_vertices[k]);
        if (first[v] == kInvalidIndex)
            first[v] = e;
        else if (first[v] != e)
            differs[v] = 1;
        for (size_t a = 0; a < 3; ++a)
            per_vertex[3 * v + a] += normals.values[3 * static_cast<size_t>(e) + a];
    }
    for (size_t v = 0; v < nv; ++v)
    {
        double* n = &per_vertex[3 * v];
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (length > 0)
            for (size_t a = 0; a < 3; ++a)
                n[a] /= length;
    }
    hard = std::count(differs.begin(), differs.end(), 1);
    return per_vertex;
}

std::string hard_edges_note(const std::string& format, std::int64_t hard)
{
    return format + " holds one normal per vertex: " + std::to_string(hard) +
           " vertices with different normals on different faces (hard edges) get their mean";
}

bool all_finite(std::span<const double> values)
{
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

std::string nonfinite_note(const std::string& format, const std::string& what)
{
    return format + " cannot hold NaN or infinite values: the " + what + " are not written";
}

namespace {

// `dimension` vertex columns as per-corner values: one entry per vertex, each corner
// naming its vertex's.
CornerValues vertex_columns_at_corners(const Mesh& mesh, const Property* const* columns,
                                       int dimension)
{
    CornerValues c;
    c.dimension = dimension;
    const auto d = static_cast<size_t>(dimension);
    c.values.resize(d * static_cast<size_t>(mesh.vertex_count()));
    for (size_t v = 0; v < static_cast<size_t>(mesh.vertex_count()); ++v)
        for (size_t a = 0; a < d; ++a)
            c.values[d * v + a] = columns[a]->values[v];
    c.corners = mesh.face_vertices;
    return c;
}

} // namespace

CornerValues corner_texcoords(const Mesh& mesh, const MeshAttributes& attributes,
                              const Property** source)
{
    if (source)
        *source = nullptr;
    if (!attributes.texcoords.empty())
        return attributes.texcoords;
    CornerValues c;
    for (const Property& p : attributes.face.properties)
        if (p.is_list && p.name == kCornerTexcoords)
        {
            // Two values per corner; a face whose list has another length has none.
            c.dimension = 2;
            c.values = p.values;
            c.corners.assign(static_cast<size_t>(mesh.corner_count()), kInvalidIndex);
            bool any = false;
            for (Index f = 0; f < mesh.face_count(); ++f)
            {
                const Index begin = p.offsets[static_cast<size_t>(f)];
                if (p.offsets[static_cast<size_t>(f) + 1] - begin != 2 * mesh.face_size(f))
                    continue;
                for (Index k = 0; k < mesh.face_size(f); ++k)
                    c.corners[static_cast<size_t>(mesh.face_offsets[f]) + static_cast<size_t>(k)] =
                        begin / 2 + k;
                any = true;
            }
            // Entries are pairs of values, so every list must start at an even offset.
            const bool aligned =
                std::all_of(p.offsets.begin(), p.offsets.end(), [](Index o) { return o % 2 == 0; });
            if (any && aligned)
            {
                if (source)
                    *source = &p;
                return c;
            }
            return {};
        }
    const Channels vertex = find_channels(attributes.vertex);
    if (!vertex.has_uv())
        return {};
    if (source)
        *source = vertex.uv[0];
    return vertex_columns_at_corners(mesh, vertex.uv, 2);
}

CornerValues corner_normals(const Mesh& mesh, const MeshAttributes& attributes)
{
    if (!attributes.normals.empty())
        return attributes.normals;
    const Channels vertex = find_channels(attributes.vertex);
    if (!vertex.has_normal())
        return {};
    return vertex_columns_at_corners(mesh, vertex.normal, 3);
}

namespace {

std::string type_list(const std::vector<const Property*>& ps)
{
    std::string names, types;
    for (const Property* p : ps)
    {
        names += (names.empty() ? "" : " ") + p->name;
        const std::string t(value_type_name(p->type));
        if (types.find(t) == std::string::npos)
            types += (types.empty() ? "" : ", ") + t;
    }
    return names + ": " + types;
}

void describe_table(const Element& table, const std::string& what, std::vector<std::string>& out)
{
    const Channels c = find_channels(table);
    if (c.has_colour())
    {
        std::vector<const Property*> ps(std::begin(c.rgb), std::end(c.rgb));
        if (c.alpha)
            ps.push_back(c.alpha);
        out.push_back(what + " colours (" + type_list(ps) + ")");
    }
    if (c.has_normal())
        out.push_back(what + " normals (" + type_list({c.normal[0], c.normal[1], c.normal[2]}) +
                      ")");
    if (c.has_uv())
        out.push_back(what + " texture coordinates (" + type_list({c.uv[0], c.uv[1]}) + ")");
    std::string rest;
    for (const Property& p : table.properties)
        if (!c.contains(&p))
            rest += (rest.empty() ? "" : ", ") + std::string("'") + p.name + "' (" +
                    (p.is_list ? "list of " : "") + std::string(value_type_name(p.type)) + ")";
    if (!rest.empty())
        out.push_back(what + " properties " + rest);
}

} // namespace

std::vector<std::string> describe_attributes(const MeshAttributes& a)
{
    std::vector<std::string> out;
    describe_table(a.vertex, "vertex", out);
    describe_table(a.face, "face", out);
    const auto corners_used = [](const CornerValues& c) {
        return std::count_if(c.corners.begin(), c.corners.end(),
                             [](Index k) { return k != kInvalidIndex; });
    };
    if (!a.texcoords.empty())
        out.push_back("texture coordinates: " + std::to_string(a.texcoords.entry_count()) +
                      " vt on " + std::to_string(corners_used(a.texcoords)) + " corners");
    if (!a.normals.empty())
        out.push_back("normals: " + std::to_string(a.normals.entry_count()) + " vn on " +
                      std::to_string(corners_used(a.normals)) + " corners");
    // The first few by name, the rest counted: a header of thousands of elements is a
    // line of the report, not thousands.
    const size_t listed = std::min(a.other_elements.size(), kElementsListed);
    for (size_t k = 0; k < listed; ++k)
    {
        const Element& e = a.other_elements[k];
        out.push_back(
            "element '" + e.name + "' (" + count_of(e.count, "row", "rows") + ", " +
            count_of(static_cast<std::int64_t>(e.properties.size()), "property", "properties") +
            ")");
    }
    if (a.other_elements.size() > listed)
    {
        std::int64_t rows = 0, properties = 0;
        for (size_t k = listed; k < a.other_elements.size(); ++k)
        {
            rows += a.other_elements[k].count;
            properties += static_cast<std::int64_t>(a.other_elements[k].properties.size());
        }
        out.push_back(count_of(static_cast<std::int64_t>(a.other_elements.size() - listed),
                               "more element", "more elements") +
                      " (" + count_of(rows, "row", "rows") + ", " +
                      count_of(properties, "property", "properties") + " in all)");
    }
    if (!a.statements.empty())
    {
        std::map<std::string, int> kinds;
        for (const ObjStatement& s : a.statements)
            ++kinds[s.text.substr(0, s.text.find(' '))];
        std::string list;
        for (const auto& [keyword, n] : kinds)
            list += (list.empty() ? "" : ", ") + std::to_string(n) + " " + keyword;
        out.push_back("groups and materials: " + list);
    }
    // MeshFair's own signature is not the file's content.
    const auto comments =
        std::count_if(a.comments.begin(), a.comments.end(),
                      [](const std::string& c) { return c != "comment MeshFair"; });
    if (comments > 0)
        out.push_back("header comments: " + std::to_string(comments));
    return out;
}

void Unwritten::add(const std::string& kind, const std::string& name)
{
    for (auto& [k, names] : kinds_)
        if (k == kind)
        {
            names.push_back(name);
            return;
        }
    kinds_.push_back({kind, {name}});
}

void Unwritten::add_table(const Element& table, const std::vector<const Property*>& written)
{
    for (const Property& p : table.properties)
        if (std::find(written.begin(), written.end(), &p) == written.end())
            add(table.name + " properties", "'" + p.name + "'");
}

void Unwritten::add_elements(const std::vector<Element>& elements)
{
    for (const Element& e : elements)
        add("elements", "'" + e.name + "' (" + count_of(e.count, "row", "rows") + ")");
}

void Unwritten::flush(std::vector<std::string>& notes) const
{
    for (const auto& [kind, names] : kinds_)
    {
        std::string list;
        for (size_t k = 0; k < names.size() && k < kElementsListed; ++k)
            list += (k == 0 ? "" : ", ") + names[k];
        if (names.size() > kElementsListed)
            list += " and " + std::to_string(names.size() - kElementsListed) + " more";
        notes.push_back(format_ + " cannot hold the " + kind + " " + list +
                        "; they are not written");
    }
}

} // namespace meshfair::io
