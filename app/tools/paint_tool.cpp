// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/paint_tool.h"

#include <algorithm>
#include <cmath>

namespace meshfair::app {

bool PaintTool::press(const ToolContext& context, Modifiers, ScreenPoint at,
                      std::vector<Command>& out)
{
    view_ = context.view;
    paint_ = context.settings.paint;
    if (paint_.set.empty())
        paint_.set = std::string(kPaintSet);
    radius_px_ = std::max(context.settings.brush_radius_px, 1.0);
    if (view_.mesh == nullptr || view_.camera == nullptr)
        return false;
    // The visible vertices in the view and where they project, kept for the stroke.
    ToolSettings vertices = context.settings;
    vertices.elements = ElementKind::Vertices;
    vertices.through = false;
    const ScreenElements elements = screen_elements(view_, vertices);
    visible_.clear();
    projected_.clear();
    places_.clear();
    for (size_t k = 0; k < elements.points.size(); ++k)
    {
        const ScreenPoint& p = elements.points[k];
        if ((elements.visible.empty() || elements.visible[k]) && p.depth >= 0 && p.depth <= 1 &&
            p.x >= 0 && p.y >= 0 && p.x < view_.view.width && p.y < view_.view.height)
        {
            visible_.push_back(static_cast<Index>(k));
            projected_.push_back(p);
            const std::vector<Scalar>& x = view_.mesh->positions;
            places_.push_back({x[3 * k], x[3 * k + 1], x[3 * k + 2]});
        }
    }
    const Index v = nearest(at);
    if (v == kInvalidIndex)
        return false;
    // The screen radius at that vertex's depth, in the world.
    const ScreenPoint& p = projected_[static_cast<size_t>(v)];
    const Camera& camera = *view_.camera;
    const int w = view_.view.width, h = view_.view.height;
    radius_ = glm::length(camera.unproject({p.x + radius_px_, p.y, p.depth}, w, h) -
                          camera.unproject({p.x, p.y, p.depth}, w, h));
    if (!(radius_ > 0) || !std::isfinite(radius_))
        return false;
    dab(at, out);
    last_ = at;
    return true;
}

Index PaintTool::nearest(ScreenPoint at) const
{
    Index best = kInvalidIndex;
    double best_d2 = radius_px_ * radius_px_;
    for (size_t k = 0; k < projected_.size(); ++k)
    {
        const double dx = projected_[k].x - at.x, dy = projected_[k].y - at.y;
        const double d2 = dx * dx + dy * dy;
        if (d2 <= best_d2)
        {
            best_d2 = d2;
            best = static_cast<Index>(k);
        }
    }
    return best;
}

void PaintTool::dab(ScreenPoint at, std::vector<Command>& out)
{
    const Index k = nearest(at);
    if (k == kInvalidIndex)
        return;
    // Where the vertex was when the stroke began, in the world: the shape the dabs measure
    // their reach on. (The smoothing brush's runs move it while the stroke goes on, as they
    // come in from the solver's thread: the same mouse path gives the same dabs whichever
    // have come.)
    out.push_back(cmd::PaintDab{paint_.set, paint_.mode, places_[static_cast<size_t>(k)], radius_,
                                paint_.strength, paint_.curve, paint_.steps});
}

void PaintTool::move(ScreenPoint to, std::vector<Command>& out)
{
    const double spacing = std::max(1.0, radius_px_ / 4);
    double dx = to.x - last_.x, dy = to.y - last_.y;
    double length = std::sqrt(dx * dx + dy * dy);
    while (length >= spacing)
    {
        last_ = {last_.x + dx / length * spacing, last_.y + dy / length * spacing, 0};
        dab(last_, out);
        dx = to.x - last_.x;
        dy = to.y - last_.y;
        length = std::sqrt(dx * dx + dy * dy);
    }
}

void PaintTool::release(ScreenPoint at, std::vector<Command>& out)
{
    move(at, out);
}

ToolOverlay PaintTool::overlay(ScreenPoint cursor, const ToolSettings& settings, bool) const
{
    return {ToolOverlay::Shape::Circle, {cursor}, settings.brush_radius_px};
}

} // namespace meshfair::app
