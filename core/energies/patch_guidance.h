// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief Guidance normals of guided mesh normal filtering \cite zhang_2015: for each face,
//! the area-weighted mean normal of the most consistent patch that contains it.
//!
//! The patch P_g of a face g is g with the faces sharing a vertex with it; the patches that
//! contain a face f are those of f and of the faces sharing a vertex with f. A patch's
//! consistency is
//!
//!     H(P) = D(P) * R(P),  D(P) = max_{i,j in P} |u_i - u_j|,
//!     R(P) = max_{e in E_P} phi(e) / (eps + sum_{e in E_P} phi(e)),
//!
//! E_P the edges shared by two faces of P, phi(e) = |u_i - u_j| for e's two faces, eps =
//! 1e-9: low when the normals in P barely differ (small D) or differ everywhere alike, as
//! noise does (small R), high when P straddles a crease (one large jump among small ones).
//! The guidance normal of f is m_P = normalize(sum_{i in P} A_i u_i) of the patch of
//! least H among those containing f (the lowest face number on a tie), so a face beside
//! a crease is guided by a patch on its own side. The guidance is then the range input
//! of the bilateral weights (BilateralFaceWeights with BilateralWeights::guided).
class PatchGuidance
{
public:
    //! \pre the topology has TopologyParts::Dual and TopologyParts::Corners.
    PatchGuidance(const Mesh& mesh, const Topology& topology);

    //! \brief Writes into g (3 #F) the guidance normals of normals u (3 #F) with the face
    //! areas at positions x (3 #V). Allocates nothing; the same bits for any thread count.
    //! A face whose best patch has no area keeps its own normal as guidance.
    void compute(std::span<const Scalar> x, std::span<const Scalar> u, std::span<Scalar> g);

    //! The faces of f's patch other than f (sorted).
    std::span<const Index> ring_of(Index f) const
    {
        return {ring_.data() + offsets_[f], static_cast<size_t>(offsets_[f + 1] - offsets_[f])};
    }
    //! H(P_f) of the last compute().
    Scalar consistency(Index f) const { return consistency_[f]; }

private:
    const Mesh* mesh_;
    const Topology* topology_;
    std::vector<Index> offsets_, ring_; //!< CSR: the faces sharing a vertex with each face
    //! CSR: each patch's E_P, as positions in the topology's face_neighbors listing
    std::vector<Index> inner_offsets_, inner_edges_;
    std::vector<Scalar> area_;        //!< A_f at the last compute(), #F
    std::vector<Scalar> jump_;        //!< phi of each dual-graph listing (CSR of N*(f))
    std::vector<Scalar> consistency_; //!< H(P_f), #F
    std::vector<Scalar> mean_;        //!< m_{P_f}, 3 #F
};

//! \brief The faces sharing a vertex with f, for every f: CSR (offsets #F + 1), each list
//! sorted, f excluded. \pre the topology has TopologyParts::Corners.
void vertex_face_rings(const Mesh& mesh, const Topology& topology, std::vector<Index>& offsets,
                       std::vector<Index>& rings);

} // namespace meshfair
