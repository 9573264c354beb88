// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "app/edit/tool_settings.h"
#include "app/render/camera.h"
#include "app/render/renderer.h"
#include "core/energies/falloff.h"
#include "core/mesh/mesh.h"
#include "core/select/screen_select.h"

namespace meshfair::app {

//! The view a gesture starts in. The camera does not move during a gesture.
struct ToolView
{
    const Mesh* mesh = nullptr;
    Renderer* renderer = nullptr;
    const Camera* camera = nullptr;
    ViewRect view;
    //! \brief What the view shows, when the caller keeps it between gestures (the ID
    //! buffer is the costly part of a press, and strokes from one view can share it);
    //! empty: the tool asks the renderer.
    std::function<const Visibility&()> visibility;
    //! The face centroids projected into the view, kept likewise; empty: projected here.
    std::function<std::span<const ScreenPoint>()> face_points;
};

//! The face centroids (the mean of each face's corners) projected into a view.
std::vector<ScreenPoint> project_face_centroids(const Mesh& mesh, const Camera& camera, int width,
                                                int height);

//! \brief The elements of one kind as a view shows them: where each projects (window
//! pixels of the view) and, unless the tool selects through the surface, which ones the
//! ID buffer shows (a face: it covers a pixel; a vertex: not behind the surface drawn
//! around it, see Renderer::visibility). `visible` is empty when every element counts.
//! The spans view either the arrays held here or a visibility the caller keeps for the
//! gesture (ToolView::visibility), which is then not copied.
struct ScreenElements
{
    // Moved, never copied: the spans may point into the vectors (a move keeps their arrays).
    ScreenElements() = default;
    ScreenElements(ScreenElements&&) = default;
    ScreenElements& operator=(ScreenElements&&) = default;
    ScreenElements(const ScreenElements&) = delete;
    ScreenElements& operator=(const ScreenElements&) = delete;

    std::span<const ScreenPoint> points;
    std::span<const char> visible;
    std::vector<ScreenPoint> own_points;
    std::vector<char> own_visible;
};

//! \brief Projects the vertices or the face centroids of `view`'s mesh and, when
//! `settings.through` is false, renders the ID buffer once to tell which are visible.
//! Linear in the mesh, on the threads; the one ID-buffer pass of a gesture.
ScreenElements screen_elements(const ToolView& view, const ToolSettings& settings);

//! What a tool draws over the view while it is in use, in the view's pixels.
struct ToolOverlay
{
    enum class Shape
    {
        None,
        Circle,    //!< points[0] the centre, radius
        Rectangle, //!< points[0] and points[1] opposite corners
        Polyline   //!< an open line through points (the lasso being drawn)
    };
    Shape shape = Shape::None;
    std::vector<ScreenPoint> points;
    double radius = 0;
};

//! \brief A selection gesture: a press, drags, a release, each returning the elements it
//! covers (indices into the mesh's vertices or faces). The editor applies them to the
//! selection with the modifiers' operation (Shift adds, Ctrl subtracts), as they come:
//! a brush selects while it paints, a rectangle when it is released.
//! Points are in the view's pixels, (0, 0) its top-left corner.
class SelectionTool
{
public:
    virtual ~SelectionTool() = default;
    //! \pre view.mesh, view.renderer and view.camera are set and outlive the gesture.
    virtual std::vector<Index> press(const ToolView& view, const ToolSettings& settings,
                                     ScreenPoint at) = 0;
    virtual std::vector<Index> drag(ScreenPoint to) = 0;
    virtual std::vector<Index> release(ScreenPoint at) = 0;
    //! What to draw with the cursor at `cursor` (pressed or not).
    virtual ToolOverlay overlay(ScreenPoint cursor) const = 0;
};

} // namespace meshfair::app
