// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/energies/falloff.h"

//! \file
//! \brief What the tools are and the settings they share: the words the commands speak of
//! tools (app/edit/command.h), below the tools themselves (app/tools), which produce them.

namespace meshfair::app {

//! What the selection tools select: vertices, or faces (a face counts where its
//! centroid projects).
enum class ElementKind
{
    Vertices,
    Faces
};

//! "vertices" or "faces".
std::optional<ElementKind> element_kind_named(std::string_view name);

//! The tool the left mouse button uses.
enum class ToolKind
{
    Navigate,   //!< left drag orbits
    Click,      //!< ClickTool
    Brush,      //!< BrushTool
    Rectangle,  //!< RectangleTool
    Lasso,      //!< LassoTool
    MovePins,   //!< drag a pin set's glyphs to new targets in the view plane (the session's)
    AimNormals, //!< drag a normal set's arrows to turn its direction (the session's)
    Paint       //!< PaintTool: the smoothing brush, and painting a set's weight map
};

//! "navigate", "click", "brush", "rectangle", "lasso", "move_pins", "aim_normals", "paint".
std::string_view tool_name(ToolKind tool);
std::optional<ToolKind> tool_named(std::string_view name);

//! What a dab of the Paint tool does to the vertices under it (cmd::PaintDab).
enum class PaintMode
{
    Relax,    //!< the smoothing brush: frees them in a region's map and runs the solver
    Add,      //!< raises the set's weight map toward 1
    Subtract, //!< lowers it toward 0
    Smooth    //!< blends each weight with its neighbours' mean
};
//! "relax", "add", "subtract", "smooth".
std::string_view paint_mode_name(PaintMode mode);
std::optional<PaintMode> paint_mode_named(std::string_view name);

//! The Paint tool's settings (the side panel's "Paint" section).
struct PaintSettings
{
    PaintMode mode = PaintMode::Relax;
    //! How much a dab changes a weight at its centre, in [0, 1].
    double strength = 0.5;
    FalloffCurve curve = FalloffCurve::Smooth;
    //! Relax: the solver steps a stroke runs from the shape it started on.
    int steps = 10;
    //! The set whose map is painted; empty: kPaintSet.
    std::string set;
    bool operator==(const PaintSettings&) const = default;
};
//! The set the Paint tool paints when none is chosen: a region made at the first dab.
inline constexpr std::string_view kPaintSet = "brush";

//! The settings the tools share (the side panel's "Select" and "Paint" sections).
struct ToolSettings
{
    ElementKind elements = ElementKind::Vertices;
    //! Select through the surface: hidden elements too (default: what is seen only).
    bool through = false;
    double brush_radius_px = 24;
    PaintSettings paint;
};

} // namespace meshfair::app
