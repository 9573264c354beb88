// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// RecordingRenderer, on which the editor's GL-free tests pick and select, held to the
// contract GlRenderer keeps through OSMesa (app/render/renderer.h): pick and visibility on
// the same meshes and views give the same answers. Both are compared with a reference
// computed here in double precision from the same projected vertices, the faces drawn as the
// fans both renderers draw, sampled at pixel centres. What rounding may decide either way is
// left out of the comparison, counted and bounded (check_views):
//  - a pixel is "on an edge" unless some triangle covers its centre for sure: by
//    kEdgeMarginPx or more, or with the centre that near one edge only and the triangle
//    across that edge on its other side (a silhouette, a boundary or a corner does not
//    count). What lies more than kDepthTie behind the covering triangle cannot show there;
//    pick's face is compared where everything that may show is of one face, its vertex and
//    point where one triangle alone may show, the nearest of its corners clear by
//    kCornerTiePx;
//  - a vertex's visibility (not behind the farthest surface of the 3 x 3 pixels around its
//    own by more than kVisibilityDepthMargin) is compared unless some depth each of those
//    pixels may hold by the rule above decides it the other way, within kDepthPrecision;
//  - a face's "shown" flag is compared where some pixel shows it for sure or none may.
// Everything compared must agree with the reference, so with each other, and GL and the
// recording must also disagree on few of the pixels, vertices and faces left out.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "app/editor/document.h"
#include "app/render/gl_renderer.h"
#include "app/render/recording_renderer.h"
#include "core/io/io.h"
#include "tests/app/render/render_support.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

//! A pixel centre nearer than this to an edge of a drawn triangle is on the edge: both
//! renderers sample at pixel centres, from the same float positions (GL snaps them to
//! 1/256 of a pixel and transforms them in float: both well under this).
constexpr double kEdgeMarginPx = 0.02;
//! Two corners whose distances to a pixel centre differ by less than this are a tie.
constexpr double kCornerTiePx = 0.01;
//! Window depths closer than this: either surface may be the one kept (GL keeps 24 bits
//! and the later of equal depths, the recording a float and the first).
constexpr double kDepthTie = 1e-5;
//! The depth buffers' precision, around the visibility rule's margin.
constexpr double kDepthPrecision = 1e-6;

// One triangle of a face's fan that may be drawn at a pixel centre.
struct Candidate
{
    double depth; // its plane's window depth at the centre
    Index face;
    std::array<Index, 3> corners;
    //! Signed distances in pixels from the centre to the lines of its edges (corner k to
    //! corner k + 1), positive inside; the smallest is more than -kEdgeMarginPx.
    std::array<double, 3> edge;
    double inside() const { return std::min({edge[0], edge[1], edge[2]}); }
};

// What the reference says of one pixel.
struct Pixel
{
    bool surface_possible = false; // a triangle may cover the centre
    bool surface_certain = false;  // some triangle covers it, whatever the rounding
    bool face_certain = false;     // ...and every triangle that may be in front is of one face
    bool vertex_certain = false;   // ...and one triangle alone, its nearest corner clear
    Index face = kInvalidIndex, vertex = kInvalidIndex;
    double depth = 1;                    // of that one triangle (vertex_certain)
    double min_depth = 1, max_depth = 0; // of what may be drawn there (surface_possible)
};

// The reference for one mesh in a width x height view.
struct Reference
{
    int width = 0, height = 0;
    std::vector<ScreenPoint> projected;
    std::vector<Pixel> pixels;
    //! Per face: shown for sure (the face of a face_certain pixel), or possibly (a triangle
    //! of it may be in front at some pixel).
    std::vector<char> face_shown, face_possible;
    const Pixel& at(int x, int y) const
    {
        return pixels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
    }
};

double cross(const ScreenPoint& o, const ScreenPoint& a, const ScreenPoint& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The largest depth at which the centre is covered for sure, by `t` (the centre inside it)
// or by `t` and the triangle across the one edge of it the centre is near: rasterized from
// the same corners, two triangles on both sides of their shared edge leave no gap along it
// (GL's rule gives a centre on the edge to one of them, the recording's to both). Infinity
// when that does not decide: near a corner, a silhouette or a boundary.
double covered_depth(const Candidate& t, const std::vector<Candidate>& here,
                     const std::vector<ScreenPoint>& projected)
{
    const double none = std::numeric_limits<double>::infinity();
    if (t.inside() < 0)
        return none;
    int near = -1;
    for (int k = 0; k < 3; ++k)
        if (t.edge[static_cast<size_t>(k)] < kEdgeMarginPx)
        {
            if (near >= 0)
                return none; // near two edges: a corner, around which a whole fan would count
            near = k;
        }
    if (near < 0)
        return t.depth;
    const Index u = t.corners[static_cast<size_t>(near)],
                v = t.corners[static_cast<size_t>((near + 1) % 3)],
                w = t.corners[static_cast<size_t>((near + 2) % 3)];
    const auto at = [&](Index i) { return projected[static_cast<size_t>(i)]; };
    double best = none;
    for (const Candidate& n : here)
    {
        const auto& c = n.corners;
        const bool has_u = std::find(c.begin(), c.end(), u) != c.end();
        const bool has_v = std::find(c.begin(), c.end(), v) != c.end();
        if (&n == &t || !has_u || !has_v)
            continue;
        const Index other = c[0] != u && c[0] != v ? c[0] : c[1] != u && c[1] != v ? c[1] : c[2];
        if (cross(at(u), at(v), at(w)) * cross(at(u), at(v), at(other)) < 0)
            best = std::min(best, std::max(t.depth, n.depth)); // on the other side
    }
    return best;
}

Reference make_reference(const Mesh& mesh, const Camera& camera, int width, int height)
{
    Reference ref;
    ref.width = width;
    ref.height = height;
    // The vertices where both renderers project them: their float copies (Renderer::set_mesh).
    const std::vector<float> positions(mesh.positions.begin(), mesh.positions.end());
    ref.projected = project_points(camera, positions, width, height);
    // Every view here keeps the whole mesh between the near and far planes, so that no
    // triangle is clipped (GL clips, the recording drops a triangle that crosses a plane).
    REQUIRE(std::all_of(ref.projected.begin(), ref.projected.end(),
                        [](const ScreenPoint& s) { return s.depth > 0 && s.depth < 1; }));
    std::vector<std::vector<Candidate>> candidates(static_cast<size_t>(width) *
                                                   static_cast<size_t>(height));
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const auto corners = mesh.face(f);
        for (size_t k = 1; k + 1 < corners.size(); ++k)
        {
            const std::array<Index, 3> tri{corners[0], corners[k], corners[k + 1]};
            const ScreenPoint& a = ref.projected[static_cast<size_t>(tri[0])];
            const ScreenPoint& b = ref.projected[static_cast<size_t>(tri[1])];
            const ScreenPoint& c = ref.projected[static_cast<size_t>(tri[2])];
            const double area = cross(a, b, c);
            if (area == 0)
                continue; // nothing drawn
            // The distance to edge ab is wc |area| / |ab|, and so on.
            const double to_ab = std::abs(area) / std::hypot(b.x - a.x, b.y - a.y),
                         to_bc = std::abs(area) / std::hypot(c.x - b.x, c.y - b.y),
                         to_ca = std::abs(area) / std::hypot(a.x - c.x, a.y - c.y);
            const double m = kEdgeMarginPx + 1;
            const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}) - m)));
            const int x1 =
                std::min(width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}) + m)));
            const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}) - m)));
            const int y1 =
                std::min(height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}) + m)));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                {
                    const ScreenPoint p{x + 0.5, y + 0.5, 0};
                    const double wa = cross(p, b, c) / area, wb = cross(p, c, a) / area;
                    const double wc = 1 - wa - wb;
                    const Candidate candidate{wa * a.depth + wb * b.depth + wc * c.depth,
                                              f,
                                              tri,
                                              {wc * to_ab, wa * to_bc, wb * to_ca}};
                    if (candidate.inside() > -kEdgeMarginPx)
                        candidates[static_cast<size_t>(y) * static_cast<size_t>(width) +
                                   static_cast<size_t>(x)]
                            .push_back(candidate);
                }
        }
    }
    ref.pixels.resize(candidates.size());
    ref.face_shown.assign(static_cast<size_t>(mesh.face_count()), 0);
    ref.face_possible.assign(ref.face_shown.size(), 0);
    for (size_t p = 0; p < candidates.size(); ++p)
    {
        const std::vector<Candidate>& here = candidates[p];
        Pixel& out = ref.pixels[p];
        if (here.empty())
            continue; // background for sure
        out.surface_possible = true;
        // The centre is covered for sure at this depth or nearer; what lies farther (by more
        // than a depth tie) cannot be in front there.
        double covered = std::numeric_limits<double>::infinity();
        for (const Candidate& t : here)
            covered = std::min(covered, covered_depth(t, here, ref.projected));
        out.surface_certain = covered < std::numeric_limits<double>::infinity();
        double lo = 2, hi = -1;
        std::vector<const Candidate*> plausible;
        for (const Candidate& c : here)
            if (c.depth <= covered + kDepthTie)
            {
                lo = std::min(lo, c.depth);
                hi = std::max(hi, c.depth);
                plausible.push_back(&c);
                ref.face_possible[static_cast<size_t>(c.face)] = 1;
            }
        out.min_depth = lo;
        out.max_depth = hi;
        if (!out.surface_certain)
            continue; // a silhouette, a boundary or a corner: the surface or what is behind
        out.face = plausible.front()->face;
        out.face_certain = std::all_of(plausible.begin(), plausible.end(),
                                       [&](const Candidate* c) { return c->face == out.face; });
        if (!out.face_certain)
            continue;
        ref.face_shown[static_cast<size_t>(out.face)] = 1;
        if (plausible.size() != 1 || plausible.front()->inside() < kEdgeMarginPx)
            continue;
        // The nearest corner of the triangle drawn there (PickResult).
        const Candidate& front = *plausible.front();
        const ScreenPoint centre{static_cast<double>(p % static_cast<size_t>(width)) + 0.5,
                                 static_cast<double>(p / static_cast<size_t>(width)) + 0.5, 0};
        std::array<std::pair<double, Index>, 3> by_distance;
        for (size_t k = 0; k < 3; ++k)
        {
            const ScreenPoint& s = ref.projected[static_cast<size_t>(front.corners[k])];
            by_distance[k] = {std::hypot(s.x - centre.x, s.y - centre.y), front.corners[k]};
        }
        std::sort(by_distance.begin(), by_distance.end());
        out.vertex = by_distance[0].second;
        out.depth = front.depth;
        out.vertex_certain = by_distance[1].first - by_distance[0].first >= kCornerTiePx;
    }
    return ref;
}

// A view of a mesh: its camera and where it lies in the framebuffer; picks at every
// stride-th pixel of every stride-th row (0: none, visibility only).
struct View
{
    std::string name;
    Camera camera;
    ViewRect rect;
    int stride = 2;
};

// What one view gave.
struct Tally
{
    int sampled = 0, surface = 0;        // pixels picked; those the reference may see a surface at
    int skipped = 0;                     // ...of which its face is left out
    int vertex_skipped = 0;              // ...of which only its vertex (and point) are left out
    int pick_differ = 0;                 // pixels GL and the recording pick differently
    int wrong_pick = 0, wrong_point = 0; // pixels either picks otherwise than the reference
    int in_view = 0, vertex_ambiguous = 0, vertex_differ = 0, wrong_vertex = 0;
    int faces_shown = 0, face_differ = 0, wrong_face = 0;
    int offset_differ = 0, wrong_projection = 0;
    std::string first_wrong; // where, for the message
};

std::ostream& operator<<(std::ostream& out, const Tally& t)
{
    return out << "picks: " << t.sampled << " pixels, " << t.surface << " on the surface, "
               << t.skipped << " left out (" << t.vertex_skipped << " more for the vertex), "
               << t.pick_differ << " picked differently by GL and the recording, " << t.wrong_pick
               << " otherwise than the reference (" << t.wrong_point << " surface points)"
               << t.first_wrong << "; vertices: " << t.in_view << " in the view, "
               << t.vertex_ambiguous << " left out, " << t.vertex_differ << " differ, "
               << t.wrong_vertex << " otherwise than the reference; faces: " << t.faces_shown
               << " shown by GL, " << t.face_differ << " differ, " << t.wrong_face
               << " otherwise than the reference; offset view: " << t.offset_differ
               << " differ from the whole view";
}

bool same_pick(const PickResult& a, const PickResult& b)
{
    return a.hit == b.hit && a.face == b.face && a.vertex == b.vertex;
}

// Picks and visibility of both renderers in one view, against the reference.
Tally compare(const Mesh& mesh, GlRenderer& gl, RecordingRenderer& recording, const View& view)
{
    const int width = view.rect.width, height = view.rect.height;
    const Camera& camera = view.camera;
    const Reference ref = make_reference(mesh, camera, width, height);
    // A view's pixels are its own, wherever it lies in the framebuffer.
    const ViewRect whole = ViewRect::whole(width, height);
    const bool offset = view.rect.x != 0 || view.rect.y != 0;
    Tally t;
    const auto wrong = [&](int x, int y, const PickResult& g, const PickResult& r) {
        if (!t.first_wrong.empty())
            return;
        const Pixel& p = ref.at(x, y);
        t.first_wrong = " (first at (" + std::to_string(x) + ", " + std::to_string(y) +
                        "): the reference's face " + std::to_string(p.face) + " vertex " +
                        std::to_string(p.vertex) + ", GL's " + std::to_string(g.face) + " " +
                        std::to_string(g.vertex) + ", the recording's " + std::to_string(r.face) +
                        " " + std::to_string(r.vertex) + ")";
    };
    for (int y = view.stride / 2; view.stride > 0 && y < height; y += view.stride)
        for (int x = view.stride / 2; x < width; x += view.stride)
        {
            const Pixel& p = ref.at(x, y);
            const PickResult g = gl.pick(camera, view.rect, x, y);
            const PickResult r = recording.pick(camera, view.rect, x, y);
            ++t.sampled;
            if (offset)
                t.offset_differ += same_pick(g, gl.pick(camera, whole, x, y)) &&
                                           same_pick(r, recording.pick(camera, whole, x, y))
                                       ? 0
                                       : 1;
            t.pick_differ += same_pick(g, r) ? 0 : 1;
            if (!p.surface_possible)
            {
                if (g.hit || r.hit)
                {
                    ++t.wrong_pick;
                    wrong(x, y, g, r);
                }
                continue;
            }
            ++t.surface;
            if (!p.face_certain)
            {
                ++t.skipped;
                continue;
            }
            if (!(g.hit && r.hit && g.face == p.face && r.face == p.face))
            {
                ++t.wrong_pick;
                wrong(x, y, g, r);
                continue;
            }
            if (!p.vertex_certain)
            {
                ++t.vertex_skipped;
                continue;
            }
            if (g.vertex != p.vertex || r.vertex != p.vertex)
            {
                ++t.wrong_pick;
                wrong(x, y, g, r);
            }
            // The surface point: the pixel centre unprojected at the depth drawn there.
            const glm::dvec3 point = camera.unproject({x + 0.5, y + 0.5, p.depth}, width, height);
            const double tolerance = 1e-4 * camera.scene_radius;
            t.wrong_point += glm::length(g.point - point) <= tolerance &&
                                     glm::length(r.point - point) <= tolerance
                                 ? 0
                                 : 1;
        }

    const Visibility g = gl.visibility(camera, view.rect);
    const Visibility r = recording.visibility(camera, view.rect);
    REQUIRE(g.vertices.size() == ref.projected.size());
    REQUIRE(r.vertices.size() == ref.projected.size());
    REQUIRE(g.projected.size() == ref.projected.size());
    REQUIRE(r.projected.size() == ref.projected.size());
    REQUIRE(g.faces.size() == ref.face_shown.size());
    REQUIRE(r.faces.size() == ref.face_shown.size());
    if (offset)
    {
        const Visibility gw = gl.visibility(camera, whole),
                         rw = recording.visibility(camera, whole);
        t.offset_differ += gw.vertices != g.vertices || gw.faces != g.faces ? 1 : 0;
        t.offset_differ += rw.vertices != r.vertices || rw.faces != r.faces ? 1 : 0;
    }
    for (size_t i = 0; i < ref.projected.size(); ++i)
    {
        const ScreenPoint& s = ref.projected[i];
        // Both project the vertices as the reference does, to the bit.
        t.wrong_projection += g.projected[i].x == s.x && g.projected[i].y == s.y &&
                                      g.projected[i].depth == s.depth && r.projected[i].x == s.x &&
                                      r.projected[i].y == s.y && r.projected[i].depth == s.depth
                                  ? 0
                                  : 1;
        t.vertex_differ += g.vertices[i] != r.vertices[i] ? 1 : 0;
        if (!(s.depth >= 0 && s.depth <= 1 && s.x >= 0 && s.y >= 0 && s.x < width && s.y < height))
        {
            t.wrong_vertex += g.vertices[i] == 0 && r.vertices[i] == 0 ? 0 : 1;
            continue;
        }
        ++t.in_view;
        // The renderers' rule: visible unless behind the farthest surface drawn in the 3 x 3
        // pixels around by more than the margin (nothing drawn there: visible). That
        // farthest depth is at least `lowest` (or nothing, when no pixel there is surface for
        // sure) and at most `highest`, whatever each pixel draws of what it may.
        bool any_certain = false, any_possible = false;
        double certain_floor = -1, possible_floor = 2, highest = -1;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
            {
                const Pixel& p = ref.at(std::clamp(static_cast<int>(s.x) + dx, 0, width - 1),
                                        std::clamp(static_cast<int>(s.y) + dy, 0, height - 1));
                if (!p.surface_possible)
                    continue;
                any_possible = true;
                highest = std::max(highest, p.max_depth);
                possible_floor = std::min(possible_floor, p.min_depth);
                if (p.surface_certain)
                {
                    any_certain = true;
                    certain_floor = std::max(certain_floor, p.min_depth);
                }
            }
        const double lowest = any_certain ? certain_floor : possible_floor;
        const bool visible =
            !any_possible || s.depth <= lowest + kVisibilityDepthMargin - kDepthPrecision;
        const bool hidden =
            any_certain && s.depth > highest + kVisibilityDepthMargin + kDepthPrecision;
        if (!visible && !hidden)
            ++t.vertex_ambiguous;
        else
            t.wrong_vertex += g.vertices[i] == visible && r.vertices[i] == visible ? 0 : 1;
    }
    // Faces: shown when some pixel shows them for sure, not shown when no pixel may.
    for (size_t f = 0; f < ref.face_shown.size(); ++f)
    {
        t.faces_shown += g.faces[f];
        t.face_differ += g.faces[f] != r.faces[f] ? 1 : 0;
        if (ref.face_shown[f] || !ref.face_possible[f])
            t.wrong_face +=
                g.faces[f] == ref.face_shown[f] && r.faces[f] == ref.face_shown[f] ? 0 : 1;
    }
    return t;
}

// Both renderers on `mesh` in each view, every answer the reference calls held to it, and
// what it leaves out bounded: pixels whose face it leaves out at most 3 % of those picked
// and 15 % of those on the surface (25 % with those whose vertex only it leaves out), GL
// and the recording picking differently at 1 % at most; vertices left out at most 2 + 6 %
// of those in the view, GL and the recording disagreeing on 2 + 0.1 % at most; faces shown
// by one of them only 1 + 1.5 % of those GL shows at most. (Measured with OSMesa 22,
// llvmpipe: at most 2.3 % of the pixels picked, 12.5 % of those on the surface, 4.8 % of the
// vertices; the renderers disagree at no pixel, on 13 of 34835 vertices and 76 of 7666
// faces shown.)
void check_views(const Mesh& mesh, const std::vector<View>& views)
{
    const Document d = make_document(mesh, "contract.obj");
    GlRenderer gl;
    gl.set_mesh(d.mesh, d.draw_data);
    RecordingRenderer recording;
    recording.set_mesh(d.mesh, d.draw_data);
    for (const View& view : views)
    {
        const Tally t = compare(d.mesh, gl, recording, view);
        INFO(view.name << ": " << t);
        CHECK(t.wrong_pick == 0);
        CHECK(t.wrong_point == 0);
        CHECK(t.wrong_vertex == 0);
        CHECK(t.wrong_face == 0);
        CHECK(t.wrong_projection == 0);
        CHECK(t.offset_differ == 0);
        CHECK(t.skipped <= 0.03 * t.sampled);
        CHECK(t.skipped <= 0.15 * t.surface);
        CHECK(t.skipped + t.vertex_skipped <= 0.25 * t.surface);
        CHECK(t.pick_differ <= 0.01 * t.sampled);
        CHECK(t.vertex_ambiguous <= 2 + 0.06 * t.in_view);
        CHECK(t.vertex_differ <= 2 + 0.001 * t.in_view);
        CHECK(t.face_differ <= 1 + 0.015 * t.faces_shown);
        // Each view shows something to check.
        CHECK(t.in_view > 0);
        CHECK(t.faces_shown > 0);
        if (view.stride > 0)
            CHECK(t.surface - t.skipped >= 40);
        if (view.name.starts_with("close-up"))
            CHECK(t.in_view < d.mesh.vertex_count()); // part of the mesh outside the view
    }
}

constexpr int kWidth = 64, kHeight = 48;

glm::dquat oblique()
{
    return glm::angleAxis(glm::radians(35.0), glm::dvec3(0, 1, 0)) *
           glm::angleAxis(glm::radians(-25.0), glm::dvec3(1, 0, 0));
}

std::string projection_name(Projection projection)
{
    return projection == Projection::Perspective ? "perspective" : "orthographic";
}

// Adds the front and then an oblique view of the whole of `box` in a width x height view,
// with picks at the given stride; returns the oblique camera, where close-ups start.
Camera add_front_and_oblique(std::vector<View>& views, const Box3& box, Projection projection,
                             int width, int height, int stride)
{
    const std::string name = projection_name(projection);
    Camera c;
    c.projection = projection;
    c.frame(box, double(width) / height);
    views.push_back({"front, " + name, c, ViewRect::whole(width, height), stride});
    c.rotation = oblique();
    views.push_back({"oblique, " + name, c, ViewRect::whole(width, height), stride});
    return c;
}

// Adds the second view (the oblique perspective one) again, as the part `rect` of a larger
// framebuffer.
void add_offset_copy(std::vector<View>& views, const ViewRect& rect)
{
    View offset = views[1];
    offset.name = "oblique, perspective, offset in the framebuffer";
    offset.rect = rect;
    views.push_back(offset);
}

// The front and an oblique view of the whole mesh, and a close-up of the oblique one with
// part of the mesh outside, each in perspective and orthographic; the oblique perspective
// view again as the right part of a larger framebuffer.
std::vector<View> standard_views(const Mesh& mesh)
{
    const Box3 box = app::bounding_box(mesh.positions);
    std::vector<View> views;
    for (const Projection projection : {Projection::Perspective, Projection::Orthographic})
    {
        Camera c = add_front_and_oblique(views, box, projection, kWidth, kHeight, 2);
        c.zoom(0.45, 0.3 * kWidth, 0.35 * kHeight, kWidth, kHeight);
        views.push_back(
            {"close-up, " + projection_name(projection), c, ViewRect::whole(kWidth, kHeight)});
    }
    add_offset_copy(views, ViewRect{100, 80, 30, 20, kWidth, kHeight});
    return views;
}

} // namespace

TEST_SUITE("Renderer contract")
{
    TEST_CASE("a tetrahedron: pick and visibility as GlRenderer's in every view")
    {
        test::offscreen_context(100, 80);
        check_views(test::tetrahedron(), standard_views(test::tetrahedron()));
    }

    TEST_CASE("a quad cube: the picked vertex is a corner of the fan triangle drawn there")
    {
        test::offscreen_context(100, 80);
        check_views(test::quad_cube(), standard_views(test::quad_cube()));
    }

    TEST_CASE("a noisy open grid of quads: its boundary and its fans' diagonals")
    {
        test::offscreen_context(100, 80);
        Mesh grid = test::open_grid(6, 4);
        test::perturb(grid, 0.08, 3); // non-planar quads: the fan's diagonal shows
        check_views(grid, standard_views(grid));
    }

    TEST_CASE("a non-manifold fan: three triangles on one edge")
    {
        test::offscreen_context(100, 80);
        check_views(test::nonmanifold_fan(), standard_views(test::nonmanifold_fan()));
    }

    TEST_CASE("the bunny: the visibility of its 35k vertices, picks in close-ups")
    {
        // Its triangles are about a pixel across in the whole views (256 x 192), where the
        // visibility is compared; a long lens on the top of the bunny (the background above)
        // makes them about 8 pixels across in a 64 x 48 view for the picks.
        const Mesh bunny = io::read_mesh((test::assets_dir() / "bunny.obj").string());
        const Box3 box = app::bounding_box(bunny.positions);
        const int w = 256, h = 192;
        test::offscreen_context(320, 240);
        std::vector<View> views;
        for (const Projection projection : {Projection::Perspective, Projection::Orthographic})
        {
            Camera c = add_front_and_oblique(views, box, projection, w, h, 0);
            c.frame(box, double(kWidth) / kHeight);
            Index top = 0;
            const auto at = [&](Index v) {
                const Vec3 p = bunny.position(v);
                return glm::dvec3(p[0], p[1], p[2]);
            };
            for (Index v = 1; v < bunny.vertex_count(); ++v)
                if (glm::dot(at(v), c.up()) > glm::dot(at(top), c.up()))
                    top = v;
            c.fov_y_degrees = 1;
            c.target = at(top) - 0.25 * c.view_height() * c.up(); // a quarter from the top
            views.push_back({"close-up, " + projection_name(projection), c,
                             ViewRect::whole(kWidth, kHeight), 6});
        }
        add_offset_copy(views, ViewRect{320, 240, 40, 30, w, h});
        check_views(bunny, views);
    }
}
