// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/cgal_fair_peer.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Weights/uniform_weights.h>

#include <stdexcept>
#include <string>

namespace meshfair::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using VertexIndex = SurfaceMesh::Vertex_index;

} // namespace

struct CgalFairPeer::State
{
    SurfaceMesh mesh;
};

CgalFairPeer::CgalFairPeer(const Mesh& mesh) : state_(std::make_unique<State>())
{
    SurfaceMesh& m = state_->mesh;
    m.reserve(static_cast<SurfaceMesh::size_type>(mesh.vertex_count()),
              static_cast<SurfaceMesh::size_type>(mesh.vertex_count() + mesh.face_count()),
              static_cast<SurfaceMesh::size_type>(mesh.face_count()));
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        const Vec3 p = mesh.position(i);
        m.add_vertex(Point(p[0], p[1], p[2]));
    }
    std::vector<VertexIndex> corners;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        corners.clear();
        for (const Index v : mesh.face(f))
            corners.push_back(VertexIndex(static_cast<SurfaceMesh::size_type>(v)));
        if (corners.size() != 3 || m.add_face(corners) == SurfaceMesh::null_face())
            throw std::runtime_error("CGAL's Surface_mesh refuses face " + std::to_string(f) +
                                     " (fair needs a manifold triangle mesh)");
    }
}

CgalFairPeer::~CgalFairPeer() = default;

void CgalFairPeer::set_positions(std::span<const Scalar> positions)
{
    SurfaceMesh& m = state_->mesh;
    for (const VertexIndex v : m.vertices())
    {
        const size_t i = 3 * static_cast<size_t>(v.idx());
        m.point(v) = Point(positions[i], positions[i + 1], positions[i + 2]);
    }
}

bool CgalFairPeer::fair(std::span<const Index> vertices, CgalFairWeights weights)
{
    namespace pmp = CGAL::Polygon_mesh_processing;
    SurfaceMesh& m = state_->mesh;
    std::vector<VertexIndex> range;
    range.reserve(vertices.size());
    for (const Index v : vertices)
        range.push_back(VertexIndex(static_cast<SurfaceMesh::size_type>(v)));
    if (weights == CgalFairWeights::Uniform)
        return pmp::fair(m, range,
                         CGAL::parameters::fairing_continuity(0).weight_calculator(
                             CGAL::Weights::Uniform_weight<SurfaceMesh>()));
    return pmp::fair(m, range, CGAL::parameters::fairing_continuity(0));
}

std::vector<Scalar> CgalFairPeer::positions() const
{
    const SurfaceMesh& m = state_->mesh;
    std::vector<Scalar> out(3 * static_cast<size_t>(m.number_of_vertices()));
    for (const VertexIndex v : m.vertices())
    {
        const Point& p = m.point(v);
        const size_t i = 3 * static_cast<size_t>(v.idx());
        out[i] = p.x();
        out[i + 1] = p.y();
        out[i + 2] = p.z();
    }
    return out;
}

} // namespace meshfair::bench
