// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// The selection tools through an EditorSession drawing with a RecordingRenderer (picking and
// visibility by a software depth test, no GL): which elements a click, a rectangle, a lasso and a
// brush select from a known camera. The expected sets are worked out in world coordinates, not from
// the screen maths.
#include "app/editor/editor_session.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "app/render/recording_renderer.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

constexpr int kToolsWidth = 480, kToolsHeight = 480;
constexpr int kN = 10; // a 10 x 10 grid of unit quads, vertices at integer (x, y), z = 0

// A session on a grid seen from the front, orthographic, the whole framebuffer its view.
struct GridSession
{
    RecordingRenderer renderer;
    EditorSession session;
    explicit GridSession(Mesh mesh = test::open_grid(kN, kN))
        : session(make_document(std::move(mesh), "grid.obj"), renderer)
    {
        session.set_view_rect(ViewRect::whole(kToolsWidth, kToolsHeight));
        session.state().offscreen = true;
        Camera& c = session.camera();
        c.projection = Projection::Orthographic;
        c.frame(session.document().box, 1.0);
    }
    // Where a world point (z = 0) is in the view's pixels.
    ScreenPoint at(double x, double y, double z = 0) const
    {
        const glm::dvec3 w = session.camera().project({x, y, z}, kToolsWidth, kToolsHeight);
        return {w.x, w.y, 0};
    }
    void drag(std::initializer_list<ScreenPoint> path, Modifiers mods = {})
    {
        const ScreenPoint first = *path.begin(), last = *(path.end() - 1);
        session.mouse_press(MouseButton::Left, mods, first.x, first.y);
        for (const ScreenPoint& p : path)
            session.mouse_move(p.x, p.y);
        session.mouse_release(MouseButton::Left, last.x, last.y);
    }
    void click(ScreenPoint p, Modifiers mods = {})
    {
        session.mouse_press(MouseButton::Left, mods, p.x, p.y);
        session.mouse_release(MouseButton::Left, p.x, p.y);
    }
    std::vector<Index> vertices() const
    {
        return selected_indices(session.document().selected_vertices);
    }
    std::vector<Index> faces() const { return selected_indices(session.document().selected_faces); }
};

Index vertex(int x, int y)
{
    return static_cast<Index>(y * (kN + 1) + x);
}
Index face(int x, int y)
{
    return static_cast<Index>(y * kN + x);
}

// The grid vertices (x, y) for which `inside` holds, increasing.
template <class Inside>
std::vector<Index> grid_vertices(Inside inside)
{
    std::vector<Index> out;
    for (int y = 0; y <= kN; ++y)
        for (int x = 0; x <= kN; ++x)
            if (inside(double(x), double(y)))
                out.push_back(vertex(x, y));
    return out;
}

} // namespace

TEST_SUITE("Selection tools")
{
    TEST_CASE("a rectangle selects the vertices inside it, and Shift / Ctrl add and take away")
    {
        GridSession g;
        g.session.dispatch(cmd::SetTool{ToolKind::Rectangle});
        g.drag({g.at(2.5, 2.5), g.at(4, 4), g.at(5.5, 4.5)});
        CHECK(g.vertices() == grid_vertices([](double x, double y) {
                  return x >= 3 && x <= 5 && y >= 3 && y <= 4;
              }));
        CHECK(g.faces().empty());
        // Shift adds a second block; Ctrl then takes a column out of both.
        g.drag({g.at(6.5, 6.5), g.at(8.5, 7.5)}, {.shift = true});
        g.drag({g.at(4.5, 0.5), g.at(7.5, 9.5)}, {.ctrl = true});
        CHECK(g.vertices() == grid_vertices([](double x, double y) {
                  const bool a = x >= 3 && x <= 5 && y >= 3 && y <= 4;
                  const bool b = x >= 7 && x <= 8 && y == 7;
                  return (a || b) && !(x >= 5 && x <= 7);
              }));
        // Without a modifier the next rectangle replaces the selection.
        g.drag({g.at(0.5, 0.5), g.at(1.5, 1.5)});
        CHECK(g.vertices() == std::vector<Index>{vertex(1, 1)});
    }

    TEST_CASE("in face mode a rectangle selects the faces whose centroid is inside")
    {
        GridSession g;
        g.session.dispatch(cmd::SetTool{ToolKind::Rectangle});
        g.session.dispatch(cmd::SetElements{ElementKind::Faces});
        g.drag({g.at(2.1, 2.1), g.at(5.9, 4.9)});
        std::vector<Index> expected;
        for (int y = 0; y < kN; ++y)
            for (int x = 0; x < kN; ++x)
                if (x + 0.5 >= 2.1 && x + 0.5 <= 5.9 && y + 0.5 >= 2.1 && y + 0.5 <= 4.9)
                    expected.push_back(face(x, y));
        CHECK(g.faces() == expected);
        CHECK(expected.size() == 12);
        CHECK(g.vertices().empty());
    }

    TEST_CASE("a lasso selects what is inside the drawn curve")
    {
        GridSession g;
        g.session.dispatch(cmd::SetTool{ToolKind::Lasso});
        // A triangle with corners (1.5, 1.5), (8.5, 1.5), (1.5, 8.5), drawn with points
        // along its sides, as a mouse gives them.
        std::vector<ScreenPoint> curve;
        const double corners[4][2] = {{1.5, 1.5}, {8.5, 1.5}, {1.5, 8.5}, {1.5, 1.5}};
        for (int side = 0; side < 3; ++side)
            for (int k = 0; k < 20; ++k)
            {
                const double t = k / 20.0;
                curve.push_back(
                    g.at(corners[side][0] + t * (corners[side + 1][0] - corners[side][0]),
                         corners[side][1] + t * (corners[side + 1][1] - corners[side][1])));
            }
        const ScreenPoint first = curve.front();
        g.session.mouse_press(MouseButton::Left, {}, first.x, first.y);
        for (const ScreenPoint& p : curve)
            g.session.mouse_move(p.x, p.y);
        g.session.mouse_release(MouseButton::Left, first.x, first.y);
        // x + y = 10 is the hypotenuse; no grid vertex lies on it (x + y is an integer and
        // the line is x + y = 10 exactly: those are excluded below by a margin).
        CHECK(g.vertices() ==
              grid_vertices([](double x, double y) { return x >= 2 && y >= 2 && x + y <= 9; }));
    }

    TEST_CASE("a brush stroke selects what is within its radius of the path")
    {
        GridSession g;
        g.session.dispatch(cmd::SetTool{ToolKind::Brush});
        // Radius 1.3 grid units: from the path y = 5, x in [2, 8], the vertices at distance
        // 0 and 1 are in, those at sqrt(2) (diagonal from the ends) and 2 are out.
        const double px_per_unit = g.at(1, 0).x - g.at(0, 0).x;
        g.session.dispatch(cmd::SetBrushRadius{1.3 * px_per_unit});
        g.drag({g.at(2, 5), g.at(3.7, 5), g.at(6.1, 5), g.at(8, 5)});
        CHECK(g.vertices() == grid_vertices([](double x, double y) {
                  return (y == 5 && x >= 1 && x <= 9) || ((y == 4 || y == 6) && x >= 2 && x <= 8);
              }));
        // A fast stroke (two points far apart) leaves no gap: the dabs come closer.
        g.drag({g.at(1, 1), g.at(9, 1)});
        CHECK(g.vertices() == grid_vertices([](double x, double y) {
                  return (y == 1 && x >= 0 && x <= 10) || ((y == 0 || y == 2) && x >= 1 && x <= 9);
              }));
    }

    TEST_CASE("a click selects the nearest vertex of the face under it, or that face")
    {
        GridSession g;
        g.session.dispatch(cmd::SetTool{ToolKind::Click});
        g.click(g.at(3.2, 4.3));
        CHECK(g.vertices() == std::vector<Index>{vertex(3, 4)});
        g.click(g.at(6.7, 1.6), {.shift = true});
        CHECK(g.vertices() == std::vector<Index>{vertex(7, 2), vertex(3, 4)});
        g.session.dispatch(cmd::SetElements{ElementKind::Faces});
        g.click(g.at(3.2, 4.3));
        CHECK(g.faces() == std::vector<Index>{face(3, 4)});
        // On the background, without a modifier: nothing (the face selection is cleared).
        const ScreenPoint outside = g.at(-0.3, -0.3);
        REQUIRE(outside.x >= 0);
        g.click(outside);
        CHECK(g.faces().empty());
        CHECK(g.vertices().size() == 2); // the other mode's selection is not touched
    }

    TEST_CASE("front-facing only by default, 'through' also takes what is hidden")
    {
        // Two grids, one 1 unit behind the other, seen from the front: the back one is hidden.
        Mesh two = test::open_grid(kN, kN);
        const Mesh back = test::open_grid(kN, kN);
        const Index offset = two.vertex_count();
        for (size_t k = 0; k < back.positions.size(); k += 3)
            two.add_vertex(back.positions[k], back.positions[k + 1], -1.0);
        for (Index f = 0; f < back.face_count(); ++f)
        {
            std::vector<Index> q(back.face(f).begin(), back.face(f).end());
            for (Index& v : q)
                v += offset;
            two.add_face(q);
        }
        GridSession g(std::move(two));
        g.session.camera().projection = Projection::Orthographic;
        const double px_per_unit = g.at(1, 0).x - g.at(0, 0).x;
        g.session.dispatch(cmd::SetBrushRadius{0.25 * px_per_unit});
        for (const ToolKind tool : {ToolKind::Rectangle, ToolKind::Brush})
        {
            CAPTURE(tool_name(tool));
            g.session.dispatch(cmd::SetTool{tool});
            g.session.dispatch(cmd::SetThrough{false});
            g.session.dispatch(cmd::SetElements{ElementKind::Vertices});
            // The rectangle (3.4, 3.4)-(4.6, 4.6), or a brush of radius 0.25 along its
            // diagonal: vertex (4, 4) of the front grid only.
            g.drag({g.at(3.4, 3.4), g.at(4.6, 4.6)});
            CHECK(g.vertices() == std::vector<Index>{vertex(4, 4)});
            g.session.dispatch(cmd::SetElements{ElementKind::Faces});
            g.drag({g.at(3.4, 3.4), g.at(4.6, 4.6)});
            if (tool == ToolKind::Rectangle)
                CHECK(g.faces() ==
                      std::vector<Index>{face(3, 3), face(4, 3), face(3, 4), face(4, 4)});
            else
                CHECK(g.faces() == std::vector<Index>{face(3, 3), face(4, 4)});
            g.session.dispatch(cmd::SetThrough{true});
            g.drag({g.at(3.4, 3.4), g.at(4.6, 4.6)});
            CHECK(g.faces().size() == (tool == ToolKind::Rectangle ? 8 : 4));
            CHECK(g.faces().back() >= back.face_count()); // the hidden grid's faces too
            g.session.dispatch(cmd::SetElements{ElementKind::Vertices});
            g.drag({g.at(3.4, 3.4), g.at(4.6, 4.6)});
            CHECK(g.vertices() == std::vector<Index>{vertex(4, 4), vertex(4, 4) + offset});
        }
    }

    TEST_CASE("selection commands work on the current mode's selection")
    {
        GridSession g;
        g.session.dispatch(cmd::SetTool{ToolKind::Click});
        g.click(g.at(5.1, 5.1));
        g.session.dispatch(cmd::RunSelection{SelectionCommand::Grow});
        CHECK(g.vertices() == grid_vertices([](double x, double y) {
                  return std::abs(x - 5) + std::abs(y - 5) <= 1; // V(i) on a quad grid
              }));
        g.session.dispatch(cmd::RunSelection{SelectionCommand::Shrink});
        CHECK(g.vertices() == std::vector<Index>{vertex(5, 5)});
        g.session.dispatch(cmd::RunSelection{SelectionCommand::Boundary});
        CHECK(g.vertices().size() == 4 * kN);
        g.session.dispatch(cmd::RunSelection{SelectionCommand::Invert});
        CHECK(g.vertices().size() == (kN - 1) * (kN - 1));
        g.session.dispatch(cmd::SetElements{ElementKind::Faces});
        g.session.dispatch(cmd::RunSelection{SelectionCommand::All});
        CHECK(g.faces().size() == kN * kN);
        g.session.dispatch(cmd::RunSelection{SelectionCommand::Clear});
        CHECK(g.faces().empty());
        CHECK(g.vertices().size() == (kN - 1) * (kN - 1));
        // Each command that changed something is one step of the history.
        CHECK(g.session.history().undo_count() == 7);
    }
}
