// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief The enclosed volume of each closed component kept through smoothing: after
//! each solver step the free vertices of a closed component move together along the
//! volume's gradient, x <- x + t g, with t the root nearest 0 of V(x + t g) = V_0.
//!
//! The volume of a component is the divergence theorem's sum over its faces, each polygon
//! fanned from its first corner: V = 1/6 sum_f sum_{m=1}^{n_f-2} det(x_f0, x_fm, x_fm+1).
//! Its gradient g_i = dV/dx_i gathers, over the corners of vertex i, the cross products
//! of the fan triangles' other corners; g is 0 at fixed vertices. V(x + t g) is a cubic in
//! t whose four coefficients one pass over the faces sums, so t comes from Newton's
//! iteration on that cubic (from t = 0, where its slope is |g|^2 > 0) to rounding: the
//! volume after the correction equals V_0 to about 1e-15 relative. This is the minimal
//! (Euclidean) change of the free vertices that restores the volume to first order, the
//! projection step of a constrained gradient method; derivation in docs/math.md
//! ("Keeping the volume").
//!
//! A component is closed when every edge of its faces has exactly two faces that traverse
//! it in opposite directions (an oriented closed 2-manifold, possibly with pinched
//! vertices); only closed components have a volume. The others are left as the solver
//! moves them and named in notes().
class VolumeConstraint
{
public:
    //! \pre the topology has TopologyParts::Corners and TopologyParts::Edges; x: 3 #V
    //! positions whose volumes are kept; fixed: #V flags of the vertices no step moves.
    //! \throw RecipeError ("volume") when no component of the mesh is closed.
    VolumeConstraint(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                     std::span<const char> fixed);

    Index component_count() const { return static_cast<Index>(closed_.size()); }
    Index closed_component_count() const;
    bool is_closed(Index component) const { return closed_[component] != 0; }
    //! The volumes kept (V_0 of each component; 0 for components that are not closed).
    std::span<const Scalar> target_volumes() const { return target_; }
    //! The enclosed volume of a component at x (meaningful for closed ones).
    Scalar volume(Index component, std::span<const Scalar> x) const;
    //! What the constraint leaves alone, for reports: the components that are not closed.
    const std::vector<std::string>& notes() const { return notes_; }

    //! \brief Moves each closed component's free vertices along the volume gradient until
    //! its volume is V_0 again. Allocates nothing; the same bits for any thread count.
    void project(std::span<Scalar> x);

private:
    const Mesh* mesh_;
    const Topology* topology_;
    //! The faces and the free vertices of each closed component, in CSR form.
    std::vector<Index> face_offsets_, faces_, vertex_offsets_, vertices_;
    std::vector<char> closed_;
    std::vector<Scalar> target_;
    std::vector<Scalar> gradient_; //!< 3 #V scratch: g, 0 at fixed vertices
    std::vector<std::string> notes_;
};

//! \brief 6 dV/dx_i, the gradient at vertex i of six times the volume of the faces around
//! it (each fanned from its first corner), written to out[0..3).
//! \pre the topology has TopologyParts::Corners.
void volume_gradient6(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                      Index i, Scalar* out);

} // namespace meshfair
