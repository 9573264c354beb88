// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-editor-bench's drag case: a pin dragged with the M tool in a large region, each
// mouse move timed until the shape the editor shows is the minimizer (docs/performance.md,
// "Editor").
#pragma once

#include "app/editor/editor_session.h"

namespace meshfair::bench {

//! How the drag is set up and judged.
struct DragOptions
{
    int moves = 20;              //!< mouse moves timed after the first (0: no drag case)
    double step_px = 8;          //!< how far each move lifts the pins, in pixels of the view
    double region = 0.5;         //!< the region's rectangle, as a fraction of the view's sides
    double pins_px = 4;          //!< the pins' rectangle's side, in pixels
    double tolerance = 1e-4;     //!< a shape within this many bounding-box diagonals counts
    double budget_ms = 100;      //!< the latency asked for
    int jacobi_moves = 5;        //!< moves of the Jacobi peer (0: none)
    double jacobi_cap_ms = 3000; //!< how long the peer may take for one move
    //! The drag by conjugate gradients (no factor: a frame's iterations at a time) in place
    //! of the direct method, as for a system too large to factor
    bool conjugate_gradients = false;
};

//! \brief Sets up a region ("patch") and pins inside it as an artist does (rectangles
//! through the surface and on it, in the front view), drags the pins up with the M tool
//! (its first move takes the dome settings: the direct method with the thin plate) and
//! prints, per mouse move, the time until the editor shows the minimizer within
//! `tolerance` of the diagonal, checked against a run of its own; then the Jacobi peer and
//! the peak memory. Leaves the sets, settings and shape in the document.
//! \pre the session's view is `width` x `height` pixels and its renderer can pick.
void drag_case(app::EditorSession& session, int width, int height, const DragOptions& options);

} // namespace meshfair::bench
