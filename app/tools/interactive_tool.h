// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/edit/command.h"
#include "app/tools/navigation.h"
#include "app/tools/selection_tool.h"

namespace meshfair::app {

//! \brief Something a tool can grab in the view: a pin of a pin set (at its target), or one
//! of a normal set's arrows as drawn (from a face centroid to its tip), with the set's
//! direction.
struct GrabHandle
{
    std::string set;         //!< the set's name
    glm::dvec3 point{0};     //!< in the world
    Vec3 direction{0, 0, 1}; //!< normal sets: the set's direction now (its mean normal)
    //! An arrow's tip (the handle is the segment from point to it); none: a point.
    std::optional<glm::dvec3> tip;
};

//! What a tool reads of the editor when its gesture starts. The camera does not move
//! during a gesture.
struct ToolContext
{
    ToolView view;
    ToolSettings settings;
    //! The grab handles of the visible pin sets and normal sets (asked for only by the
    //! tools that grab them).
    std::function<std::vector<GrabHandle>()> pin_handles, normal_handles;
    //! The solver settings a pin drag takes first, when the current ones raise no dome
    //! (dome_settings): the M tool's drag shows the minimizer with the thin plate.
    std::optional<SolverSettings> dome;
};

//! \brief A tool of the left mouse button: a gesture (a press, moves, a release) that
//! produces editor commands, and what it draws over the view. Points are in the view's
//! pixels, (0, 0) its top-left corner.
class InteractiveTool
{
public:
    virtual ~InteractiveTool() = default;
    //! \brief Starts a gesture; false when there is nothing to act on at `at` (the press
    //! then navigates, as with the Navigate tool).
    virtual bool press(const ToolContext& context, Modifiers mods, ScreenPoint at,
                       std::vector<Command>& out) = 0;
    virtual void move(ScreenPoint to, std::vector<Command>& out) = 0;
    virtual void release(ScreenPoint at, std::vector<Command>& out) = 0;
    //! What to draw with the cursor at `cursor`, in a gesture (`active`) or not.
    virtual ToolOverlay overlay(ScreenPoint cursor, const ToolSettings& settings,
                                bool active) const = 0;
    //! The name of the undo step a gesture makes.
    virtual const char* gesture_name() const = 0;
};

//! How far from a handle (in pixels) a press still grabs it.
inline constexpr double kGrabRadiusPx = 12;

//! \brief The handle nearest to `at` on screen within kGrabRadiusPx (an arrow anywhere
//! along it, from base to tip), and its window depth there.
struct Grabbed
{
    const GrabHandle* handle = nullptr;
    double depth = 0;
};
Grabbed nearest_handle(std::span<const GrabHandle> handles, const Camera& camera,
                       const ViewRect& view, ScreenPoint at);

} // namespace meshfair::app
