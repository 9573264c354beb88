// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// meshfair-editor-bench's paint case: strokes of the smoothing brush over a noisy scan,
// each dab timed on the interface's thread, and the time from a stroke's end to its final
// shape (docs/performance.md, "Editor").
#pragma once

#include "core/mesh/mesh.h"

namespace meshfair::bench {

//! How the strokes are made.
struct PaintOptions
{
    int dabs = 30;         //!< dabs a stroke (one per mouse move)
    int strokes = 3;       //!< strokes per recipe, each undone after it
    double radius_px = 40; //!< the brush's radius on screen
    double noise = 0.3;    //!< the scan's noise, in mean edge lengths (AddNoise)
};

//! \brief Makes a document of `mesh` (in the locality numbering) with noise added, and
//! strokes the smoothing brush over it in the front view, as the mouse gives it (a dab a
//! mouse move), for plain smoothing of the painted region and for the denoise-organic
//! preset. Prints per recipe the interface's time per dab (the mouse move that gives it,
//! and the frame's update that takes the runs' shapes), the release (the stroke's end until
//! its final shape is the document's), and the whole stroke.
//! \pre an OpenGL context of `width` x `height` is current.
void paint_case(const Mesh& mesh, int width, int height, const PaintOptions& options);

} // namespace meshfair::bench
