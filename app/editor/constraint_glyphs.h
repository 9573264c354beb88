// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string_view>
#include <vector>

#include "app/editor/document.h"
#include "app/render/renderer.h"

namespace meshfair::app {

//! At most this many glyphs per set are drawn (evenly spread over the set): a set over a
//! whole scan would otherwise hide the surface it constrains.
inline constexpr size_t kMaxGlyphsPerSet = 50000;

//! \brief The glyphs of the document's visible sets at the current positions, in each set's
//! colour: pins as large dots (at their targets), anchors as dots, centroids as dots at
//! the face centroids, normals as arrows of six mean edge lengths from the centroids of up to
//! 24 of the set's faces (the set's own directions or
//! the current face normals), and for regions the border ring: the fixed vertices next to
//! a moving one, joined by the edges between them.
//! \brief The border ring of the regions: the vertices outside every region that have a
//! neighbour inside one (what stays put where the smoothing stops), and the edges between
//! two of them (vertex pairs). Empty without regions. It depends on the sets only, so the
//! editor computes it once per set change, not per frame.
struct RegionBorder
{
    std::vector<Index> vertices;
    std::vector<Index> edges; //!< 2 per edge
};
RegionBorder region_border(const Document& document);

//! `hidden`: a set whose glyphs are left out (the set whose weight map the Paint tool shows
//! in colour: its dots would cover the colours).
std::vector<GlyphGroup> constraint_glyphs(const Document& document, const RegionBorder& border,
                                          std::string_view hidden = {});

} // namespace meshfair::app
