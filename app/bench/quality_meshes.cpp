// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/quality_meshes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "app/bench/vec3_math.h"
#include "core/geometry/face_geometry.h"

namespace meshfair::bench {

namespace {

Index add_vertex(Mesh& mesh, const Vec3& p)
{
    return mesh.add_vertex(p[0], p[1], p[2]);
}

void add_triangle(Mesh& mesh, Index a, Index b, Index c)
{
    const Index face[3] = {a, b, c};
    mesh.add_face(face);
}

// The surface points of the (n+1)^3 lattice of [-1, 1]^3, numbered on first use and placed
// by `place`, and its 6 n^2 squares facing outwards, as quads or split into two triangles.
// Integer lattice keys make the points shared by two faces the same vertex.
Mesh cube_surface(int n, bool quads, const std::function<Vec3(const Vec3&)>& place)
{
    if (n < 1)
        throw std::invalid_argument("cube_surface: n must be at least 1");
    Mesh mesh;
    const size_t m = static_cast<size_t>(n) + 1;
    std::vector<Index> id(m * m * m, kInvalidIndex);
    const auto vertex = [&](const std::array<int, 3>& g) {
        Index& v = id[(g[0] * m + g[1]) * m + g[2]];
        if (v == kInvalidIndex)
        {
            Vec3 c;
            for (int a = 0; a < 3; ++a)
                c[a] = -1 + 2 * Scalar(g[a]) / n;
            v = add_vertex(mesh, place(c));
        }
        return v;
    };
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side)
        {
            // (b, c) span the face with e_b x e_c pointing outwards.
            int b = (a + 1) % 3, c = (a + 2) % 3;
            if (side == 0)
                std::swap(b, c);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                {
                    const auto at = [&](int di, int dj) {
                        std::array<int, 3> g{};
                        g[a] = side * n;
                        g[b] = i + di;
                        g[c] = j + dj;
                        return vertex(g);
                    };
                    const Index p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
                    if (quads)
                    {
                        const Index quad[4] = {p00, p10, p11, p01};
                        mesh.add_face(quad);
                    }
                    else
                    {
                        add_triangle(mesh, p00, p10, p11);
                        add_triangle(mesh, p00, p11, p01);
                    }
                }
        }
    return mesh;
}

// --- Delaunay triangulation of a planar point set (Bowyer-Watson) ---

struct Point2
{
    Scalar x, y;
};

struct Triangle2
{
    std::array<int, 3> v;
    Scalar cx, cy, r2; // circumcircle
};

Triangle2 make_triangle(const std::vector<Point2>& p, int a, int b, int c)
{
    // Relative to a, for precision.
    const Scalar bx = p[b].x - p[a].x, by = p[b].y - p[a].y;
    const Scalar cx = p[c].x - p[a].x, cy = p[c].y - p[a].y;
    const Scalar d = 2 * (bx * cy - by * cx);
    const Scalar b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const Scalar ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
    return {{a, b, c}, p[a].x + ux, p[a].y + uy, ux * ux + uy * uy};
}

// Counter-clockwise Delaunay triangles over the points: those of the faces of
// convex_polyhedron_mesh (its sides' samples, which may be many per side, and lattice points
// well inside), whose result is checked there. A super-triangle 20 times the extent makes
// every hull edge between collinear side points appear: such a point lies on the chord of
// any circle through its neighbours, so strictly inside it. Each insertion tests every
// triangle, O(n^2): a few milliseconds for a face of a few thousand points.
std::vector<std::array<int, 3>> delaunay(std::vector<Point2> p)
{
    const int n = static_cast<int>(p.size());
    Scalar x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
    for (const Point2& q : p)
    {
        x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
    }
    const Scalar size = std::max(x1 - x0, y1 - y0), mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
    for (int k = 0; k < 3; ++k)
    {
        const Scalar angle = std::numbers::pi / 2 + 2 * std::numbers::pi * k / 3;
        p.push_back({mx + 20 * size * std::cos(angle), my + 20 * size * std::sin(angle)});
    }
    std::vector<Triangle2> triangles{make_triangle(p, n, n + 1, n + 2)};
    std::vector<std::pair<int, int>> cavity_edges;
    for (int i = 0; i < n; ++i)
    {
        cavity_edges.clear();
        std::erase_if(triangles, [&](const Triangle2& t) {
            const Scalar dx = p[i].x - t.cx, dy = p[i].y - t.cy;
            if (!(dx * dx + dy * dy < t.r2))
                return false;
            for (int k = 0; k < 3; ++k)
                cavity_edges.emplace_back(t.v[k], t.v[(k + 1) % 3]);
            return true;
        });
        // The cavity's border: edges whose reverse is not in it. Each keeps the cavity on
        // its left, so the new triangles are counter-clockwise.
        for (const auto& [a, b] : cavity_edges)
            if (std::find(cavity_edges.begin(), cavity_edges.end(), std::pair{b, a}) ==
                cavity_edges.end())
                triangles.push_back(make_triangle(p, a, b, i));
    }
    std::vector<std::array<int, 3>> out;
    for (const Triangle2& t : triangles)
        if (t.v[0] < n && t.v[1] < n && t.v[2] < n)
            out.push_back(t.v);
    return out;
}

Scalar cross2(const Point2& o, const Point2& a, const Point2& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// One face of a convex polyhedron: its unit outward normal and its corners, counter-clockwise
// seen from outside (indices into the welded corner list).
struct PolygonFace
{
    Vec3 normal;
    std::vector<int> corners;
};

// The polygon the other half-spaces cut from plane i (a large square clipped by each).
std::vector<Vec3> clip_plane(std::span<const HalfSpace> h, size_t i, Scalar big)
{
    const Vec3 n = h[i].normal;
    const Vec3 axis = std::abs(n[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalized(cross(n, axis)), v = cross(n, u);
    const Vec3 o = h[i].offset * n;
    std::vector<Vec3> polygon = {o + (-big) * u + (-big) * v, o + big * u + (-big) * v,
                                 o + big * u + big * v, o + (-big) * u + big * v};
    for (size_t j = 0; j < h.size() && polygon.size() >= 3; ++j)
    {
        if (j == i)
            continue;
        std::vector<Vec3> kept;
        const auto side = [&](const Vec3& p) { return dot(h[j].normal, p) - h[j].offset; };
        for (size_t k = 0; k < polygon.size(); ++k)
        {
            const Vec3& a = polygon[k];
            const Vec3& b = polygon[(k + 1) % polygon.size()];
            const Scalar sa = side(a), sb = side(b);
            if (sa <= 0)
                kept.push_back(a);
            if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0))
                kept.push_back(a + (sa / (sa - sb)) * (b - a));
        }
        polygon = std::move(kept);
    }
    return polygon;
}

// Meshes one convex face: `loop` are its boundary vertices in order (mesh indices), already
// in `mesh`; adds the lattice points inside and the Delaunay triangles.
void mesh_convex_face(Mesh& mesh, const Vec3& normal, const std::vector<Index>& loop,
                      const std::vector<Vec3>& corners, Scalar edge)
{
    const Vec3 o = corners[0];
    const Vec3 u = normalized(corners[1] - corners[0]), v = cross(normal, u);
    const auto to_2d = [&](const Vec3& p) { return Point2{dot(p - o, u), dot(p - o, v)}; };
    std::vector<Point2> points;
    std::vector<Index> ids = loop;
    for (const Index k : loop)
        points.push_back(to_2d(mesh.position(k)));
    std::vector<Point2> polygon;
    for (const Vec3& c : corners)
        polygon.push_back(to_2d(c));

    Scalar u0 = 0, u1 = 0, v1 = 0;
    for (const Point2& q : polygon)
        u0 = std::min(u0, q.x), u1 = std::max(u1, q.x), v1 = std::max(v1, q.y);
    const auto depth = [&](const Point2& q) { // distance inside the polygon (< 0 outside)
        Scalar d = std::numeric_limits<Scalar>::max();
        for (size_t k = 0; k < polygon.size(); ++k)
        {
            const Point2 &a = polygon[k], &b = polygon[(k + 1) % polygon.size()];
            d = std::min(d, cross2(a, b, q) / std::hypot(b.x - a.x, b.y - a.y));
        }
        return d;
    };
    // Rows parallel to the first edge, the first one row-height away from it.
    const Scalar row = edge * std::sqrt(Scalar(3)) / 2;
    for (int j = 1; j * row < v1; ++j)
        for (int i = static_cast<int>(std::floor(u0 / edge)) - 1; i * edge < u1 + edge; ++i)
        {
            const Point2 q{(i + 0.5 * (j % 2)) * edge, j * row};
            if (depth(q) >= 0.55 * edge)
            {
                points.push_back(q);
                const Vec3 p = o + q.x * u + q.y * v;
                ids.push_back(add_vertex(mesh, p));
            }
        }

    const std::vector<std::array<int, 3>> triangles = delaunay(points);
    // A triangulation of a convex polygon with b points on its border and i inside has
    // 2 i + b - 2 triangles covering its area.
    Scalar area = 0, polygon_area = 0;
    for (const auto& t : triangles)
        area += cross2(points[t[0]], points[t[1]], points[t[2]]) / 2;
    for (size_t k = 1; k + 1 < polygon.size(); ++k)
        polygon_area += cross2(polygon[0], polygon[k], polygon[k + 1]) / 2;
    const size_t interior = points.size() - loop.size();
    if (triangles.size() != 2 * interior + loop.size() - 2 ||
        std::abs(area - polygon_area) > 1e-9 * polygon_area)
        throw std::logic_error("convex_polyhedron_mesh: a face's triangulation failed");
    for (const auto& t : triangles)
        add_triangle(mesh, ids[t[0]], ids[t[1]], ids[t[2]]);
}

} // namespace

Mesh cube_mesh(int n, Scalar side)
{
    return cube_surface(n, false, [side](const Vec3& c) { return (side / 2) * c; });
}

Mesh rounded_box_quad_mesh(int n, Scalar corner_radius)
{
    if (!(corner_radius > 0 && corner_radius < 1))
        throw std::invalid_argument("rounded_box_quad_mesh: corner_radius must be in (0, 1)");
    const Scalar r = corner_radius;
    return cube_surface(n, true, [r](const Vec3& c) {
        Vec3 inner;
        for (int a = 0; a < 3; ++a)
            inner[a] = std::clamp(c[a], -(1 - r), 1 - r);
        // On the cube's surface, c - inner has length >= r (one coordinate is +-1).
        return inner + r * normalized(c - inner);
    });
}

Mesh revolve_profile(std::span<const ProfilePoint> profile, Scalar edge)
{
    const size_t rings = profile.size();
    if (rings < 3 || profile.front()[0] != 0 || profile.back()[0] != 0)
        throw std::invalid_argument("revolve_profile: the profile must run from pole to pole");
    Mesh mesh;
    std::vector<Index> first(rings), count(rings);
    std::vector<Scalar> phase(rings);
    for (size_t k = 0; k < rings; ++k)
    {
        const auto [rho, z] = profile[k];
        if ((k == 0 || k + 1 == rings) != (rho == 0) || rho < 0)
            throw std::invalid_argument("revolve_profile: only the ends may be on the axis");
        first[k] = mesh.vertex_count();
        count[k] = rho == 0 ? 1 : std::max(3L, std::lround(2 * std::numbers::pi * rho / edge));
        phase[k] = 0.5 * (k % 2);
        for (Index i = 0; i < count[k]; ++i)
        {
            const Scalar angle = 2 * std::numbers::pi * (i + phase[k]) / count[k];
            mesh.add_vertex(rho * std::cos(angle), rho * std::sin(angle), z);
        }
    }
    // The strip between rings a and b: walk both by angle, each step a triangle with the
    // next point of the ring whose next point comes first (a pole only ever gives its one).
    for (size_t a = 0; a + 1 < rings; ++a)
    {
        const size_t b = a + 1;
        const Index na = count[a], nb = count[b];
        const auto A = [&](Index i) { return first[a] + i % na; };
        const auto B = [&](Index j) { return first[b] + j % nb; };
        Index i = na == 1 ? 1 : 0, j = nb == 1 ? 1 : 0;
        while (i < na || j < nb)
        {
            const bool advance_a =
                j == nb || (i < na && (i + 1 + phase[a]) / na < (j + 1 + phase[b]) / nb);
            if (advance_a)
                add_triangle(mesh, A(i), A(i + 1), B(j)), ++i;
            else
                add_triangle(mesh, A(i), B(j + 1), B(j)), ++j;
        }
    }
    return mesh;
}

Mesh cylinder_mesh(Scalar radius, Scalar height, Scalar edge)
{
    // Rows one equilateral triangle's height apart, on the caps and on the side.
    const Scalar row = edge * std::sqrt(Scalar(3)) / 2;
    const long caps = std::max(1L, std::lround(radius / row));
    const long rows = std::max(1L, std::lround(height / row));
    std::vector<ProfilePoint> profile{{0, -height / 2}};
    for (long k = 1; k <= caps; ++k)
        profile.push_back({radius * k / caps, -height / 2});
    for (long j = 1; j <= rows; ++j)
        profile.push_back({radius, -height / 2 + height * j / rows});
    for (long k = caps - 1; k >= 0; --k)
        profile.push_back({radius * k / caps, height / 2});
    return revolve_profile(profile, edge);
}

Mesh cut_sphere_mesh(Scalar radius, Scalar z_low, Scalar z_high, Scalar edge)
{
    if (!(-radius < z_low && z_low < z_high && z_high < radius))
        throw std::invalid_argument("cut_sphere_mesh: need -radius < z_low < z_high < radius");
    const Scalar row = edge * std::sqrt(Scalar(3)) / 2;
    const Scalar rho_low = std::sqrt(radius * radius - z_low * z_low);
    const Scalar rho_high = std::sqrt(radius * radius - z_high * z_high);
    const long caps_low = std::max(1L, std::lround(rho_low / row));
    const long caps_high = std::max(1L, std::lround(rho_high / row));
    const Scalar phi_low = std::asin(z_low / radius), phi_high = std::asin(z_high / radius);
    const long rows = std::max(1L, std::lround(radius * (phi_high - phi_low) / row));
    std::vector<ProfilePoint> profile{{0, z_low}};
    for (long k = 1; k <= caps_low; ++k)
        profile.push_back({rho_low * k / caps_low, z_low});
    for (long j = 1; j < rows; ++j)
    {
        const Scalar phi = phi_low + (phi_high - phi_low) * j / rows;
        profile.push_back({radius * std::cos(phi), radius * std::sin(phi)});
    }
    for (long k = caps_high; k >= 0; --k)
        profile.push_back({rho_high * k / caps_high, z_high});
    return revolve_profile(profile, edge);
}

Mesh convex_polyhedron_mesh(std::span<const HalfSpace> half_spaces, Scalar edge)
{
    std::vector<HalfSpace> h(half_spaces.begin(), half_spaces.end());
    for (HalfSpace& s : h)
    {
        const Scalar length = std::sqrt(dot(s.normal, s.normal));
        s.normal = (1 / length) * s.normal;
        s.offset /= length;
    }
    // Corners of all faces, welded: each polyhedron corner is computed once per face.
    const Scalar big = 1e3;
    std::vector<Vec3> corners;
    std::vector<PolygonFace> faces;
    for (size_t i = 0; i < h.size(); ++i)
    {
        const std::vector<Vec3> polygon = clip_plane(h, i, big);
        PolygonFace face{h[i].normal, {}};
        for (const Vec3& p : polygon)
        {
            if (std::sqrt(dot(p, p)) > big / 2)
                throw std::invalid_argument("convex_polyhedron_mesh: the solid is unbounded");
            int id = 0;
            while (id < static_cast<int>(corners.size()) &&
                   std::sqrt(dot(corners[id] - p, corners[id] - p)) > 1e-9)
                ++id;
            if (id == static_cast<int>(corners.size()))
                corners.push_back(p);
            if (face.corners.empty() || (face.corners.back() != id && face.corners[0] != id))
                face.corners.push_back(id);
        }
        if (face.corners.size() < 3)
            throw std::invalid_argument("convex_polyhedron_mesh: half-space " + std::to_string(i) +
                                        " carries no face");
        faces.push_back(std::move(face));
    }

    Mesh mesh;
    for (const Vec3& c : corners)
        add_vertex(mesh, c);
    // Each edge's inner points, from its lower corner to its higher, shared by both faces.
    std::map<std::pair<int, int>, std::vector<Index>> edge_points;
    for (const PolygonFace& face : faces)
    {
        std::vector<Index> loop;
        std::vector<Vec3> face_corners;
        for (size_t k = 0; k < face.corners.size(); ++k)
        {
            const int a = face.corners[k], b = face.corners[(k + 1) % face.corners.size()];
            auto [it, is_new] = edge_points.try_emplace({std::min(a, b), std::max(a, b)});
            const Vec3 p = corners[std::min(a, b)], q = corners[std::max(a, b)];
            if (is_new)
            {
                const long segments =
                    std::max(1L, std::lround(std::sqrt(dot(q - p, q - p)) / edge));
                for (long s = 1; s < segments; ++s)
                    it->second.push_back(add_vertex(mesh, p + (Scalar(s) / segments) * (q - p)));
            }
            loop.push_back(a);
            face_corners.push_back(corners[a]);
            if (a < b)
                loop.insert(loop.end(), it->second.begin(), it->second.end());
            else
                loop.insert(loop.end(), it->second.rbegin(), it->second.rend());
        }
        mesh_convex_face(mesh, face.normal, loop, face_corners, edge);
    }
    return mesh;
}

std::vector<HalfSpace> cad_part_half_spaces()
{
    const HalfSpace chamfer{{0, -1, 1}, 0.7};      // through (y, z) = (0, 0.7) and (0.3, 1)
    const HalfSpace bevel{{0, 0.35, -0.6}, 0.315}; // through (y, z) = (0.9, 0) and (1.5, 0.35)
    const HalfSpace corner{{1, 1, 1}, 4}; // through (1.5, 1.5, 1), (2, 1, 1) and (2, 1.5, 0.5)
    return {{{-1, 0, 0}, 0},  {{1, 0, 0}, 2},  {{0, -1, 0}, 0},
            {{0, 1, 0}, 1.5}, {{0, 0, -1}, 0}, {{0, 0, 1}, 1},
            chamfer,          bevel,           corner};
}

Mesh cad_part_mesh(Scalar edge)
{
    return convex_polyhedron_mesh(cad_part_half_spaces(), edge);
}

namespace {

//! The faces of `mesh` that keep(f) accepts, with the vertices they use (renumbered in
//! order of first use).
template <class Keep>
Mesh faces_where(const Mesh& mesh, Keep keep)
{
    std::vector<Index> renumber(mesh.vertex_count(), kInvalidIndex);
    Mesh out;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        if (!keep(f))
            continue;
        std::vector<Index> face;
        for (const Index v : mesh.face(f))
        {
            if (renumber[v] == kInvalidIndex)
            {
                renumber[v] = out.vertex_count();
                out.add_vertex(mesh.positions[3 * v], mesh.positions[3 * v + 1],
                               mesh.positions[3 * v + 2]);
            }
            face.push_back(renumber[v]);
        }
        out.add_face(face);
    }
    return out;
}

} // namespace

Mesh scan_patch_mesh(Scalar edge)
{
    const auto height = [](Scalar x, Scalar y) {
        const Scalar ridge = 0.25 * std::max<Scalar>(0, 0.6 - std::abs(x - 0.1));
        const Scalar bump =
            0.12 * std::exp(-((x + 0.55) * (x + 0.55) + (y - 0.45) * (y - 0.45)) / 0.04);
        return ridge + bump;
    };
    const auto inside = [](Scalar x, Scalar y) {
        return std::hypot(x, y) < 1 + 0.08 * std::sin(5 * std::atan2(y, x));
    };
    const int n = static_cast<int>(std::ceil(2.2 / edge));
    Mesh mesh;
    std::vector<Index> id(static_cast<size_t>(n + 1) * (n + 1), kInvalidIndex);
    const auto at = [&](int i, int j) -> Index& {
        return id[static_cast<size_t>(j) * (n + 1) + i];
    };
    const auto point = [&](int i, int j) {
        return std::array<Scalar, 2>{-1.1 + i * edge, -1.1 + j * edge};
    };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
        {
            const auto [x, y] = point(i, j);
            if (inside(x, y))
            {
                at(i, j) = mesh.vertex_count();
                mesh.add_vertex(x, y, height(x, y));
            }
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            // Counter-clockwise seen from +z: the normals point up.
            const Index a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (a != kInvalidIndex && b != kInvalidIndex && c != kInvalidIndex)
                mesh.add_face(std::vector<Index>{a, b, c});
            if (a != kInvalidIndex && c != kInvalidIndex && d != kInvalidIndex)
                mesh.add_face(std::vector<Index>{a, c, d});
        }
    // Without the vertices no face uses (a corner of the disk's edge alone).
    return faces_where(mesh, [](Index) { return true; });
}

Mesh holed_part_mesh(Scalar edge)
{
    const Mesh part = cad_part_mesh(edge);
    // On the top (z = 1), the front (y = 0), the left (x = 0), the chamfer, the edge
    // x = 0, y = 0 (a crease) and the corner (0, 1.5, 1).
    const std::array<Vec3, 6> centres = {Vec3{1.0, 0.7, 1.0},  Vec3{1.2, 0.0, 0.4},
                                         Vec3{0.0, 0.8, 0.5},  Vec3{0.6, 0.15, 0.85},
                                         Vec3{0.0, 0.0, 0.45}, Vec3{0.0, 1.5, 1.0}};
    const Scalar radius = 0.12;
    return faces_where(part, [&](Index f) {
        const Vec3 c = face_centroid(part, part.positions, f);
        return std::ranges::none_of(centres, [&](const Vec3& p) {
            return std::hypot(c[0] - p[0], c[1] - p[1], c[2] - p[2]) < radius;
        });
    });
}

std::vector<std::string> generated_mesh_names()
{
    return {"cube", "cylinder", "cad-part", "cut-sphere", "quad-box", "scan-patch", "holed-part"};
}

Mesh generated_mesh(const std::string& name)
{
    if (name == "cube")
        return cube_mesh();
    if (name == "cylinder")
        return cylinder_mesh();
    if (name == "cad-part")
        return cad_part_mesh();
    if (name == "cut-sphere")
        return cut_sphere_mesh();
    if (name == "quad-box")
        return rounded_box_quad_mesh();
    if (name == "scan-patch")
        return scan_patch_mesh();
    if (name == "holed-part")
        return holed_part_mesh();
    std::string known;
    for (const std::string& n : generated_mesh_names())
        known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("generated_mesh: unknown mesh '" + name + "' (known: " + known +
                                ")");
}

} // namespace meshfair::bench
