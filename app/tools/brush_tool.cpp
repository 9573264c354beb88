// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/brush_tool.h"

#include <algorithm>
#include <cmath>

namespace meshfair::app {

std::vector<Index> BrushTool::press(const ToolView& view, const ToolSettings& settings,
                                    ScreenPoint at)
{
    radius_ = std::max(settings.brush_radius_px, 1.0);
    elements_ = screen_elements(view, settings);
    const size_t n = elements_.points.size();
    covered_.assign(n, 0);

    // Bucket the elements that lie in the view (and are visible) by cell: a counting sort.
    cell_ = std::max(radius_, 4.0);
    columns_ = std::max(1, static_cast<int>(std::ceil(view.view.width / cell_)));
    rows_ = std::max(1, static_cast<int>(std::ceil(view.view.height / cell_)));
    std::vector<Index> cell_of(n, kInvalidIndex);
    cell_offsets_.assign(static_cast<size_t>(columns_) * rows_ + 1, 0);
    for (size_t k = 0; k < n; ++k)
    {
        const ScreenPoint& p = elements_.points[k];
        if ((!elements_.visible.empty() && !elements_.visible[k]) || !(p.depth >= 0) ||
            !(p.depth <= 1) || !(p.x >= 0) || !(p.y >= 0) || p.x >= view.view.width ||
            p.y >= view.view.height)
            continue;
        const int cx = std::min(static_cast<int>(p.x / cell_), columns_ - 1);
        const int cy = std::min(static_cast<int>(p.y / cell_), rows_ - 1);
        cell_of[k] = static_cast<Index>(cy * columns_ + cx);
        ++cell_offsets_[static_cast<size_t>(cell_of[k]) + 1];
    }
    for (size_t c = 1; c < cell_offsets_.size(); ++c)
        cell_offsets_[c] += cell_offsets_[c - 1];
    cell_points_.resize(static_cast<size_t>(cell_offsets_.back()));
    std::vector<Index> fill(cell_offsets_.begin(), cell_offsets_.end() - 1);
    for (size_t k = 0; k < n; ++k)
        if (cell_of[k] != kInvalidIndex)
            cell_points_[static_cast<size_t>(fill[static_cast<size_t>(cell_of[k])]++)] =
                static_cast<Index>(k);

    active_ = true;
    last_ = at;
    std::vector<Index> out;
    dab(at, out);
    std::sort(out.begin(), out.end());
    return out;
}

void BrushTool::dab(ScreenPoint c, std::vector<Index>& out)
{
    const double r2 = radius_ * radius_;
    const int x0 = std::max(0, static_cast<int>(std::floor((c.x - radius_) / cell_)));
    const int x1 = std::min(columns_ - 1, static_cast<int>(std::floor((c.x + radius_) / cell_)));
    const int y0 = std::max(0, static_cast<int>(std::floor((c.y - radius_) / cell_)));
    const int y1 = std::min(rows_ - 1, static_cast<int>(std::floor((c.y + radius_) / cell_)));
    for (int cy = y0; cy <= y1; ++cy)
        for (int cx = x0; cx <= x1; ++cx)
        {
            const size_t cell = static_cast<size_t>(cy) * columns_ + cx;
            for (Index j = cell_offsets_[cell]; j < cell_offsets_[cell + 1]; ++j)
            {
                const size_t k = static_cast<size_t>(cell_points_[static_cast<size_t>(j)]);
                const ScreenPoint& p = elements_.points[k];
                const double dx = p.x - c.x, dy = p.y - c.y;
                if (!covered_[k] && dx * dx + dy * dy <= r2)
                {
                    covered_[k] = 1;
                    out.push_back(static_cast<Index>(k));
                }
            }
        }
}

std::vector<Index> BrushTool::drag(ScreenPoint to)
{
    std::vector<Index> out;
    if (!active_)
        return out;
    const double length = std::hypot(to.x - last_.x, to.y - last_.y);
    const int steps = std::max(1, static_cast<int>(std::ceil(length / (0.25 * radius_))));
    for (int s = 1; s <= steps; ++s)
    {
        const double t = double(s) / steps;
        dab({last_.x + t * (to.x - last_.x), last_.y + t * (to.y - last_.y), 0}, out);
    }
    last_ = to;
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<Index> BrushTool::release(ScreenPoint at)
{
    std::vector<Index> out = drag(at);
    active_ = false;
    elements_ = {};
    covered_ = {};
    cell_offsets_ = {};
    cell_points_ = {};
    return out;
}

ToolOverlay BrushTool::overlay(ScreenPoint cursor) const
{
    return {ToolOverlay::Shape::Circle, {active_ ? last_ : cursor}, radius_};
}

} // namespace meshfair::app
