// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/select/screen_select.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace meshfair;

namespace {

// A 5 x 5 lattice of points 10 px apart from (0, 0), at mid depth.
std::vector<ScreenPoint> lattice()
{
    std::vector<ScreenPoint> p;
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x)
            p.push_back({10.0 * x, 10.0 * y, 0.5});
    return p;
}

} // namespace

TEST_SUITE("ScreenSelect")
{
    TEST_CASE("a rectangle covers the points inside it, edges included, corners in any order")
    {
        const auto p = lattice();
        const std::vector<Index> expected{6, 7, 8, 11, 12, 13};
        CHECK(points_in_rectangle(p, {10, 10, 30, 20}) == expected);
        CHECK(points_in_rectangle(p, {30, 20, 10, 10}) == expected);
        CHECK(points_in_rectangle(p, {41, 41, 60, 60}).empty());
    }

    TEST_CASE("hidden points and points behind the eye are left out")
    {
        auto p = lattice();
        std::vector<char> visible(p.size(), 1);
        visible[7] = 0;
        p[8].depth = 1.5; // beyond the far plane, or behind the eye
        CHECK(points_in_rectangle(p, {10, 10, 30, 20}, visible) ==
              std::vector<Index>{6, 11, 12, 13});
    }

    TEST_CASE("a lasso covers what it encloses, by the even-odd rule")
    {
        const auto p = lattice();
        // A triangle around (10, 10), (20, 10), (10, 20) only.
        const std::vector<ScreenPoint> triangle{{5, 5, 0}, {28, 5, 0}, {5, 28, 0}};
        CHECK(points_in_lasso(p, triangle) == std::vector<Index>{6, 7, 11});
        // A square ring drawn as one self-crossing path: outer square, then the inner one
        // the other way round; the hole stays unselected.
        const std::vector<ScreenPoint> ring{{-5, -5, 0}, {45, -5, 0}, {45, 45, 0}, {-5, 45, 0},
                                            {-5, -5, 0}, {15, 15, 0}, {15, 25, 0}, {25, 25, 0},
                                            {25, 15, 0}, {15, 15, 0}};
        const std::vector<Index> inside = points_in_lasso(p, ring);
        CHECK(inside.size() == 24);
        CHECK(std::find(inside.begin(), inside.end(), 12) == inside.end()); // (20, 20)
        CHECK(points_in_lasso(p, std::vector<ScreenPoint>{{0, 0, 0}, {40, 40, 0}}).empty());
    }

    TEST_CASE("a brush dab covers the points within its radius")
    {
        const auto p = lattice();
        CHECK(points_in_circle(p, {20, 20, 0}, 10) == std::vector<Index>{7, 11, 12, 13, 17});
        CHECK(points_in_circle(p, {20, 20, 0}, 14.2).size() == 9);
        CHECK(points_in_circle(p, {100, 100, 0}, 5).empty());
    }
}
