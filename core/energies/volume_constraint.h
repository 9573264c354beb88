// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! What the volume constraint keeps on a component that is not closed.
enum class OpenVolume
{
    //! The volume enclosed with each boundary loop capped by a fan from the loop's
    //! centroid (which moves with the loop): defined on every component with faces.
    Capped,
    //! Nothing: open components are left as the solver moves them (named in a note); a
    //! mesh with no closed component is refused.
    None
};

//! \brief The enclosed volume of each component kept through smoothing: after each solver
//! step the free vertices of a component move together along the volume's gradient,
//! x <- x + t g, with t the root nearest 0 of V(x + t g) = V_0.
//!
//! The volume of a component is the divergence theorem's sum over its faces, each polygon
//! fanned from its first corner: V = 1/6 sum_f sum_{m=1}^{n_f-2} det(x_f0, x_fm, x_fm+1).
//! That sum is a volume (the same wherever the origin is) when the faces form a cycle:
//! every edge traversed as often in one direction as in the other. A component that is
//! not closed so (a boundary, an edge of three faces, two faces of opposite orientations)
//! has a boundary chain, the edges traversed more often one way, which decomposes into
//! loops; with OpenVolume::Capped each loop a_0 .. a_{n-1} is closed by the triangles
//! (p, a_{k+1}, a_k) of a fan from its centroid p = 1/n sum_k a_k, and V is the capped
//! surface's volume: well defined, and it follows the boundary as the boundary moves
//! (docs/math.md, "Keeping the volume").
//!
//! Its gradient g_i = dV/dx_i gathers, over the corners of vertex i, the cross products
//! of the fan triangles' other corners, and over the caps those of the cap triangles
//! (p's share spread evenly over its loop); g is 0 at fixed vertices. V(x + t g) is a
//! cubic in t whose four coefficients one pass over the faces and caps sums, so t comes
//! from Newton's iteration on that cubic (from t = 0, where its slope is |g|^2 > 0) to
//! rounding: the volume after the correction equals V_0 to about 1e-15 relative. This is
//! the minimal (Euclidean) change of the free vertices that restores the volume to first
//! order, the projection step of a constrained gradient method.
class VolumeConstraint
{
public:
    //! \pre the topology has TopologyParts::Corners and TopologyParts::Edges; x: 3 #V
    //! positions whose volumes are kept; fixed: #V flags of the vertices no step moves.
    //! free_components_only: keep only the components none of whose vertices is fixed
    //! (where pins or a region's rest hold the shape, fairing may change the volume: a
    //! dragged pin raises a dome).
    //! \throw RecipeError ("volume") when the mesh has no face, or with OpenVolume::None
    //! when no component of the mesh is closed.
    VolumeConstraint(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x,
                     std::span<const char> fixed, OpenVolume open = OpenVolume::Capped,
                     bool free_components_only = false);

    Index component_count() const { return static_cast<Index>(closed_.size()); }
    Index closed_component_count() const;
    //! A component whose faces form a cycle: it needs no caps.
    bool is_closed(Index component) const { return closed_[component] != 0; }
    //! Whether the component's volume is kept: closed, or capped.
    bool is_kept(Index component) const { return kept_[component] != 0; }
    //! The boundary loops that cap the open components (0 with OpenVolume::None).
    Index loop_count() const { return static_cast<Index>(loop_offsets_.size()) - 1; }
    //! The volumes kept (V_0 of each component; 0 for components not kept).
    std::span<const Scalar> target_volumes() const { return target_; }
    //! The enclosed volume of a component at x, capped where it is open (0 for a
    //! component not kept).
    Scalar volume(Index component, std::span<const Scalar> x) const;
    //! What the constraint does besides keeping closed volumes, for reports: the open
    //! components and the rule that keeps them (or that they are left alone).
    const std::vector<std::string>& notes() const { return notes_; }

    //! \brief Moves each kept component's free vertices along the volume gradient until its
    //! volume is V_0 again. Allocates nothing; the same bits for any thread count.
    //! `hold`: free vertices left where they are this time (the gradient taken as 0 there),
    //! as after FlipGuard shortened their steps.
    void project(std::span<Scalar> x, std::span<const Index> hold = {});
    //! \brief The same move along another direction: each kept component's free vertices of
    //! x move along `direction(g)` (g the volume gradient at `at`, 3 #V, rewritten in place;
    //! a direction the components do not mix) until its volume is V_0: the direct method's
    //! step toward the constrained minimizer, the direction A_ff^-1 g (docs/math.md, "The
    //! direct method with the volume kept").
    void project_along(std::span<Scalar> x, std::span<const Scalar> at,
                       const std::function<void(std::span<Scalar>)>& direction);
    //! \brief r less its part along each kept component's volume gradient at x (r, 3 #V,
    //! read and written at the components' free vertices): what is left of the energy's
    //! gradient at a minimizer under the constraint (0 there), for the stopping rule.
    void remove_normal_part(std::span<const Scalar> x, std::span<Scalar> r);

private:
    //! f(component, first, count) for each kept component with free vertices: they are
    //! vertices_[first, first + count).
    template <class F>
    void for_each_kept(F&& f) const
    {
        for (Index component = 0; component < component_count(); ++component)
        {
            const Index first = vertex_offsets_[component];
            const Index count = vertex_offsets_[component + 1] - first;
            if (is_kept(component) && count > 0)
                f(component, first, count);
        }
    }
    //! The volume gradient (times 6) of every kept component at x into gradient_.
    void gather_gradient(std::span<const Scalar> x);
    //! Each kept component's free vertices of x moved along gradient_ to the volume V_0.
    void move_to_targets(std::span<Scalar> x);
    //! 6 times the volume of component c's caps at x (0 without caps).
    Scalar caps_volume6(Index component, std::span<const Scalar> x) const;
    //! Adds the caps' part of 6 dV/dx to g at the component's free vertices.
    void add_caps_gradient(Index component, std::span<const Scalar> x, Scalar* g) const;

    const Mesh* mesh_;
    const Topology* topology_;
    //! The faces and the free vertices of each kept component, in CSR form.
    std::vector<Index> face_offsets_, faces_, vertex_offsets_, vertices_;
    //! The boundary loops (vertices in the boundary's direction, CSR) and, per component,
    //! the range of its loops (CSR over loops).
    std::vector<Index> loop_offsets_{0}, loop_vertices_, component_loops_;
    std::vector<char> fixed_; //!< #V: vertices that no step moves
    std::vector<char> closed_;
    std::vector<char> kept_; //!< per component: its volume is kept
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
