// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief Keeps a solver step from turning faces over: a face is turned over when its
//! Newell vector n_f points away from its reference normal r_f, the input's
//! (n_f . r_f <= 0: more than 90 degrees from it). After a step from x to y, each free
//! vertex of a face that the step turned over (one that was not turned over at x) has its
//! step shortened, y_i = x_i + t_i (y_i - x_i) with t_i = 1/2, 1/4, 1/8, 1/16 and then 0,
//! and the faces around the shortened vertices are checked again, until none is turned
//! over: a per-vertex backtracking line search on the orientation of the vertex's star
//! (docs/math.md, "Faces never turned over"). It ends: with every t_i = 0 a face is
//! where it was at x. Faces of zero input area have no reference and are not checked;
//! faces already turned over at x may be turned back.
class FlipGuard
{
public:
    //! \pre the topology has TopologyParts::Corners; x0: 3 #V reference positions;
    //! fixed: #V flags of the vertices no step moves.
    FlipGuard(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x0,
              std::span<const char> fixed);

    //! \brief Shortens the step x -> y where it turns faces over (y written at free
    //! vertices only). Returns how many vertices' steps were shortened. The same bits for
    //! any thread count; allocates only while it shortens steps.
    Index limit(std::span<const Scalar> x, std::span<Scalar> y);
    //! The vertices whose steps the last limit() shortened, in the order it shortened them.
    std::span<const Index> shortened() const { return shortened_; }

    //! Whether face f is turned over at x (n_f . r_f <= 0; false for faces not checked).
    bool turned_over(std::span<const Scalar> x, Index f) const;

private:
    const Mesh* mesh_;
    const Topology* topology_;
    std::vector<Scalar> reference_; //!< 3 #F: the input's Newell vectors (0: not checked)
    std::vector<Index> faces_;      //!< the checked faces with a free vertex, ascending
    std::vector<char> fixed_;       //!< #V
    std::vector<char> flagged_;     //!< per entry of faces_: turned over by this step
    std::vector<Index> shortened_;  //!< the last limit()'s shortened vertices
};

} // namespace meshfair
