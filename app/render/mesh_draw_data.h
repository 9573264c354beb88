// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair::app {

//! \brief What the renderer draws of a polygon mesh, built once per connectivity (no GL).
//!
//! Polygons are fan-triangulated for drawing only: face f with corners c0 .. c(n-1) gives
//! the triangles (c0, ck, ck+1), k = 1 .. n-2, and triangle_face maps each back to f (the
//! ID buffer and flat shading read it). The wireframe draws the polygon edges, never the
//! fan's diagonals (triangle_edges tells them apart). Boundary (n_e = 1) and singular (n_e >= 3)
//! edges are listed apart for their highlight.
struct MeshDrawData
{
    std::uint32_t vertex_count = 0;
    std::uint32_t face_count = 0;
    std::vector<std::uint32_t> triangles;     //!< 3 vertex indices per triangle
    std::vector<std::uint32_t> triangle_face; //!< the face of each triangle
    //! Per triangle (c0, c1, c2), bit k set when its side from ck to ck+1 (mod 3) is an
    //! edge of its polygon, not a diagonal of the fan (what the wireframe draws).
    std::vector<std::uint8_t> triangle_edges;
    std::vector<std::uint32_t> edges;          //!< 2 vertex indices per polygon edge
    std::vector<std::uint32_t> boundary_edges; //!< 2 per boundary edge
    std::vector<std::uint32_t> singular_edges; //!< 2 per singular edge
    //! The faces around each vertex (CSR), for the vertex normals.
    std::vector<Index> vertex_face_offsets, vertex_faces;
};

//! \brief The draw data of `mesh`. `topology` must hold the Edges and Corners parts.
//! \pre the mesh has fewer than 2^32 vertices and its fan has fewer than 2^32 / 3 triangles.
MeshDrawData mesh_draw_data(const Mesh& mesh, const Topology& topology);

//! \brief Each face's area vector (Newell's method: half the sum of p_k x p_k+1 over its
//! corners, whose length is the area of a planar polygon and which a non-planar one
//! averages), as floats, 3 #F, computed face by face on the threads.
void face_area_vectors(std::span<const Scalar> positions, const Mesh& mesh, std::span<float> out);
//! The same from float coordinates (the GPU's copy), the products still in double.
void face_area_vectors(std::span<const float> positions, const Mesh& mesh, std::span<float> out);

//! \brief Unit vertex normals, 3 #V: the normalized sum of the area vectors of the faces
//! around each vertex (area-weighted), (0, 0, 0) where that sum vanishes (isolated or
//! degenerate). Each vertex gathers its own sum, so any thread count gives the same bits.
void vertex_normals(std::span<const Index> vertex_face_offsets, std::span<const Index> vertex_faces,
                    std::span<const float> face_areas, std::span<float> out);
//! The same, from the draw data's faces around each vertex.
inline void vertex_normals(const MeshDrawData& data, std::span<const float> face_areas,
                           std::span<float> out)
{
    vertex_normals(data.vertex_face_offsets, data.vertex_faces, face_areas, out);
}

//! Positions as floats for the GPU, converted on the threads.
void positions_to_float(std::span<const Scalar> positions, std::span<float> out);

//! \brief Ascending, disjoint index ranges [begin[k], end[k]) of vertices or of faces, with
//! the count of indices before each range (for splitting them over the threads).
struct IndexRanges
{
    std::vector<Index> begin, end, before;
    //! The indices in all ranges.
    Index count() const { return before.empty() ? 0 : before.back() + (end.back() - begin.back()); }
};

//! \brief The part of the display geometry a solver run can change (Session moves only its
//! free vertices): the vertices whose position or normal can change (the free vertices and
//! every corner of a face around one) and the faces whose area vector can (those around a
//! free vertex). Ranges closer than a few dozen indices are merged, and more when there
//! would be hundreds of them: recomputing and uploading some unchanged elements costs less
//! than a range of its own (an upload call each). A region the artist selected, in the
//! document's locality numbering, is a few ranges.
struct ChangingPart
{
    IndexRanges vertices, faces;
};
//! The changing part for `free_vertices` (ascending) of `mesh` (its faces; its positions
//! are not read), whose faces around each vertex are given as in MeshDrawData.
ChangingPart changing_part(const Mesh& mesh, std::span<const Index> vertex_face_offsets,
                           std::span<const Index> vertex_faces,
                           std::span<const Index> free_vertices);

//! \brief What the view draws of a solver frame, computed on the solver's thread so that the
//! interface only uploads it: float positions and unit vertex normals (3 #V) and face area
//! vectors (3 #F). Frames of one run (`run` != 0, from new_display_run) differ only in the
//! run's `changing` part (null: anywhere), which is all a frame recomputes and uploads.
struct DisplayGeometry
{
    std::vector<float> positions, normals, face_areas;
    std::uint64_t run = 0;
    std::shared_ptr<const ChangingPart> changing;
};

//! A run number no other run of this process has (never 0).
std::uint64_t new_display_run();

//! \brief `g` for the positions `x`: only the changing part when `g` already holds a frame of
//! `run`, else everything (and `g` becomes a frame of `run`, changing in `changing`). The
//! same values as a computation of everything (each element's own expression).
//! \pre outside `changing`, x is what g's earlier frame of `run` was computed from.
void update_display_geometry(std::span<const Scalar> x, const Mesh& mesh,
                             std::span<const Index> vertex_face_offsets,
                             std::span<const Index> vertex_faces, std::uint64_t run,
                             std::shared_ptr<const ChangingPart> changing, DisplayGeometry& g);

} // namespace meshfair::app
