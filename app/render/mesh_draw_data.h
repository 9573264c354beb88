// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
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
//! fan's diagonals. Boundary (n_e = 1) and singular (n_e >= 3) edges are listed apart for
//! their highlight.
struct MeshDrawData
{
    std::uint32_t vertex_count = 0;
    std::uint32_t face_count = 0;
    std::vector<std::uint32_t> triangles;      //!< 3 vertex indices per triangle
    std::vector<std::uint32_t> triangle_face;  //!< the face of each triangle
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

} // namespace meshfair::app
