// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/openmesh_peer.h"

// MeshIO.hh must come before the mesh kernels: it registers the file readers.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>
#include <stdexcept>

namespace meshfair::bench {

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits
{
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using PeerMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using Smoother = OpenMesh::Smoother::JacobiLaplaceSmootherT<PeerMesh>;

} // namespace

struct OpenMeshPeer::State
{
    PeerMesh mesh;
    std::unique_ptr<Smoother> smoother;
};

OpenMeshPeer::OpenMeshPeer(const Mesh& mesh) : state_(std::make_unique<State>())
{
    PeerMesh& m = state_->mesh;
    std::vector<PeerMesh::VertexHandle> handles;
    handles.reserve(static_cast<size_t>(mesh.vertex_count()));
    for (Index i = 0; i < mesh.vertex_count(); ++i)
    {
        const Vec3 p = mesh.position(i);
        handles.push_back(m.add_vertex(PeerMesh::Point(p[0], p[1], p[2])));
    }
    std::vector<PeerMesh::VertexHandle> face;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        face.clear();
        for (const Index i : mesh.face(f))
            face.push_back(handles[static_cast<size_t>(i)]);
        if (!m.add_face(face).is_valid())
            throw std::runtime_error("OpenMesh refused face " + std::to_string(f));
    }
    state_->smoother = std::make_unique<Smoother>(m);
    state_->smoother->initialize(Smoother::Tangential_and_Normal, Smoother::C0);
}

OpenMeshPeer::~OpenMeshPeer() = default;

void OpenMeshPeer::smooth(int iterations)
{
    state_->smoother->smooth(static_cast<unsigned>(iterations));
}

std::vector<Scalar> OpenMeshPeer::positions() const
{
    const PeerMesh& m = state_->mesh;
    std::vector<Scalar> x;
    x.reserve(3 * m.n_vertices());
    for (const auto v : m.vertices())
        for (int a = 0; a < 3; ++a)
            x.push_back(m.point(v)[a]);
    return x;
}

void OpenMeshPeer::set_positions(std::span<const Scalar> positions)
{
    PeerMesh& m = state_->mesh;
    for (const auto v : m.vertices())
    {
        const size_t i = 3 * static_cast<size_t>(v.idx());
        m.set_point(v, PeerMesh::Point(positions[i], positions[i + 1], positions[i + 2]));
    }
}

std::vector<Index> OpenMeshPeer::boundary_vertices() const
{
    std::vector<Index> boundary;
    for (const auto v : state_->mesh.vertices())
        if (state_->mesh.is_boundary(v))
            boundary.push_back(v.idx());
    return boundary;
}

Index openmesh_read(const std::string& path)
{
    PeerMesh m;
    if (!OpenMesh::IO::read_mesh(m, path))
        throw std::runtime_error("OpenMesh could not read " + path);
    return static_cast<Index>(m.n_vertices());
}

} // namespace meshfair::bench
