// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair::bench {

//! \brief The peer of the benchmark: an OpenMesh triangle mesh with double-precision
//! points, and OpenMesh's JacobiLaplaceSmootherT configured as the uniform Laplacian in
//! all three components with C0 continuity, which is MeshFair's plain Laplacian step with
//! lambda = 1/2 and the boundary vertices fixed (OpenMesh never moves them).
//! OpenMesh's headers stay inside openmesh_peer.cpp.
class OpenMeshPeer
{
public:
    //! Builds the halfedge mesh from `mesh`, vertex and face order kept.
    //! \throw std::runtime_error if OpenMesh refuses a face (non-manifold input).
    explicit OpenMeshPeer(const Mesh& mesh);
    ~OpenMeshPeer();
    OpenMeshPeer(const OpenMeshPeer&) = delete;
    OpenMeshPeer& operator=(const OpenMeshPeer&) = delete;

    //! `iterations` steps of the smoother (one smooth() call).
    void smooth(int iterations);
    //! 3 #V coordinates.
    std::vector<Scalar> positions() const;
    //! Puts the positions back (3 #V values).
    void set_positions(std::span<const Scalar> positions);
    //! Vertices OpenMesh treats as boundary (and never moves).
    std::vector<Index> boundary_vertices() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

//! \brief OpenMesh's reader (IO::read_mesh) into the same mesh type, which builds its
//! halfedge connectivity while reading; returns the vertex count read.
//! \throw std::runtime_error when OpenMesh cannot read the file.
Index openmesh_read(const std::string& path);

} // namespace meshfair::bench
