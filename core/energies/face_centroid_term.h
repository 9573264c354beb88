// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/geometry/face_geometry.h"
#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! Which Jacobi denominator the centroid term uses; see FaceCentroidTerm.
enum class CentroidDenominator
{
    Paper, //!< n_i + mu sum_{f in F_C(i)} 1/n_f, as printed (a majorizer; the default)
    Exact  //!< n_i + mu sum_{f in F_C(i)} 1/n_f^2, the exact one-variable minimizer
};

//! \brief Soft face-centroid constraints \cite taubin_2012 ("Face Centroid Constraints"):
//!
//!     E_C(x) = mu sum_{f in F_C} |x_f - x0_f|^2,   x_f = (1/n_f) sum_{i in f} x_i
//!
//! Gradient: dE_C/dx_i = 2 mu sum_{f in F_C(i)} (1/n_f)(x_f - x0_f). Right-hand side
//! mu sum_f (1/n_f)(x0_f - x_f) as printed. Minimizing E exactly in x_i alone gives
//! the diagonal contribution mu sum_f 1/n_f^2; the paper prints mu sum_f 1/n_f, which is
//! larger. With the printed one the simultaneous (Jacobi) step decreases E_L + E_C for
//! every lambda in (0, 1) on any mesh, because each face's block c c^T is bounded by
//! diag(1/n_f) (docs/math.md); with the exact one that holds only for
//! lambda < 2 / max(2, max n_f): always for triangles at 0.5, never guaranteed beyond
//! quads. Both are offered; Paper is the default.
class FaceCentroidTerm
{
public:
    //! \pre faces distinct and < #F; targets hold 3 values per listed face.
    FaceCentroidTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces,
                     Scalar mu, std::span<const Scalar> targets, CentroidDenominator denominator);
    //! The same with every target at the origin until set_targets or
    //! set_targets_to_centroids.
    FaceCentroidTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces,
                     Scalar mu, CentroidDenominator denominator);

    void set_targets(std::span<const Scalar> targets);
    //! Targets at the listed faces' centroids for positions `x` (3 #V): no gathered copy.
    void set_targets_to_centroids(std::span<const Scalar> x);
    const std::vector<Index>& faces() const { return faces_; }

    Scalar energy(std::span<const Scalar> x) const;
    Scalar quadratic(std::span<const Scalar> dx) const;
    void add_diagonal(std::span<Scalar> diagonal) const;
    //! rhs_i += the residuals of the constrained faces of i, for each i in `vertices`.
    void add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                 std::span<Scalar> rhs) const;
    //! The same for one vertex, for the fused step. Each face's residual
    //! mu/n_f (x0_f - x_f) is computed by each of its vertices rather than cached per face:
    //! the same values without a 3 #F array (48 bytes per vertex on triangle meshes) and
    //! its extra pass over memory.
    void add_vertex_rhs(Index i, const Scalar* x, Scalar* r) const
    {
        // The sums live in locals, not in r: every store through r (a Scalar*) could
        // change x or mu_ for the compiler, which would then load them again.
        Scalar r0 = r[0], r1 = r[1], r2 = r[2];
        const Index* offsets = mesh_->face_offsets.data();
        const Index* corner_face = topology_->corner_face.data();
        // 1/n_f and mu/n_f for the last face size met (face_centroid's 1/n_f, so the
        // residuals are energy()'s): most meshes have one or two face sizes, so this saves two
        // divisions per face.
        Index last_n = 0;
        Scalar inv = 0, w = 0;
        for (const Index c : topology_->corners_of_vertex(i))
        {
            const Index f = corner_face[c];
            if (!constrained_[f])
                continue;
            const Index n = offsets[f + 1] - offsets[f];
            if (n != last_n)
            {
                last_n = n;
                inv = Scalar(1) / n;
                w = mu_ / n;
            }
            const Vec3 sum = face_corner_sum(*mesh_, x, f);
            const Scalar* t = &target_[3 * static_cast<size_t>(f)];
            r0 += w * (t[0] - sum[0] * inv);
            r1 += w * (t[1] - sum[1] * inv);
            r2 += w * (t[2] - sum[2] * inv);
        }
        r[0] = r0;
        r[1] = r1;
        r[2] = r2;
    }

private:
    const Mesh* mesh_;
    const Topology* topology_;
    Scalar mu_;
    CentroidDenominator denominator_;
    std::vector<Index> faces_;
    std::vector<char> constrained_; //!< #F
    std::vector<Scalar> target_;    //!< 3 #F
};

} // namespace meshfair
