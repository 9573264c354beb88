// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "tests/fuzz/fuzz_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/errors.h"
#include "core/recipe/recipe.h"

namespace meshfair::fuzz {

namespace {

bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// The first whitespace-separated word after an optional UTF-8 byte-order mark.
std::string_view first_word(std::string_view data)
{
    if (data.starts_with("\xEF\xBB\xBF"))
        data.remove_prefix(3);
    size_t k = 0;
    while (k < data.size() && is_space(data[k]))
        ++k;
    size_t end = k;
    while (end < data.size() && !is_space(data[end]))
        ++end;
    return data.substr(k, end - k);
}

bool equals_ignoring_case(std::string_view a, std::string_view b)
{
    if (a.size() != b.size())
        return false;
    for (size_t k = 0; k < a.size(); ++k)
        if ((a[k] | 0x20) != (b[k] | 0x20))
            return false;
    return true;
}

bool bounded(double v)
{
    return std::abs(v) <= 1000;
}

bool bounded(const std::vector<Vec3>& points)
{
    for (const Vec3& p : points)
        if (!bounded(p[0]) || !bounded(p[1]) || !bounded(p[2]))
            return false;
    return true;
}

// A term's mu and its per-element weights mu * weights[k]: within what two numbers of
// +-1000 give (a list of sets is merged into mu = 1 and weights set.mu * set.weights[k]).
bool bounded(double mu, const std::vector<Scalar>& weights)
{
    return bounded(mu) && std::all_of(weights.begin(), weights.end(),
                                      [&](Scalar w) { return std::abs(mu * w) <= 1e6; });
}

} // namespace

bool verbose()
{
    static const bool on = std::getenv("MESHFAIR_FUZZ_VERBOSE") != nullptr;
    return on;
}

void fail(const std::string& what)
{
    std::fprintf(stderr, "fuzz target check failed: %s\n", what.c_str());
    std::fflush(stderr);
    __builtin_trap();
}

std::optional<Mesh> read_or_refuse(std::string_view data, io::Format format, io::ReadReport* report,
                                   io::MeshAttributes* attributes)
{
    std::optional<Mesh> mesh;
    try
    {
        mesh = io::read_mesh_data(data, format, "fuzz", report, attributes);
    }
    catch (const InvalidInputError& e)
    {
        if (verbose())
            std::fprintf(stderr, "refused: %s\n", e.what());
        return std::nullopt;
    }
    try
    {
        validate_mesh(*mesh);
        if (attributes)
            io::check_attributes(*mesh, *attributes); // what every writer requires
    }
    catch (const std::exception& e)
    {
        fail(std::string("accepted mesh fails validate_mesh: ") + e.what());
    }
    if (verbose())
        std::fprintf(stderr, "accepted: %d vertices, %d faces\n", mesh->vertex_count(),
                     mesh->face_count());
    return mesh;
}

io::Format sniff_format(std::string_view data)
{
    const std::string_view word = first_word(data);
    if (word == "ply")
        return io::Format::Ply;
    if (word.ends_with("OFF"))
        return io::Format::Off;
    if (data.size() >= 84)
    {
        std::uint32_t count = 0;
        for (int k = 3; k >= 0; --k)
            count = count << 8 | static_cast<unsigned char>(data[80 + static_cast<size_t>(k)]);
        if (data.size() == 84 + 50 * std::uint64_t{count})
            return io::Format::Stl;
    }
    if (equals_ignoring_case(word, "solid"))
        return io::Format::Stl;
    return io::Format::Obj;
}

std::string canned_ply_header(io::Encoding encoding, unsigned vertices, unsigned faces,
                              unsigned types)
{
    static constexpr const char* kCountTypes[] = {"uchar", "ushort", "uint", "int"};
    const char* coordinate = (types & 1) ? "double" : "float";
    std::string h = "ply\nformat ";
    h += io::encoding_name(encoding);
    h += " 1.0\nelement vertex " + std::to_string(vertices) + "\n";
    for (const char* axis : {"x", "y", "z"})
        h += std::string("property ") + coordinate + " " + axis + "\n";
    if (types & 16)
        h += "property uchar red\n";
    h += "element face " + std::to_string(faces) + "\nproperty list ";
    h += kCountTypes[(types >> 1) & 3];
    h += (types & 8) ? " uint" : " int";
    h += " vertex_indices\nend_header\n";
    return h;
}

std::string steer_ply(std::string_view data, io::Encoding encoding)
{
    const std::string format_line = "format " + std::string(io::encoding_name(encoding)) + " 1.0";
    if (!data.starts_with("ply"))
    {
        const auto byte = [&](size_t k) -> unsigned {
            return k < data.size() ? static_cast<unsigned char>(data[k]) : 0u;
        };
        std::string out = canned_ply_header(encoding, byte(0), byte(1), byte(2));
        if (data.size() > 3)
            out.append(data.substr(3));
        return out;
    }
    std::string out(data);
    const size_t header_end = std::min(out.find("end_header"), out.size());
    for (size_t k = out.find("format"); k < header_end; k = out.find("format", k + 1))
    {
        if (k == 0 || (out[k - 1] != '\n' && out[k - 1] != '\r'))
            continue;
        size_t end = k;
        while (end < out.size() && out[end] != '\n' && out[end] != '\r')
            ++end;
        out.replace(k, end - k, format_line);
        return out;
    }
    // No format line in the header: add one after the magic line.
    size_t magic_end = 3;
    while (magic_end < out.size() && out[magic_end] != '\n' && out[magic_end] != '\r')
        ++magic_end;
    if (magic_end == out.size())
        out += "\n" + format_line + "\n";
    else
        out.insert(magic_end + 1, format_line + "\n");
    return out;
}

bool identical(const Mesh& a, const Mesh& b)
{
    return a.positions.size() == b.positions.size() &&
           (a.positions.empty() || std::memcmp(a.positions.data(), b.positions.data(),
                                               a.positions.size() * sizeof(double)) == 0) &&
           a.face_offsets == b.face_offsets && a.face_vertices == b.face_vertices;
}

bool all_finite(const double* values, size_t count)
{
    for (size_t k = 0; k < count; ++k)
        if (!std::isfinite(values[k]))
            return false;
    return true;
}

Mesh small_mesh()
{
    Mesh m;
    for (const Vec3& p : std::initializer_list<Vec3>{{0, 0, 0},
                                                     {1, 0, 0},
                                                     {1, 1, 0},
                                                     {0, 1, 0},
                                                     {0, 0, 1},
                                                     {1, 0, 1},
                                                     {1, 1, 1},
                                                     {0, 1, 1},
                                                     {0.5, 1.5, 0.5},
                                                     {-0.5, 0.5, 0.5}})
        m.add_vertex(p[0], p[1], p[2]);
    const std::initializer_list<std::initializer_list<Index>> faces = {
        {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5},
        {2, 3, 8},    {3, 7, 8},    {3, 0, 9},    {0, 4, 7, 3, 9}};
    for (const auto& f : faces)
        m.add_face(std::vector<Index>(f));
    return m;
}

// Every number of the recipe is within +-1000 (weights, step lengths, targets, normals).
bool bounded(const Recipe& r)
{
    bool ok = (r.optimal_step || bounded(r.lambda)) && bounded(r.tolerance);
    if (r.hard)
        ok = ok && bounded(r.hard->targets);
    if (r.soft)
        ok = ok && bounded(r.soft->mu, r.soft->weights) && bounded(r.soft->targets);
    if (r.centroid)
        ok = ok && bounded(r.centroid->mu, r.centroid->weights) && bounded(r.centroid->targets);
    if (r.normal)
        ok = ok && bounded(r.normal->mu, r.normal->weights) && bounded(r.normal->normals);
    if (r.normal_smoothing)
    {
        const NormalSmoothing& ns = *r.normal_smoothing;
        ok = ok && bounded(ns.lambda) && bounded(ns.hard.normals) &&
             bounded(ns.soft.mu, ns.soft.weights) && bounded(ns.soft.normals);
    }
    if (r.joint)
        ok = ok && bounded(r.joint->gamma);
    return ok;
}

} // namespace meshfair::fuzz
