// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/select/screen_select.h"

#include <algorithm>

namespace meshfair {

namespace {

bool in_view(const ScreenPoint& p)
{
    return p.depth >= 0 && p.depth <= 1;
}

template <class Covers>
std::vector<Index> covered(std::span<const ScreenPoint> points, std::span<const char> visible,
                           Covers covers)
{
    std::vector<Index> out;
    for (size_t k = 0; k < points.size(); ++k)
        if ((visible.empty() || visible[k]) && in_view(points[k]) && covers(points[k]))
            out.push_back(static_cast<Index>(k));
    return out;
}

} // namespace

std::vector<Index> points_in_rectangle(std::span<const ScreenPoint> points, ScreenRect r,
                                       std::span<const char> visible)
{
    const double x0 = std::min(r.x0, r.x1), x1 = std::max(r.x0, r.x1);
    const double y0 = std::min(r.y0, r.y1), y1 = std::max(r.y0, r.y1);
    return covered(points, visible, [&](const ScreenPoint& p) {
        return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
    });
}

std::vector<Index> points_in_lasso(std::span<const ScreenPoint> points,
                                   std::span<const ScreenPoint> lasso,
                                   std::span<const char> visible)
{
    if (lasso.size() < 3)
        return {};
    // The lasso's box first: most points of a large mesh are outside it.
    double x0 = lasso[0].x, x1 = x0, y0 = lasso[0].y, y1 = y0;
    for (const ScreenPoint& q : lasso)
    {
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
    }
    return covered(points, visible, [&](const ScreenPoint& p) {
        if (p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1)
            return false;
        // Even-odd rule: count the edges a ray to +x crosses (half-open in y, so a vertex
        // of the lasso on the ray is counted once).
        bool inside = false;
        for (size_t a = 0, b = lasso.size() - 1; a < lasso.size(); b = a++)
        {
            const ScreenPoint& u = lasso[a];
            const ScreenPoint& v = lasso[b];
            if ((u.y > p.y) != (v.y > p.y) && p.x < (v.x - u.x) * (p.y - u.y) / (v.y - u.y) + u.x)
                inside = !inside;
        }
        return inside;
    });
}

std::vector<Index> points_in_circle(std::span<const ScreenPoint> points, ScreenPoint c,
                                    double radius_px, std::span<const char> visible)
{
    const double r2 = radius_px * radius_px;
    return covered(points, visible, [&](const ScreenPoint& p) {
        const double dx = p.x - c.x, dy = p.y - c.y;
        return dx * dx + dy * dy <= r2;
    });
}

} // namespace meshfair
