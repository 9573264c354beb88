// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/render/camera.h"

#include <doctest/doctest.h>

#include <cmath>

#include "core/errors.h"

using namespace meshfair;
using namespace meshfair::app;

namespace {

Box3 unit_box()
{
    Box3 b;
    b.add({-1, -0.5, -2});
    b.add({3, 1.5, 0});
    return b;
}

double distance(const glm::dvec3& a, const glm::dvec3& b)
{
    return glm::length(a - b);
}

} // namespace

TEST_SUITE("Camera")
{
    TEST_CASE("project then unproject returns the point, in both projections")
    {
        for (const Projection p : {Projection::Perspective, Projection::Orthographic})
        {
            Camera c;
            c.projection = p;
            c.frame(unit_box(), 1.6);
            c.orbit(OrbitStyle::Turntable, 100, 100, 160, 130, 800, 500);
            for (const glm::dvec3 q : {glm::dvec3(0.3, 0.2, -1.1), glm::dvec3(2.9, 1.4, -0.1),
                                       glm::dvec3(-0.9, -0.4, -1.9)})
            {
                const glm::dvec3 w = c.project(q, 800, 500);
                CHECK(distance(c.unproject(w, 800, 500), q) < 1e-9);
                CHECK(w.z > 0);
                CHECK(w.z < 1);
            }
        }
    }

    TEST_CASE("frame puts every corner of the box inside the window, for any aspect")
    {
        const Box3 box = unit_box();
        for (const Projection p : {Projection::Perspective, Projection::Orthographic})
            for (const StandardView v : {StandardView::Front, StandardView::Right,
                                         StandardView::Top, StandardView::Bottom})
                for (const auto& [w, h] : {std::pair{1280, 800}, std::pair{400, 900}})
                {
                    Camera c;
                    c.projection = p;
                    c.set_view(v);
                    c.frame(box, double(w) / h);
                    for (int k = 0; k < 8; ++k)
                    {
                        const glm::dvec3 corner{k & 1 ? box.hi.x : box.lo.x,
                                                k & 2 ? box.hi.y : box.lo.y,
                                                k & 4 ? box.hi.z : box.lo.z};
                        const glm::dvec3 s = c.project(corner, w, h);
                        CHECK(s.x > 0);
                        CHECK(s.x < w);
                        CHECK(s.y > 0);
                        CHECK(s.y < h);
                        CHECK(s.z > 0); // between the near and far planes
                        CHECK(s.z < 1);
                    }
                }
    }

    TEST_CASE("framing a part shows the part and keeps the whole scene between near and far")
    {
        Box3 scene = unit_box();
        Box3 part;
        part.add({2.5, 1.0, -0.2});
        part.add({2.9, 1.4, -0.1});
        Camera c;
        c.frame(part, scene, 1.5);
        CHECK(c.scene_radius == doctest::Approx(scene.radius()));
        CHECK(glm::length(c.target - part.center()) < 1e-12);
        for (int k = 0; k < 8; ++k)
        {
            const glm::dvec3 corner{k & 1 ? part.hi.x : part.lo.x, k & 2 ? part.hi.y : part.lo.y,
                                    k & 4 ? part.hi.z : part.lo.z};
            const glm::dvec3 s = c.project(corner, 900, 600);
            CHECK(s.x > 0);
            CHECK(s.x < 900);
            CHECK(s.y > 0);
            CHECK(s.y < 600);
        }
        // The far end of the scene, seen through the part, is not cut off by the far plane.
        CHECK(c.far_plane() >=
              glm::dot(scene.center() - c.eye(), c.forward()) + scene.radius() - 1e-9);
    }

    TEST_CASE("project_points gives what project gives, for every point")
    {
        Camera c;
        c.frame(unit_box(), 1.6);
        c.orbit(OrbitStyle::Trackball, 10, 10, 90, 40, 800, 500);
        const std::vector<float> p{0.3f, 0.2f, -1.1f, 2.9f, 1.4f, -0.1f, -0.9f, -0.4f, -1.9f};
        const std::vector<ScreenPoint> s = project_points(c, p, 800, 500);
        REQUIRE(s.size() == 3);
        for (size_t i = 0; i < 3; ++i)
        {
            const glm::dvec3 w = c.project({p[3 * i], p[3 * i + 1], p[3 * i + 2]}, 800, 500);
            CHECK(s[i].x == doctest::Approx(w.x).epsilon(1e-12));
            CHECK(s[i].y == doctest::Approx(w.y).epsilon(1e-12));
            CHECK(s[i].depth == doctest::Approx(w.z).epsilon(1e-12));
        }
        // Behind the eye: a depth outside [0, 1], which no tool selects.
        const glm::dvec3 behind = c.eye() - c.forward();
        const std::vector<float> q{float(behind.x), float(behind.y), float(behind.z)};
        CHECK(project_points(c, q, 800, 500)[0].depth < 0);
    }

    TEST_CASE("the standard views look along the axes, with +y up except from above")
    {
        Camera c;
        c.set_view(StandardView::Front);
        CHECK(distance(c.forward(), {0, 0, -1}) < 1e-12);
        c.set_view(StandardView::Right);
        CHECK(distance(c.forward(), {-1, 0, 0}) < 1e-12);
        CHECK(distance(c.up(), {0, 1, 0}) < 1e-12);
        c.set_view(StandardView::Top);
        CHECK(distance(c.forward(), {0, -1, 0}) < 1e-12);
        c.set_view(StandardView::Back);
        CHECK(distance(c.forward(), {0, 0, 1}) < 1e-12);
        c.set_view(StandardView::Bottom);
        CHECK(distance(c.forward(), {0, 1, 0}) < 1e-12);
    }

    TEST_CASE("a turntable orbit keeps the world's up axis upright on screen")
    {
        Camera c;
        c.frame(unit_box(), 1.5);
        c.orbit(OrbitStyle::Turntable, 0, 0, 300, 0, 900, 600); // a horizontal drag: yaw only
        CHECK(std::abs(glm::dot(c.right(), glm::dvec3(0, 1, 0))) < 1e-12);
        CHECK(glm::dot(c.up(), glm::dvec3(0, 1, 0)) == doctest::Approx(1.0));
        // Half a window height of horizontal drag turns 90 degrees.
        CHECK(distance(c.forward(), {1, 0, 0}) < 1e-9);
    }

    TEST_CASE("a trackball drag across the centre turns the scene with the mouse")
    {
        Camera c;
        c.frame(unit_box(), 1.0);
        const glm::dvec3 point = c.target + glm::dvec3(0, 0, 1); // in front of the target
        const double before = c.project(point, 600, 600).x;
        c.orbit(OrbitStyle::Trackball, 300, 300, 340, 300, 600, 600);
        CHECK(c.project(point, 600, 600).x > before); // moved right, like the mouse
        CHECK(glm::length(c.rotation) == doctest::Approx(1.0));
    }

    TEST_CASE("zoom keeps the point under the cursor where it is on screen")
    {
        for (const Projection p : {Projection::Perspective, Projection::Orthographic})
        {
            Camera c;
            c.projection = p;
            c.frame(unit_box(), 1.6);
            const glm::dvec3 window{620, 140, 0};
            // The point under the cursor at the target's depth.
            const double depth = c.project(c.target, 800, 500).z;
            const glm::dvec3 under = c.unproject({window.x, window.y, depth}, 800, 500);
            const double before = c.distance;
            c.zoom(0.5, window.x, window.y, 800, 500);
            CHECK(c.distance == doctest::Approx(0.5 * before));
            const glm::dvec3 after = c.project(under, 800, 500);
            CHECK(after.x == doctest::Approx(window.x).epsilon(1e-9));
            CHECK(after.y == doctest::Approx(window.y).epsilon(1e-9));
        }
    }

    TEST_CASE("a pan moves the scene with the mouse by as many pixels")
    {
        Camera c;
        c.frame(unit_box(), 1.6);
        const glm::dvec3 before = c.project(c.target, 800, 500);
        const glm::dvec3 target = c.target;
        c.pan(25, -10, 800, 500);
        const glm::dvec3 after = c.project(target, 800, 500);
        CHECK(after.x - before.x == doctest::Approx(25).epsilon(1e-9));
        CHECK(after.y - before.y == doctest::Approx(-10).epsilon(1e-9));
    }

    TEST_CASE("a view saved as JSON loads back the same camera")
    {
        Camera c;
        c.projection = Projection::Orthographic;
        c.frame(unit_box(), 1.3);
        c.orbit(OrbitStyle::Trackball, 10, 20, 200, 90, 640, 480);
        const Camera d = camera_from_json(to_json(c), "v.json");
        CHECK(distance(d.target, c.target) == 0);
        CHECK(d.distance == c.distance);
        CHECK(d.projection == c.projection);
        CHECK(std::abs(glm::dot(d.rotation, c.rotation)) == doctest::Approx(1.0).epsilon(1e-15));
        CHECK(distance(d.project({1, 1, -1}, 640, 480), c.project({1, 1, -1}, 640, 480)) < 1e-9);
    }

    TEST_CASE("a bad view file is refused with the file and the field named")
    {
        const auto error = [](const std::string& text) {
            try
            {
                camera_from_json(text, "v.json");
            }
            catch (const InvalidInputError& e)
            {
                return std::string(e.what());
            }
            return std::string("accepted");
        };
        CHECK(error("{\"distance\": -1}") == "'v.json': view field 'distance' must be positive");
        CHECK(error("{\"target\": [1, 2]}") ==
              "'v.json': view field 'target' must be an array of 3 numbers");
        CHECK(error("{\"rotation\": [0, 0, 0, 0]}") ==
              "'v.json': view field 'rotation' must be a non-zero quaternion (w x y z)");
        CHECK(error("{\"projection\": \"fisheye\"}") ==
              "'v.json': view field 'projection' must be \"perspective\" or \"orthographic\"");
        CHECK(error("{\"zoom\": 2}") == "'v.json': view field 'zoom' is unknown");
        CHECK(error("[1]") == "'v.json': a view must be a JSON object");
        CHECK(error("{\"distance\": 1,").find("'v.json': not JSON:") == 0);
        CHECK(error("{\"distance\": 1,").find("line 1") != std::string::npos);
    }
}

TEST_SUITE("Camera up axis")
{
    TEST_CASE("with +z up the front view looks along +y with +z up, and the turntable keeps z up")
    {
        Camera c;
        c.up_axis = UpAxis::Z;
        c.set_view(StandardView::Front);
        CHECK(glm::length(c.forward() - glm::dvec3(0, 1, 0)) < 1e-12);
        CHECK(glm::length(c.up() - glm::dvec3(0, 0, 1)) < 1e-12);
        c.set_view(StandardView::Top);
        CHECK(glm::length(c.forward() - glm::dvec3(0, 0, -1)) < 1e-12);
        c.set_view(StandardView::Front);
        c.orbit(OrbitStyle::Turntable, 0, 0, 37, 0, 400, 300); // a yaw only
        CHECK(std::abs(glm::dot(c.right(), glm::dvec3(0, 0, 1))) < 1e-12);
        CHECK(glm::length(c.up() - glm::dvec3(0, 0, 1)) < 1e-12);
        // With +y up, the same yaw turns about y.
        Camera y;
        y.set_view(StandardView::Front);
        y.orbit(OrbitStyle::Turntable, 0, 0, 37, 0, 400, 300);
        CHECK(std::abs(glm::dot(y.right(), glm::dvec3(0, 1, 0))) < 1e-12);
        CHECK(glm::length(y.up() - glm::dvec3(0, 1, 0)) < 1e-12);
    }

    TEST_CASE("a view file keeps its up axis, without scene centre and radius it takes the mesh's")
    {
        Camera c;
        c.up_axis = UpAxis::Z;
        CHECK(camera_from_json(to_json(c), "v.json").up_axis == UpAxis::Z);
        Box3 box;
        box.lo = {10, 20, 30};
        box.hi = {14, 26, 42};
        const Camera d =
            camera_from_json(R"({"target": [12, 23, 36], "distance": 30})", "v.json", &box);
        CHECK(glm::length(d.scene_center - glm::dvec3(12, 23, 36)) < 1e-12);
        CHECK(d.scene_radius == doctest::Approx(box.radius()));
        // Given, they are kept.
        const Camera e =
            camera_from_json(R"({"scene_center": [1, 2, 3], "scene_radius": 5})", "v.json", &box);
        CHECK(e.scene_radius == 5);
        CHECK_THROWS_WITH(camera_from_json(R"({"up": "w"})", "v.json"),
                          "'v.json': view field 'up' must be \"+x\", \"-x\", \"+y\", \"-y\", "
                          "\"+z\" or \"-z\"");
    }

    TEST_CASE(
        "every axis either way can be up: the turntable turns about it, the front view "
        "stands on it, a view file keeps it")
    {
        for (const UpAxis up : kUpAxes)
        {
            const std::string name(up_axis_name(up));
            CAPTURE(name);
            CHECK(up_axis_named(name) == up);
            Camera c;
            c.up_axis = up;
            const int axis = static_cast<int>(up) / 2;
            const double sign = static_cast<int>(up) % 2 == 0 ? 1 : -1;
            glm::dvec3 expected(0.0);
            expected[axis] = sign;
            CHECK(glm::length(c.world_up() - expected) < 1e-12);
            // The front view: the screen's up is the world's, the view across it.
            c.set_view(StandardView::Front);
            const glm::dmat3 to_world = glm::mat3_cast(c.rotation);
            CHECK(glm::length(to_world * glm::dvec3(0, 1, 0) - expected) < 1e-12);
            CHECK(std::abs(glm::dot(c.forward(), expected)) < 1e-12);
            // The top view looks down it.
            c.set_view(StandardView::Top);
            CHECK(glm::length(c.forward() + expected) < 1e-12);
            // A turntable orbit keeps the world's up in the view's vertical plane.
            c.set_view(StandardView::Front);
            c.orbit(OrbitStyle::Turntable, 0, 0, 37, 0, 800, 600);
            CHECK(std::abs(glm::dot(glm::mat3_cast(c.rotation) * glm::dvec3(1, 0, 0), expected)) <
                  1e-12);
            CHECK(camera_from_json(to_json(c), "v.json").up_axis == up);
        }
        CHECK(up_axis_named("z") == UpAxis::Z); // (the words of older files)
        CHECK(up_axis_named("y") == UpAxis::Y);
        CHECK_FALSE(up_axis_named("-").has_value());
        CHECK_FALSE(up_axis_named("").has_value());
        CHECK_FALSE(up_axis_named("+w").has_value());
    }

    TEST_CASE("a view file without a target or a distance frames the mesh")
    {
        Box3 box;
        box.lo = {10, 20, 30};
        box.hi = {14, 26, 42};
        // `{"up": "z"}` alone: looking at the mesh's centre from outside it, as Home frames it.
        const Camera up = camera_from_json(R"({"up": "z"})", "v.json", &box);
        Camera framed;
        framed.up_axis = UpAxis::Z;
        framed.frame(box, 1.0);
        CHECK(up.up_axis == UpAxis::Z);
        CHECK(glm::length(up.target - box.center()) < 1e-12);
        CHECK(up.distance == doctest::Approx(framed.distance));
        CHECK(up.distance > box.radius()); // the eye outside the mesh's sphere
        // What the file gives is kept: its target, with the framing distance, and the other way.
        const Camera t = camera_from_json(R"({"target": [0, 0, 0]})", "v.json", &box);
        CHECK(glm::length(t.target) == 0);
        CHECK(t.distance == doctest::Approx(framed.distance));
        const Camera d = camera_from_json(R"({"distance": 3})", "v.json", &box);
        CHECK(d.distance == 3);
        CHECK(glm::length(d.target - box.center()) < 1e-12);
        // A narrower field of view frames from further away.
        const Camera narrow = camera_from_json(R"({"fov_y_degrees": 20})", "v.json", &box);
        CHECK(narrow.distance > up.distance);
    }
}
