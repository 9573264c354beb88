// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair::bench {

// Clean meshes with sharp features for meshfair-quality (app/bench/quality_main.cpp). Each
// is a consistently oriented 2-manifold with near-uniform edge lengths (the noise is scaled
// by the mean edge length), about 10k vertices by default; all are closed but the scan
// patch (one boundary loop) and the holed part (six holes), as scans come.

//! \brief An axis-aligned cube of edge `side` centred at the origin, each face an n x n grid
//! of squares split into two triangles along the same diagonal. #V = 6 n^2 + 2.
//! \pre n >= 1 (else std::invalid_argument), side > 0.
Mesh cube_mesh(int n = 40, Scalar side = 2);

//! \brief A closed all-quad rounded box: the n x n grids of the cube [-1, 1]^3, each grid point
//! c moved to q + r (c - q) / |c - q|, q = c clamped to the inner box [-(1 - r), 1 - r]^3 and
//! r = corner_radius. Flat faces (where c stays), cylindrical edges and spherical corners, at
//! distance r from the inner box; the quads stay quads. #V = 6 n^2 + 2, #F = 6 n^2.
//! \pre n >= 1, 0 < corner_radius < 1. \throw std::invalid_argument otherwise.
Mesh rounded_box_quad_mesh(int n = 40, Scalar corner_radius = 0.3);

//! One point (rho, z) of a meridian profile: distance from the z axis and height.
using ProfilePoint = std::array<Scalar, 2>;

//! \brief The triangle mesh of a closed surface of revolution about the z axis. The profile
//! runs from a pole (rho = 0) on the axis to another, counter-clockwise around the solid in
//! the (rho, z) half-plane (first outwards at the bottom, last inwards at the top), so the
//! faces face outwards. Each profile point with rho > 0 becomes a ring of round(2 pi rho /
//! edge) points (at least 3), every other ring turned by half a step; consecutive rings are
//! joined by a strip of triangles that follows the angle.
//! \pre profile.size() >= 3, the first and last points have rho = 0, the others rho > 0.
//! \throw std::invalid_argument otherwise.
Mesh revolve_profile(std::span<const ProfilePoint> profile, Scalar edge);

//! \brief A cylinder of radius r and height h (z in [-h/2, h/2]) capped by flat disks, the
//! caps meshed with concentric rings: the cap-side edges are 90-degree creases.
Mesh cylinder_mesh(Scalar radius = 1, Scalar height = 2, Scalar edge = 0.045);

//! \brief The sphere of radius r cut by the planes z = z_low and z = z_high
//! (-r < z_low < z_high < r): a spherical zone between two flat disks, meeting them along
//! circular creases of 90 deg - asin(|z| / r) (60 and 45.6 degrees by default).
//! \throw std::invalid_argument unless -r < z_low < z_high < r.
Mesh cut_sphere_mesh(Scalar radius = 1, Scalar z_low = -0.5, Scalar z_high = 0.7,
                     Scalar edge = 0.04);

//! A half-space normal . x <= offset (the normal need not be unit length).
struct HalfSpace
{
    Vec3 normal;
    Scalar offset;
};

//! \brief The surface of the convex polyhedron that is the intersection of the half-spaces
//! (every plane must carry a face; no four planes through one corner). Each polygon edge is
//! cut into round(length / edge) equal segments, shared by its two faces; each face holds
//! the points of an equilateral triangular lattice of spacing `edge` (rows parallel to its
//! first side) that lie at least 0.55 edge inside it, and is the Delaunay triangulation of
//! its boundary and lattice points.
//! \throw std::invalid_argument when the half-spaces do not bound such a polyhedron;
//! std::logic_error when a face's triangulation fails its check (triangle count, area).
Mesh convex_polyhedron_mesh(std::span<const HalfSpace> half_spaces, Scalar edge);

//! \brief The half-spaces of the "CAD-like part": the block [0, 2] x [0, 1.5] x [0, 1]
//! with a 45-degree chamfer on the edge y = 0, z = 1, a bevel on the edge y = 1.5, z = 0
//! (creases of 30.3 and 59.7 degrees) and the corner (2, 1.5, 1) cut off by the plane
//! x + y + z = 4 (creases of 54.7 degrees, a triangle whose corners each join three creases).
std::vector<HalfSpace> cad_part_half_spaces();

//! convex_polyhedron_mesh(cad_part_half_spaces(), edge).
Mesh cad_part_mesh(Scalar edge = 0.04);

//! \brief An open scan-like patch: the height field z = h(x, y) over a wobbly disk of radius
//! about 1 (r < 1 + 0.08 sin 5 phi), sampled on a grid of spacing `edge`, each square split
//! along one diagonal, the squares the disk cuts kept as far as their triangles lie in it
//! (a ragged border, as a scan's). h is a ridge (a crease of 28 degrees along x = 0.1),
//! two valleys (creases of 14 degrees along x = -0.5 and x = 0.7) and a smooth bump.
//! Faces point up (+z). One boundary loop.
Mesh scan_patch_mesh(Scalar edge = 0.02);

//! \brief The CAD-like part with six round holes of radius 0.12 cut out (the faces whose
//! centroid lies within it of six points of its surface, on flat faces, creases and a
//! corner), unused vertices dropped: a closed model with holes, six boundary loops.
Mesh holed_part_mesh(Scalar edge = 0.04);

//! Names of the generated meshes, in report order: cube, cylinder, cad-part, cut-sphere,
//! quad-box, scan-patch, holed-part.
std::vector<std::string> generated_mesh_names();

//! \brief The generated mesh of that name, at its default size.
//! \throw std::invalid_argument naming an unknown name and the known ones.
Mesh generated_mesh(const std::string& name);

} // namespace meshfair::bench
