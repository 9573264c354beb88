// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief A set of vertices or of faces as one flag (0 or 1) per element: what the editor's
//! tools change, a brush stroke over half a million-vertex mesh included, without keeping
//! a sorted list. selected_indices gives the recipe's index list.
using SelectionMask = std::vector<char>;

//! How a tool's elements combine with the selection: Shift adds, Ctrl subtracts.
enum class SelectOp
{
    Replace,
    Add,
    Subtract
};

//! Applies `elements` to `mask` with `op` (Replace clears the mask first).
void apply_selection(SelectionMask& mask, std::span<const Index> elements, SelectOp op);

//! The indices of the selected elements, increasing.
std::vector<Index> selected_indices(const SelectionMask& mask);

//! Every flag flipped.
void invert_selection(SelectionMask& mask);

//! \brief The selected vertices and their neighbours V(i) (one ring more).
//! \pre topology has the Neighbors part.
SelectionMask grow_vertices(const Topology& topology, const SelectionMask& vertices);

//! \brief The selected vertices all of whose neighbours are selected (one ring less).
//! \pre topology has the Neighbors part.
SelectionMask shrink_vertices(const Topology& topology, const SelectionMask& vertices);

//! \brief The faces that share a vertex with a selected face (one ring more).
//! \pre topology has the Corners part.
SelectionMask grow_faces(const Mesh& mesh, const Topology& topology, const SelectionMask& faces);

//! \brief The selected faces none of whose vertices touch an unselected face.
//! \pre topology has the Corners part.
SelectionMask shrink_faces(const Mesh& mesh, const Topology& topology, const SelectionMask& faces);

//! \brief Every vertex connected to a seed by edges (the seeds' connected components).
//! \pre topology has the Neighbors part.
SelectionMask connected_vertices(const Topology& topology, std::span<const Index> seeds);

//! \brief Every face connected to a seed through shared edges, regular or singular.
//! \pre topology has the Edges part.
SelectionMask connected_faces(const Mesh& mesh, const Topology& topology,
                              std::span<const Index> seeds);

//! \brief The vertices of the boundary edges (n_e = 1).
//! \pre topology has the Edges part.
SelectionMask boundary_vertices(const Topology& topology);

//! \brief The faces with a boundary edge.
//! \pre topology has the Edges part.
SelectionMask boundary_faces(const Mesh& mesh, const Topology& topology);

//! The vertices of the selected faces.
SelectionMask vertices_of_faces(const Mesh& mesh, const SelectionMask& faces);

//! The faces whose every vertex is selected.
SelectionMask faces_of_vertices(const Mesh& mesh, const SelectionMask& vertices);

} // namespace meshfair
