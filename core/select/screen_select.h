// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/types.h"

namespace meshfair {

//! A point in window pixels, (0, 0) the top-left corner, y down; depth in [0, 1] as the
//! renderer's depth buffer holds it (0 near, 1 far).
struct ScreenPoint
{
    double x = 0, y = 0, depth = 0;
};

//! An axis-aligned rectangle of the window; the corners may come in any order.
struct ScreenRect
{
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

//! \brief Which points a selection tool covers, given where they project (pure maths: the
//! editor projects the vertices and, for front-facing-only tools, passes a visibility
//! mask from its ID buffer). Each returns the indices of the points covered, increasing.
//! `visible`, when not empty, has one flag per point and leaves out the points whose flag
//! is 0. Points behind the eye (depth outside [0, 1]) are never covered.
std::vector<Index> points_in_rectangle(std::span<const ScreenPoint> points, ScreenRect rect,
                                       std::span<const char> visible = {});

//! \brief The points inside a lasso, a closed polygon of window points (the last joined to
//! the first), by the even-odd rule, so a lasso that crosses itself leaves its inner loops
//! out as a drawn figure does. A lasso of fewer than 3 points covers nothing.
std::vector<Index> points_in_lasso(std::span<const ScreenPoint> points,
                                   std::span<const ScreenPoint> lasso,
                                   std::span<const char> visible = {});

//! The points within `radius_px` of `center` (a brush dab; a stroke is several dabs).
std::vector<Index> points_in_circle(std::span<const ScreenPoint> points, ScreenPoint center,
                                    double radius_px, std::span<const char> visible = {});

} // namespace meshfair
