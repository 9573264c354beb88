// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Golden images through OSMesa: every case renders one frame and compares it with its PNG
// in tests/app/render/golden/ (tolerances in render_support.h).
#include <doctest/doctest.h>

#include <cmath>

#include "tests/app/render/render_support.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

const Document& bunny()
{
    static const Document d = load_document((test::assets_dir() / "bunny.obj").string());
    return d;
}

Camera framed(const Document& d, int width, int height, StandardView view = StandardView::Front,
              Projection projection = Projection::Perspective)
{
    Camera c;
    c.projection = projection;
    c.set_view(view);
    c.frame(d.box, double(width) / height);
    return c;
}

// A 3/4 view from above and to the right.
Camera three_quarters(const Document& d, int width, int height)
{
    Camera c = framed(d, width, height);
    c.orbit(OrbitStyle::Turntable, 0, 0, -0.25 * height, -0.2 * height, width, height);
    return c;
}

Document warped_grid()
{
    Mesh g = test::open_grid(12, 8);
    for (size_t i = 0; i < g.positions.size(); i += 3)
        g.positions[i + 2] =
            0.8 * std::sin(0.5 * g.positions[i]) * std::cos(0.4 * g.positions[i + 1]);
    return make_document(std::move(g), "grid.obj");
}

} // namespace

TEST_SUITE("Golden images")
{
    TEST_CASE("bunny, flat shading")
    {
        DisplayOptions o;
        o.shading = Shading::Flat;
        test::check_golden("bunny_flat",
                           test::render_frame(bunny(), framed(bunny(), 640, 400), o, 640, 400));
    }

    TEST_CASE("bunny, smooth shading")
    {
        const DisplayOptions o;
        test::check_golden("bunny_smooth",
                           test::render_frame(bunny(), framed(bunny(), 640, 400), o, 640, 400));
    }

    TEST_CASE("bunny, orthographic front view")
    {
        const DisplayOptions o;
        test::check_golden(
            "bunny_ortho_front",
            test::render_frame(
                bunny(), framed(bunny(), 640, 400, StandardView::Front, Projection::Orthographic),
                o, 640, 400));
    }

    TEST_CASE("quad torus: the wireframe shows the quads' edges, not the fan diagonals")
    {
        const Document torus = make_document(test::quad_torus(24, 12, 1.0, 0.4), "torus.obj");
        DisplayOptions o;
        o.shading = Shading::Flat;
        o.wireframe = true;
        o.edge_width_px = 1.5f;
        test::check_golden("quad_torus_wireframe",
                           test::render_frame(torus, three_quarters(torus, 480, 480), o, 480, 480));
    }

    TEST_CASE("open grid: the boundary highlighted, the back faces tinted")
    {
        const Document grid = warped_grid();
        DisplayOptions o;
        o.wireframe = true;
        Camera c = three_quarters(grid, 560, 420);
        test::check_golden("open_grid_boundary", test::render_frame(grid, c, o, 560, 420));
        // From behind, the same grid shows its back faces, tinted.
        Camera back = framed(grid, 560, 420, StandardView::Back);
        back.orbit(OrbitStyle::Turntable, 0, 0, 0.2 * 420, -0.15 * 420, 560, 420);
        test::check_golden("open_grid_back_faces", test::render_frame(grid, back, o, 560, 420));
    }

    TEST_CASE("a non-manifold fan: its singular edge and boundary highlighted, vertex points")
    {
        const Document fan = make_document(test::nonmanifold_fan(), "fan.obj");
        DisplayOptions o;
        o.vertex_points = true;
        o.point_size_px = 9;
        o.edge_width_px = 1.5f;
        test::check_golden("nonmanifold_fan",
                           test::render_frame(fan, three_quarters(fan, 400, 400), o, 400, 400));
    }

    TEST_CASE("the whole interface at 1280 x 800")
    {
        const DisplayOptions o;
        test::check_golden("ui_full", test::render_frame(bunny(), framed(bunny(), 1280, 800), o,
                                                         1280, 800, {.ui = true}));
    }

    TEST_CASE("the help overlay lists the bindings over the interface")
    {
        const DisplayOptions o;
        test::check_golden("ui_help", test::render_frame(bunny(), framed(bunny(), 1280, 800), o,
                                                         1280, 800, {.ui = true, .help = true}));
    }

    TEST_CASE("a selection: faces tinted, vertices as dots")
    {
        const Document grid = warped_grid(); // 12 x 8 quads, 13 x 9 vertices
        std::vector<char> faces(static_cast<size_t>(grid.mesh.face_count()), 0);
        std::vector<char> vertices(static_cast<size_t>(grid.mesh.vertex_count()), 0);
        for (int y = 2; y < 5; ++y)
            for (int x = 3; x < 7; ++x)
                faces[static_cast<size_t>(y * 12 + x)] = 1;
        for (int x = 0; x < 13; ++x)
            vertices[static_cast<size_t>(7 * 13 + x)] = 1; // the row y = 7
        DisplayOptions o;
        o.wireframe = true;
        Camera c = framed(grid, 560, 420); // from the front, tilted a little
        c.orbit(OrbitStyle::Turntable, 0, 0, -0.1 * 420, -0.1 * 420, 560, 420);
        test::check_golden("selection_overlay", test::render_frame(grid, c, o, 560, 420,
                                                                   {.selected_vertices = vertices,
                                                                    .selected_faces = faces}));
    }

    TEST_CASE("the per-vertex colour overlay, here the height of an open grid")
    {
        const Document grid = warped_grid();
        std::vector<float> colors;
        for (size_t i = 0; i < grid.mesh.positions.size(); i += 3)
        {
            const float t = static_cast<float>(0.5 + 0.6 * grid.mesh.positions[i + 2]);
            colors.insert(colors.end(), {t, 0.3f, 1.0f - t});
        }
        DisplayOptions o;
        o.vertex_colors = true;
        test::check_golden("open_grid_vertex_colors",
                           test::render_frame(grid, three_quarters(grid, 560, 420), o, 560, 420,
                                              {.vertex_colors = colors}));
    }
}
