// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/navigation.h"

#include <doctest/doctest.h>

using namespace meshfair::app;

namespace {

Camera framed()
{
    Camera c;
    Box3 b;
    b.add({-1, -1, -1});
    b.add({1, 1, 1});
    c.frame(b, 1.5);
    return c;
}

} // namespace

TEST_SUITE("Navigator")
{
    TEST_CASE("left drag orbits, right drag pans, Ctrl + middle drag zooms")
    {
        Navigator n;
        Camera c = framed();
        const Camera start = c;
        n.press(MouseButton::Left, {}, 100, 100);
        n.move(c, OrbitStyle::Turntable, 160, 100, 900, 600);
        n.release(MouseButton::Left);
        CHECK(glm::length(c.target - start.target) == 0);
        CHECK(c.distance == start.distance);
        CHECK(glm::length(c.forward() - start.forward()) > 0.1);

        c = start;
        n.press(MouseButton::Right, {}, 100, 100);
        n.move(c, OrbitStyle::Turntable, 130, 100, 900, 600);
        n.release(MouseButton::Right);
        CHECK(glm::length(c.forward() - start.forward()) == 0);
        CHECK(glm::length(c.target - start.target) > 0);

        c = start;
        n.press(MouseButton::Middle, {false, true, false}, 100, 300);
        n.move(c, OrbitStyle::Turntable, 100, 250, 900, 600); // up: closer
        n.release(MouseButton::Middle);
        CHECK(c.distance < start.distance);
    }

    TEST_CASE("Shift + middle drag pans, a second button does not change the drag")
    {
        Navigator n;
        Camera c = framed();
        const Camera start = c;
        n.press(MouseButton::Middle, {true, false, false}, 10, 10);
        n.press(MouseButton::Left, {}, 10, 10); // ignored while the middle drag goes on
        n.move(c, OrbitStyle::Trackball, 40, 10, 900, 600);
        CHECK(glm::length(c.forward() - start.forward()) == 0);
        CHECK(glm::length(c.target - start.target) > 0);
        n.release(MouseButton::Left); // not the drag's button
        CHECK(n.dragging());
        n.release(MouseButton::Middle);
        CHECK_FALSE(n.dragging());
        const Camera after = c;
        n.move(c, OrbitStyle::Trackball, 80, 50, 900, 600); // no button: nothing moves
        CHECK(glm::length(c.target - after.target) == 0);
    }

    TEST_CASE("the wheel zooms in by 15 % a notch")
    {
        Navigator n;
        Camera c = framed();
        const double d = c.distance;
        n.scroll(c, 1, 450, 300, 900, 600);
        CHECK(c.distance == doctest::Approx(0.85 * d));
        n.scroll(c, -2, 450, 300, 900, 600);
        CHECK(c.distance == doctest::Approx(d / 0.85));
    }
}
