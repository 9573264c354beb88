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
//! neighbour inside one (what stays put where the smoothing stops), and the line where the
//! moving part meets them: in each face with vertices on both sides, a segment between the
//! midpoints of two of its edges that cross from inside to outside (consecutive ones
//! around the face), so that the line is unbroken however the ring's vertices are joined.
//! Empty without regions. It depends on the sets only, so the editor computes it once per
//! set change, not per frame.
struct RegionBorder
{
    std::vector<Index> vertices;
    //! 4 per segment: the two ends of the first crossing edge, then of the second; a
    //! segment joins their midpoints.
    std::vector<Index> crossings;
};
RegionBorder region_border(const Document& document);

//! One arrow of a normal set as drawn: from a face centroid, along the face's normal (the
//! set's own, or the face's now), six mean edge lengths long.
struct NormalArrow
{
    Vec3 base, tip;
};
//! \brief The arrows of a normal set (none for another kind): up to 24, from evenly spread
//! faces, so that a few long arrows show a direction better than one per face. `length`:
//! the arrows' length (negative: six mean edge lengths of the mesh now). The glyphs draw
//! them and the D tool grabs them, anywhere along.
std::vector<NormalArrow> normal_arrows(const Document& document, const ConstraintSet& set,
                                       Scalar length = -1);
//! \brief The unit area-weighted mean of a set's normals (its own, or its faces' now): the
//! direction its row shows and a drag of the D tool starts from; +z when they cancel.
Vec3 set_mean_normal(const Mesh& mesh, std::span<const Scalar> positions, const ConstraintSet& set);

//! `hidden`: a set whose glyphs are left out (the set whose weight map the Paint tool shows
//! in colour: its dots would cover the colours).
std::vector<GlyphGroup> constraint_glyphs(const Document& document, const RegionBorder& border,
                                          std::string_view hidden = {});

} // namespace meshfair::app
