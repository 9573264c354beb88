// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair::bench {

//! The weights of CGAL's fairing Laplacian.
enum class CgalFairWeights
{
    //! Every edge weighs 1 (CGAL::Weights::Uniform_weight): at continuity 0 the system is
    //! sum_j (x_j - x_i) = 0 at each free vertex, the normal equations of MeshFair's edge
    //! energy, so both solve the same system.
    Uniform,
    //! CGAL's default: cotangent weights with the Voronoi area (another energy).
    Cotangent
};

//! \brief The peer of the fairing benchmark: CGAL's Polygon_mesh_processing::fair at
//! continuity 0 (membrane) on a CGAL::Surface_mesh with double-precision points, with
//! CGAL's default sparse solver (Eigen's SparseLU with the COLAMD ordering). CGAL's
//! headers stay inside cgal_fair_peer.cpp, built only with MESHFAIR_BENCH_CGAL.
class CgalFairPeer
{
public:
    //! Builds the halfedge mesh from `mesh`, vertex order kept.
    //! \throw std::runtime_error if CGAL refuses a face (not a manifold triangle mesh).
    explicit CgalFairPeer(const Mesh& mesh);
    ~CgalFairPeer();
    CgalFairPeer(const CgalFairPeer&) = delete;
    CgalFairPeer& operator=(const CgalFairPeer&) = delete;

    //! Puts the positions back (3 #V values).
    void set_positions(std::span<const Scalar> positions);
    //! \brief Fairs `vertices` (the unknowns; every other vertex holds), as one call of
    //! CGAL's fair. False when CGAL reports a failure (its factorization or solve).
    bool fair(std::span<const Index> vertices, CgalFairWeights weights);
    //! 3 #V coordinates.
    std::vector<Scalar> positions() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace meshfair::bench
