// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// GlRenderer through OSMesa: picking through the ID buffer at known pixels, position
// updates that reallocate nothing, and refusals.
#include "app/render/gl_renderer.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "app/render/gl_functions.h"
#include "app/render/render_error.h"
#include "tests/app/render/render_support.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

constexpr int kRendererWidth = 400, kRendererHeight = 200;

// Two unit quads side by side in z = 0, (0, 0) to (2, 1), seen from the front.
struct TwoQuads
{
    Document document = make_document(test::open_grid(2, 1), "two_quads.obj");
    Camera camera;
    TwoQuads(Projection projection)
    {
        camera.projection = projection;
        camera.frame(document.box, double(kRendererWidth) / kRendererHeight);
    }
};

} // namespace

TEST_SUITE("GlRenderer")
{
    TEST_CASE("pick returns the face, the nearest corner and the surface point at a pixel")
    {
        for (const Projection projection : {Projection::Orthographic, Projection::Perspective})
        {
            test::offscreen_context(kRendererWidth, kRendererHeight);
            TwoQuads s(projection);
            GlRenderer r;
            r.set_mesh(s.document.mesh, s.document.draw_data);
            const auto pixel_of = [&](glm::dvec3 p) {
                const glm::dvec3 w = s.camera.project(p, kRendererWidth, kRendererHeight);
                return std::pair{int(w.x), int(w.y)};
            };
            // Inside the left quad, near its corner (0, 1): vertex 3 of the 3 x 2 grid.
            auto [x, y] = pixel_of({0.1, 0.85, 0});
            PickResult p = r.pick(s.camera, ViewRect::whole(kRendererWidth, kRendererHeight), x, y);
            REQUIRE(p.hit);
            CHECK(p.face == 0);
            CHECK(p.vertex == 3);
            CHECK(p.point.x == doctest::Approx(0.1).epsilon(0.02));
            CHECK(p.point.y == doctest::Approx(0.85).epsilon(0.02));
            CHECK(std::abs(p.point.z) < 1e-3);
            // Inside the right quad, near (2, 0): vertex 2.
            std::tie(x, y) = pixel_of({1.9, 0.1, 0});
            p = r.pick(s.camera, ViewRect::whole(kRendererWidth, kRendererHeight), x, y);
            REQUIRE(p.hit);
            CHECK(p.face == 1);
            CHECK(p.vertex == 2);
            // The window's corner is background.
            CHECK_FALSE(
                r.pick(s.camera, ViewRect::whole(kRendererWidth, kRendererHeight), 0, 0).hit);
            CHECK_FALSE(r.pick(s.camera, ViewRect::whole(kRendererWidth, kRendererHeight), -1, 5)
                            .hit); // outside the window
        }
    }

    TEST_CASE("a view inside a larger framebuffer picks in its own pixels")
    {
        // The view is the right 300 x 150 of a 400 x 200 framebuffer, 50 rows down.
        test::offscreen_context(kRendererWidth, kRendererHeight);
        const ViewRect rect{kRendererWidth, kRendererHeight, 100, 50, 300, 150};
        Document d = make_document(test::open_grid(2, 1), "two_quads.obj");
        Camera c;
        c.projection = Projection::Orthographic;
        c.frame(d.box, double(rect.width) / rect.height);
        GlRenderer r;
        r.set_mesh(d.mesh, d.draw_data);
        r.draw(c, DisplayOptions{}, rect);
        const glm::dvec3 w = c.project({1.5, 0.5, 0}, rect.width, rect.height);
        const PickResult p = r.pick(c, rect, int(w.x), int(w.y));
        REQUIRE(p.hit);
        CHECK(p.face == 1);
        CHECK(p.point.x == doctest::Approx(1.5).epsilon(0.02));
        // The frame shows the mesh there too: that pixel of the framebuffer is the surface.
        const Image image = r.read_pixels(kRendererWidth, kRendererHeight);
        const size_t at =
            4 * (size_t(rect.y + int(w.y)) * kRendererWidth + size_t(rect.x + int(w.x)));
        const DisplayOptions o;
        CHECK(std::abs(int(image.rgba[at]) - int(o.background[0] * 255)) > 40);
        // ...and left of the view, where nothing is drawn, the background.
        CHECK(std::abs(int(image.rgba[4 * (size_t(100) * kRendererWidth + 20)]) -
                       int(o.background[0] * 255 + 0.5f)) <= 1);
    }

    TEST_CASE(
        "visibility: a sphere's vertices in front of its silhouette are shown, the others not")
    {
        test::offscreen_context(kRendererWidth, kRendererHeight);
        const Document sphere = make_document(test::icosphere(3), "sphere.obj");
        Camera c;
        c.frame(sphere.box, double(kRendererWidth) / kRendererHeight); // front view: the eye on +z
        GlRenderer r;
        r.set_mesh(sphere.mesh, sphere.draw_data);
        const Visibility v = r.visibility(c, ViewRect::whole(kRendererWidth, kRendererHeight));
        REQUIRE(v.vertices.size() == static_cast<size_t>(sphere.mesh.vertex_count()));
        REQUIRE(v.projected.size() == v.vertices.size());
        // Seen from distance d, a unit sphere's silhouette is the circle z = 1 / d: the eye
        // sees less than the front half.
        const double silhouette = 1 / c.distance;
        int near_shown = 0, near = 0, far_shown = 0, far = 0;
        for (size_t i = 0; i < v.vertices.size(); ++i)
        {
            const double z = sphere.mesh.positions[3 * i + 2];
            if (z > silhouette + 0.1)
            {
                ++near;
                near_shown += v.vertices[i];
            }
            if (z < silhouette - 0.1)
            {
                ++far;
                far_shown += v.vertices[i];
            }
        }
        CHECK(far > 200);
        CHECK(near > 100);
        CHECK(near_shown == near);
        CHECK(far_shown == 0);
        // Faces: those facing the eye are in the ID buffer, those facing away are not.
        int facing_shown = 0, facing = 0, away_shown = 0;
        for (Index f = 0; f < sphere.mesh.face_count(); ++f)
        {
            double z = 0;
            for (const Index i : sphere.mesh.face(f))
                z += sphere.mesh.positions[3 * static_cast<size_t>(i) + 2] / 3;
            if (z > silhouette + 0.1)
            {
                ++facing;
                facing_shown += v.faces[static_cast<size_t>(f)];
            }
            if (z < silhouette - 0.1)
                away_shown += v.faces[static_cast<size_t>(f)];
        }
        CHECK(facing_shown == facing);
        CHECK(away_shown == 0);
    }

    TEST_CASE("visibility: a vertex hidden behind a nearer face is not shown")
    {
        test::offscreen_context(kRendererWidth, kRendererHeight);
        // A big quad at z = 1 in front of a small one at z = 0 (the eye on +z).
        const Document d = make_document(test::make_mesh({{-2, -2, 1},
                                                          {2, -2, 1},
                                                          {2, 2, 1},
                                                          {-2, 2, 1},
                                                          {-0.5, -0.5, 0},
                                                          {0.5, -0.5, 0},
                                                          {0.5, 0.5, 0},
                                                          {-0.5, 0.5, 0}},
                                                         {{0, 1, 2, 3}, {4, 5, 6, 7}}),
                                         "layers.obj");
        Camera c;
        c.frame(d.box, double(kRendererWidth) / kRendererHeight);
        GlRenderer r;
        r.set_mesh(d.mesh, d.draw_data);
        const Visibility v = r.visibility(c, ViewRect::whole(kRendererWidth, kRendererHeight));
        CHECK(std::count(v.vertices.begin(), v.vertices.begin() + 4, 1) == 4);
        CHECK(std::count(v.vertices.begin() + 4, v.vertices.end(), 1) == 0);
        CHECK(v.faces == std::vector<char>{1, 0});
    }

    TEST_CASE("updating positions re-uploads without reallocating, and the picture follows")
    {
        test::offscreen_context(kRendererWidth, kRendererHeight);
        TwoQuads s(Projection::Orthographic);
        GlRenderer r;
        r.set_mesh(s.document.mesh, s.document.draw_data);
        // One allocation per buffer of a mesh: positions, normals, area vectors, triangle
        // faces and sides, face and vertex selection flags, boundary, singular edges,
        // triangles.
        const int allocations = r.buffer_allocations();
        CHECK(allocations == 10);
        const DisplayOptions o;
        r.draw(s.camera, o, ViewRect::whole(kRendererWidth, kRendererHeight));
        const Image before = r.read_pixels(kRendererWidth, kRendererHeight);
        // Move the mesh half a unit down: the top row of pixels it covered is background.
        std::vector<Scalar> moved = s.document.mesh.positions;
        for (size_t i = 1; i < moved.size(); i += 3)
            moved[i] -= 0.5;
        r.update_positions(moved);
        r.draw(s.camera, o, ViewRect::whole(kRendererWidth, kRendererHeight));
        const Image after = r.read_pixels(kRendererWidth, kRendererHeight);
        CHECK(r.buffer_allocations() == allocations);
        const ImageDifference d = compare_images(before, after, 8);
        CHECK(d.fraction_over_tolerance > 0.05);
        const auto [x, y] =
            std::pair{kRendererWidth / 2,
                      int(s.camera.project({1, 0.9, 0}, kRendererWidth, kRendererHeight).y)};
        CHECK(r.pick(s.camera, ViewRect::whole(kRendererWidth, kRendererHeight), x, y).hit ==
              false);
        r.set_mesh(s.document.mesh, s.document.draw_data); // a new connectivity does allocate
        CHECK(r.buffer_allocations() == 2 * allocations);
    }

    TEST_CASE(
        "the face area vectors go up only while flat shading shows them, and a flat "
        "frame after smooth ones shows the shape of the last update")
    {
        test::offscreen_context(kRendererWidth, kRendererHeight);
        Document d = make_document(test::open_grid(6, 3), "bumps.obj");
        Camera camera;
        camera.frame(d.box, double(kRendererWidth) / kRendererHeight);
        // Bumps in z: faces of many orientations, each its own flat shade.
        std::vector<Scalar> moved = d.mesh.positions;
        for (size_t i = 0; i < moved.size(); i += 3)
            moved[i + 2] = 0.3 * std::sin(2.0 * moved[i]) * std::cos(3.0 * moved[i + 1]);
        DisplayGeometry frame; // of no run: uploaded whole
        update_display_geometry(moved, d.mesh, d.draw_data.vertex_face_offsets,
                                d.draw_data.vertex_faces, 0, nullptr, frame);
        const ViewRect whole = ViewRect::whole(kRendererWidth, kRendererHeight);
        DisplayOptions smooth, flat;
        flat.shading = Shading::Flat;

        GlRenderer r;
        r.set_mesh(d.mesh, d.draw_data);
        r.draw(camera, smooth, whole);
        const int uploads = r.face_area_uploads();
        r.update_geometry(frame); // smooth shading: positions and normals
        CHECK(r.face_area_uploads() == uploads);
        r.draw(camera, smooth, whole);
        const Image smooth_image = r.read_pixels(kRendererWidth, kRendererHeight);
        CHECK(r.face_area_uploads() == uploads);
        r.draw(camera, flat, whole); // turned on: the area vectors of the moved shape, once
        CHECK(r.face_area_uploads() == uploads + 1);
        const Image flat_image = r.read_pixels(kRendererWidth, kRendererHeight);
        r.draw(camera, flat, whole);
        CHECK(r.face_area_uploads() == uploads + 1);
        r.update_geometry(frame); // flat shown: uploaded with the rest
        CHECK(r.face_area_uploads() == uploads + 2);

        // The same picture as a renderer given the moved shape whole, and not the smooth one.
        GlRenderer reference;
        reference.set_mesh(d.mesh, d.draw_data);
        reference.update_positions(moved);
        reference.draw(camera, flat, whole);
        const Image expected = reference.read_pixels(kRendererWidth, kRendererHeight);
        CHECK(compare_images(flat_image, expected, 1).pixels_over_tolerance == 0);
        CHECK(compare_images(flat_image, smooth_image, 8).fraction_over_tolerance > 0.02);
    }

    TEST_CASE("a run's frames upload only its changing part and show what a whole upload shows")
    {
        test::offscreen_context(kRendererWidth, kRendererHeight);
        Document d = make_document(test::open_grid(24, 12), "grid.obj");
        Camera camera;
        camera.frame(d.box, double(kRendererWidth) / kRendererHeight);
        const ViewRect whole = ViewRect::whole(kRendererWidth, kRendererHeight);
        // A quarter of the vertices in the document's (locality) numbering, as a region.
        std::vector<Index> free(static_cast<size_t>(d.mesh.vertex_count() / 4));
        std::iota(free.begin(), free.end(), 0);
        const auto part = std::make_shared<const ChangingPart>(
            changing_part(d.mesh, d.draw_data.vertex_face_offsets, d.draw_data.vertex_faces, free));
        const size_t nv = static_cast<size_t>(d.mesh.vertex_count());
        REQUIRE(part->vertices.count() < static_cast<Index>(nv / 2));
        const std::uint64_t run = new_display_run();
        std::vector<Scalar> x = d.mesh.positions;
        DisplayGeometry g;
        const auto frame = [&](double height) { // the free vertices rise, nothing else moves
            for (const Index v : free)
                x[3 * v + 2] = height * std::sin(3.0 * x[3 * v]) * std::cos(2.0 * x[3 * v + 1]);
            update_display_geometry(x, d.mesh, d.draw_data.vertex_face_offsets,
                                    d.draw_data.vertex_faces, run, part, g);
        };
        const auto reference_image = [&](const DisplayOptions& options) {
            GlRenderer reference;
            reference.set_mesh(d.mesh, d.draw_data);
            reference.update_positions(x);
            reference.draw(camera, options, whole);
            return reference.read_pixels(kRendererWidth, kRendererHeight);
        };
        DisplayOptions smooth, flat;
        flat.shading = Shading::Flat;

        GlRenderer r;
        r.set_mesh(d.mesh, d.draw_data);
        r.draw(camera, smooth, whole);
        frame(0.2); // the run's first frame: everything
        r.update_geometry(g);
        CHECK(r.geometry_bytes_uploaded() == 2 * 3 * nv * sizeof(float));
        frame(0.4); // the next: the changing vertices' positions and normals only
        size_t bytes = r.geometry_bytes_uploaded();
        r.update_geometry(g);
        CHECK(r.geometry_bytes_uploaded() - bytes ==
              2 * 3 * static_cast<size_t>(part->vertices.count()) * sizeof(float));
        r.draw(camera, smooth, whole);
        const Image smooth_image = r.read_pixels(kRendererWidth, kRendererHeight);
        CHECK(compare_images(smooth_image, reference_image(smooth), 1).pixels_over_tolerance == 0);

        // Flat shading: its area vectors go up whole when turned on, then in part.
        r.draw(camera, flat, whole);
        frame(0.6);
        r.update_geometry(g);
        r.draw(camera, flat, whole);
        const Image flat_image = r.read_pixels(kRendererWidth, kRendererHeight);
        CHECK(compare_images(flat_image, reference_image(flat), 1).pixels_over_tolerance == 0);
        CHECK(compare_images(flat_image, smooth_image, 8).fraction_over_tolerance > 0.01);

        // Positions from elsewhere (an undo): the run's next frame goes up whole again.
        r.update_positions(d.mesh.positions);
        frame(0.8);
        bytes = r.geometry_bytes_uploaded();
        r.update_geometry(g);
        CHECK(r.geometry_bytes_uploaded() - bytes ==
              (2 * 3 * nv + 3 * static_cast<size_t>(d.mesh.face_count())) * sizeof(float));
        r.draw(camera, flat, whole);
        CHECK(
            compare_images(r.read_pixels(kRendererWidth, kRendererHeight), reference_image(flat), 1)
                .pixels_over_tolerance == 0);
    }

    TEST_CASE(
        "the view is rasterized again only when what it shows changed, and a kept "
        "view is the picture a fresh renderer draws")
    {
        test::offscreen_context(kRendererWidth, kRendererHeight);
        Document d = make_document(test::open_grid(6, 3), "bumps.obj");
        // Everything a view shows, changed one part at a time below.
        struct Shown
        {
            std::vector<Scalar> positions;
            std::vector<char> vertices, faces; // selected
            std::vector<float> colors;
            std::vector<GlyphGroup> glyphs;
            DisplayOptions options;
            Camera camera;
            ViewRect rect{kRendererWidth, kRendererHeight, 100, 50, 300, 150};
        } shown;
        shown.positions = d.mesh.positions;
        for (size_t i = 0; i < shown.positions.size(); i += 3)
            shown.positions[i + 2] =
                0.3 * std::sin(2.0 * shown.positions[i]) * std::cos(3.0 * shown.positions[i + 1]);
        shown.vertices.assign(static_cast<size_t>(d.mesh.vertex_count()), 0);
        shown.faces.assign(static_cast<size_t>(d.mesh.face_count()), 0);
        shown.camera.frame(d.box, 2.0);
        const auto give = [&](GlRenderer& r) {
            r.update_positions(shown.positions);
            r.set_selection(shown.vertices, shown.faces);
            r.set_vertex_colors(shown.colors);
            r.set_glyphs(shown.glyphs);
        };
        // A renderer that has drawn nothing: it rasterizes whatever it is given.
        const auto fresh_picture = [&] {
            GlRenderer fresh;
            fresh.set_mesh(d.mesh, d.draw_data);
            give(fresh);
            fresh.draw(shown.camera, shown.options, shown.rect);
            return fresh.read_pixels(kRendererWidth, kRendererHeight);
        };

        GlRenderer r;
        r.set_mesh(d.mesh, d.draw_data);
        give(r);
        r.draw(shown.camera, shown.options, shown.rect);
        CHECK(r.view_renders() == 1);
        const Image first = r.read_pixels(kRendererWidth, kRendererHeight);
        CHECK(compare_images(first, fresh_picture(), 0).pixels_over_tolerance == 0);
        // Nothing changed: copied, the same pixels, also over a framebuffer drawn over since.
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        r.draw(shown.camera, shown.options, shown.rect);
        CHECK(r.view_renders() == 1);
        CHECK(compare_images(r.read_pixels(kRendererWidth, kRendererHeight), first, 0)
                  .pixels_over_tolerance == 0);

        // Each change: drawn again (once), and the picture is a fresh renderer's.
        const auto changed = [&](const char* what, bool redrawn, auto&& change) {
            const std::string name = what;
            CAPTURE(name);
            const int renders = r.view_renders();
            const Image before = r.read_pixels(kRendererWidth, kRendererHeight);
            change();
            r.draw(shown.camera, shown.options, shown.rect);
            CHECK(r.view_renders() == renders + (redrawn ? 1 : 0));
            const Image now = r.read_pixels(kRendererWidth, kRendererHeight);
            CHECK(compare_images(now, fresh_picture(), 0).pixels_over_tolerance == 0);
            CHECK(compare_images(now, before, 8).pixels_over_tolerance > 0);
            r.draw(shown.camera, shown.options, shown.rect); // and then kept
            CHECK(r.view_renders() == renders + (redrawn ? 1 : 0));
        };
        changed("positions", true, [&] {
            for (size_t i = 1; i < shown.positions.size(); i += 3)
                shown.positions[i] -= 0.4;
            r.update_positions(shown.positions);
        });
        changed("selection", true, [&] {
            std::fill(shown.faces.begin(), shown.faces.begin() + 6, 1);
            r.set_selection(shown.vertices, shown.faces);
        });
        changed("colours", true, [&] {
            shown.colors.assign(shown.positions.size(), 0.0f);
            for (size_t k = 0; k < shown.colors.size(); k += 3)
                shown.colors[k] = 1.0f;
            shown.options.vertex_colors = true;
            r.set_vertex_colors(shown.colors);
        });
        changed("glyphs", true, [&] {
            GlyphGroup dots;
            dots.points = {1.0f, 0.5f, 0.5f, 4.0f, 0.5f, 0.5f};
            dots.color = {0, 1, 0};
            dots.size_px = 12;
            shown.glyphs = {dots};
            r.set_glyphs(shown.glyphs);
        });
        changed("display options", true, [&] { shown.options.wireframe = true; });
        changed("camera", true, [&] { shown.camera.distance *= 1.5; });
        changed("view size", true, [&] { shown.rect.width = 250; });
        // Moved in the window at the same size: the kept view is copied to its new place.
        changed("view place", false, [&] { shown.rect.x = 20; });
    }

    TEST_CASE("positions or colours of the wrong size are refused")
    {
        test::offscreen_context(kRendererWidth, kRendererHeight);
        TwoQuads s(Projection::Orthographic);
        GlRenderer r;
        r.set_mesh(s.document.mesh, s.document.draw_data);
        const std::vector<Scalar> short_positions(5, 0.0);
        CHECK_THROWS_AS(r.update_positions(short_positions), RenderError);
        const std::vector<float> colors(7, 0.5f);
        CHECK_THROWS_AS(r.set_vertex_colors(colors), RenderError);
        const std::vector<char> flags(3, 1);
        CHECK_THROWS_AS(r.set_selection(flags, flags), RenderError);
    }
}
