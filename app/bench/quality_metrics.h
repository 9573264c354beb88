// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair::bench {

// The figures of the mesh-denoising literature for a result x against the clean mesh
// (same connectivity), as meshfair-quality reports them.

//! \brief theta: the mean over faces of the angle, in degrees, between face f's unit normal
//! at `x` and at `clean_x` (Newell's normal, so polygons too; core's face_normal). A face of
//! zero area in either counts as 90 degrees.
//! \pre x and clean_x hold 3 #V values.
Scalar mean_normal_angle_deg(const Mesh& mesh, std::span<const Scalar> x,
                             std::span<const Scalar> clean_x);

//! \brief Distance from points to a fixed surface: its faces fan-triangulated from their
//! first corner, in a uniform grid of cells about two triangle sizes wide; a query visits
//! rings of cells around the point's cell until no unvisited cell can hold a closer point.
//! State outlives a call: built once per clean mesh, queried for every result.
class SurfaceDistance
{
public:
    //! \pre the mesh has at least one face; x holds 3 #V values.
    SurfaceDistance(const Mesh& mesh, std::span<const Scalar> x);

    //! Euclidean distance from p to the nearest point of the surface.
    Scalar distance(const Vec3& p) const;
    //! Length of the diagonal of the surface's bounding box.
    Scalar diagonal() const { return diagonal_; }

private:
    std::vector<std::array<Vec3, 3>> triangles_;
    Vec3 origin_{0, 0, 0};
    Scalar cell_ = 1;
    std::array<int, 3> cells_{1, 1, 1};
    std::vector<Index> cell_offsets_, cell_triangles_; //!< CSR: the triangles touching a cell
    Scalar diagonal_ = 0;
};

//! \brief Distance from p to the triangle (a, b, c) (closest point by Voronoi regions,
//! Ericson, Real-Time Collision Detection, 5.1.5); degenerate triangles by their edges.
Scalar point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

//! \brief E_v: the mean over the vertices of x of their distance to the clean surface,
//! divided by the clean surface's bounding-box diagonal.
Scalar mean_relative_distance(const SurfaceDistance& clean, std::span<const Scalar> x);

//! \brief Signed volume enclosed by the faces (divergence theorem over the faces
//! fan-triangulated from their first corner, about the centre of the bounding box); positive
//! for a closed outward-oriented mesh.
Scalar signed_volume(const Mesh& mesh, std::span<const Scalar> x);

//! \brief The volume of an open mesh as the volume constraint keeps it: each component's,
//! with its boundary loops capped by fans from their centroids (VolumeConstraint,
//! docs/math.md), summed. The enclosed volume where the mesh is closed.
//! \pre the topology has TopologyParts::Corners and TopologyParts::Edges.
Scalar capped_volume(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x);

//! \brief How many faces are turned over at x against `before`: their Newell vectors more
//! than 90 degrees apart, among the faces that lie in the surface at `before` (within 60
//! degrees of the sum of the Newell vectors of the faces sharing a vertex with them). The
//! presets' flip guard holds these to their normals at `before` (docs/math.md).
Index turned_over_faces(const Mesh& mesh, std::span<const Scalar> x,
                        std::span<const Scalar> before);

//! \brief Delta V: 100 (V(x) - V(clean_x)) / V(clean_x), in percent (signed_volume).
Scalar volume_change_percent(const Mesh& mesh, std::span<const Scalar> x,
                             std::span<const Scalar> clean_x);

//! \brief The dihedral angle at every edge in degrees (0 = flat): the angle between the unit
//! normals of its two faces; NaN at edges without exactly two faces (#E values).
//! \pre the topology has TopologyParts::Edges.
std::vector<Scalar> dihedral_angles_deg(const Mesh& mesh, const Topology& topology,
                                        std::span<const Scalar> x);

//! \brief The p-th percentile (0 < p <= 100) by the nearest-rank method: the smallest value
//! with at least p% of the values at or below it; NaN for no values.
Scalar percentile(std::vector<Scalar> values, Scalar p);

//! The seam figure of a region: the 95th percentile of the dihedral angle on classes of
//! edges (see seam_figure); NaN for an empty class.
struct SeamFigure
{
    Scalar border_p95_deg = 0;       //!< border rings, inside and outside
    Scalar inner_border_p95_deg = 0; //!< border rings, both ends in the region
    Scalar interior_p95_deg = 0;
    Index border_edges = 0;
    Index inner_border_edges = 0;
    Index interior_edges = 0;
};

//! \brief Whether smoothing a region leaves a visible seam. The border ring is the region's
//! vertices with a neighbour outside it; d(v) is the edge-graph distance to the border ring.
//! Edges with two faces are classified as "border rings" when an endpoint has d <= 2 (the
//! border ring, the two rings inside it and the two outside) and as "interior" when both
//! endpoints are in the region with d > 2; other edges are not counted. The border-ring
//! edges with both ends in the region are also counted on their own ("inner border"): when
//! the outside is left noisy, they show the seam without the outside's noise.
//! \pre the topology has TopologyParts::Edges and Neighbors; region vertices in [0, #V).
SeamFigure seam_figure(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                       std::span<const Index> region_vertices);

} // namespace meshfair::bench
