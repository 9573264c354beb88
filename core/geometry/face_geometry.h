// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! |a - b|^2 for 3-vectors at a and b.
inline Scalar squared_distance3(const Scalar* a, const Scalar* b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

//! \brief Centroid x_f = (1/n_f) sum_{i in f} x_i of face f for positions `x` (3 #V).
//! Sum of the positions of face f's corners, in face order (face_centroid before the
//! division; the centroid term scales it itself with a cached 1/n_f).
inline Vec3 face_corner_sum(const Mesh& mesh, const Scalar* x, Index f)
{
    // Inline: the centroid term computes it for every corner of every step.
    Vec3 c{0, 0, 0};
    for (Index v : mesh.face(f))
        for (int a = 0; a < 3; ++a)
            c[a] += x[3 * static_cast<std::ptrdiff_t>(v) + a];
    return c;
}

inline Vec3 face_centroid(const Mesh& mesh, std::span<const Scalar> x, Index f)
{
    Vec3 c = face_corner_sum(mesh, x.data(), f);
    const Scalar inv = Scalar(1) / mesh.face_size(f);
    for (int a = 0; a < 3; ++a)
        c[a] *= inv;
    return c;
}

//! \brief Newell's vector of face f: the sum over its corners of the cross products of
//! consecutive positions, halved; for a planar polygon, its area times its unit normal.
Vec3 face_area_vector(const Mesh& mesh, std::span<const Scalar> x, Index f);

//! \brief Unit normal of face f by Newell's method (the normalized sum of the cross
//! products of consecutive corners), well defined for non-planar polygons; the zero
//! vector for a face of zero area.
Vec3 face_normal(const Mesh& mesh, std::span<const Scalar> x, Index f);

//! Unit normals of all faces (3 #F), see face_normal.
std::vector<Scalar> face_normals(const Mesh& mesh, std::span<const Scalar> x);

//! Mean length of the edges of the primal graph; 0 when there are none.
//! \pre the topology has TopologyParts::Edges or TopologyParts::Neighbors.
Scalar mean_edge_length(const Topology& topology, std::span<const Scalar> x);

//! Axis-aligned bounding box of the vertices; min > max when the mesh has none.
struct BoundingBox
{
    Vec3 min{0, 0, 0};
    Vec3 max{0, 0, 0};
    bool empty = true;
    //! The length of the diagonal, |max - min|; 0 when empty.
    Scalar diagonal() const
    {
        Scalar squared = 0;
        for (int a = 0; a < 3; ++a)
            squared += (max[a] - min[a]) * (max[a] - min[a]);
        return std::sqrt(squared);
    }
    //! The middle, min + (max - min) / 2 on each axis; 0 when empty.
    Vec3 centre() const
    {
        Vec3 c{0, 0, 0};
        if (!empty)
            for (int a = 0; a < 3; ++a)
                c[a] = min[a] + (max[a] - min[a]) / 2;
        return c;
    }
};
BoundingBox bounding_box(std::span<const Scalar> x);

} // namespace meshfair
