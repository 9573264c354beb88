// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/energies/index_list.h"
#include "core/energies/position_term.h"
#include "core/geometry/face_geometry.h"
#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! Which Jacobi denominator the centroid term uses; see FaceCentroidTerm.
enum class CentroidDenominator
{
    Paper, //!< n_i + sum_{f in F_C(i)} mu_f/n_f, as printed (a majorizer; the default)
    Exact  //!< n_i + sum_{f in F_C(i)} mu_f/n_f^2, the exact one-variable minimizer
};

//! \brief Soft face-centroid constraints \cite taubin_2012 ("Face Centroid Constraints"),
//! with a weight per constrained face:
//!
//!     E_C(x) = sum_{f in F_C} mu_f |x_f - x0_f|^2,   x_f = (1/n_f) sum_{i in f} x_i
//!
//! mu_f = mu w_f >= 0, w_f = weights[k] for the k-th listed face (all 1 without weights:
//! the paper's single mu). Gradient: dE_C/dx_i = 2 sum_{f in F_C(i)} (mu_f/n_f)(x_f - x0_f).
//! Right-hand side sum_f (mu_f/n_f)(x0_f - x_f) as printed. Minimizing E exactly in x_i
//! alone gives the diagonal contribution sum_f mu_f/n_f^2; the paper prints
//! sum_f mu_f/n_f, which is larger. With the printed one the simultaneous (Jacobi) step
//! decreases E_L + E_C for every lambda in (0, 1) on any mesh, because each face's block
//! mu_f c c^T is bounded by diag(mu_f/n_f) (docs/math.md); with the exact one that holds
//! only for lambda < 2 / max(2, max n_f): always for triangles at 0.5, never guaranteed
//! beyond quads. Both are offered; Paper is the default.
class FaceCentroidTerm final : public PositionTerm
{
public:
    //! \pre faces distinct and < #F; targets hold 3 values per listed face; weights empty
    //! or one per listed face, each finite and >= 0 (as mu).
    FaceCentroidTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces,
                     Scalar mu, std::span<const Scalar> targets, CentroidDenominator denominator,
                     std::span<const Scalar> weights = {});
    //! The same with every target at the origin until set_targets or
    //! set_targets_to_centroids.
    FaceCentroidTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces,
                     Scalar mu, CentroidDenominator denominator,
                     std::span<const Scalar> weights = {});

    void set_targets(std::span<const Scalar> targets);
    //! Targets at the listed faces' centroids for positions `x` (3 #V): no gathered copy.
    void set_targets_to_centroids(std::span<const Scalar> x);
    //! Targets at the listed faces' centroids for positions `x` (3 #V), computed from `x`
    //! when needed (the same bits as set_targets_to_centroids) instead of stored: 48 bytes
    //! a vertex saved on triangle meshes, for reading the face's corners in `x` once more
    //! per step. \pre x stays alive and unchanged until the next set_targets or
    //! set_targets_to_centroids or the term's end.
    void use_centroids_of(std::span<const Scalar> x);
    const IndexList& faces() const { return faces_; }
    bool constrains(Index f) const { return constrained_[f] != 0; }
    //! mu_f of a constrained face.
    Scalar face_weight(Index f) const { return face_weight_.empty() ? mu_ : face_weight_[f]; }

    EnergyTerm kind() const override { return EnergyTerm::Centroid; }
    Scalar energy(std::span<const Scalar> x) const override;
    //! Adds each constrained face's mu_f |x_f - x0_f|^2 to per_vertex (#V), 1/n_f to each corner.
    void add_vertex_energy(std::span<const Scalar> x, std::span<Scalar> per_vertex) const override;
    //! The constrained faces without a free corner.
    Scalar held_energy(std::span<const Scalar> x, std::span<const char> is_free) const override;
    Scalar quadratic(std::span<const Scalar> dx) const override;
    void add_diagonal(std::span<Scalar> diagonal) const override;
    //! Column i of the exact half Hessian: mu_f / n_f^2 between i and every vertex of each
    //! constrained face of i (each corner counted: a vertex twice in a face, twice). Not
    //! the Jacobi diagonal of the Paper denominator, which majorizes it: the direct method
    //! solves for the minimizer itself.
    void add_hessian_column(Index i, HessianColumn& column) const override
    {
        for (const Index c : topology_->corners_of_vertex(i))
        {
            const Index f = topology_->face_of_corner(c);
            if (!constrained_[f])
                continue;
            const auto n = static_cast<Scalar>(mesh_->face_size(f));
            const Scalar a = face_weight(f) / (n * n);
            for (const Index k : mesh_->face(f))
                column.add(k, a);
        }
    }
    //! rhs_i += the residuals of the constrained faces of i, for each i in `vertices`.
    void add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                 std::span<Scalar> rhs) const override;
    //! The same for one vertex (the general step).
    void add_vertex_rhs(Index i, const Scalar* x, Scalar* r) const
    {
        for (const Index c : topology_->corners_of_vertex(i))
        {
            const Index f = topology_->face_of_corner(c);
            if (!constrained_[f])
                continue;
            Scalar residual[3];
            face_residual(x, f, residual);
            for (int a = 0; a < 3; ++a)
                r[a] += residual[a];
        }
    }
    //! Face f's residual mu_f/n_f (x0_f - x_f): its part of r_i for each of its vertices i.
    void face_residual(const Scalar* x, Index f, Scalar* out) const
    {
        const Index n = mesh_->face_size(f);
        // face_centroid's 1/n_f, so that the residuals are energy()'s.
        const Vec3 sum = face_corner_sum(*mesh_, x, f);
        if (centroid_source_.empty())
            residual_of<false>(sum, f, Scalar(1) / n, face_weight(f) / n, out);
        else
            residual_of<true>(sum, f, Scalar(1) / n, face_weight(f) / n, out);
    }
    //! face_residual of each face of faces[begin .. end) (face k itself when faces is
    //! nullptr) into residual[3 f ..] (3 #F; other
    //! faces' values are left as they are): the fused step's pass over the faces, so that
    //! each residual is computed once per step, not once per corner. Returns those faces'
    //! part of the energy, sum mu_f |x_f - x0_f|^2, which the same pass computes.
    Scalar face_residuals(const Scalar* x, const Index* faces, Index begin, Index end,
                          Scalar* residual) const;
    //! face_residuals, calling also(f) after each face's residual: another term's pass
    //! over the same faces (the normal term's sigma_f), sharing the walk over them and
    //! their corners' positions.
    template <typename Also>
    Scalar face_residuals(const Scalar* x, const Index* faces, Index begin, Index end,
                          Scalar* residual, Also&& also) const
    {
        return centroid_source_.empty()
                   ? face_residuals_from<false>(x, faces, begin, end, residual, also)
                   : face_residuals_from<true>(x, faces, begin, end, residual, also);
    }
    //! One byte per face, nonzero where constrained; nullptr when every face is.
    const char* flags() const { return all_faces_ ? nullptr : constrained_.data(); }

private:
    //! Targets of their own (3 #F), stored from here on: before set_targets writes them.
    void store_targets();
    //! |x_f - x0_f|^2: face f's centroid at x from its target.
    Scalar squared_residual(std::span<const Scalar> x, Index f) const;
    template <bool FromSource, typename Also>
    Scalar face_residuals_from(const Scalar* x, const Index* faces, Index begin, Index end,
                               Scalar* residual, Also& also) const
    {
        const bool weighted = !face_weight_.empty();
        if (walk_.triangles())
            return weighted ? residuals_over<FromSource, true, true>(x, faces, begin, end, residual,
                                                                     also)
                            : residuals_over<FromSource, true, false>(x, faces, begin, end,
                                                                      residual, also);
        return weighted
                   ? residuals_over<FromSource, false, true>(x, faces, begin, end, residual, also)
                   : residuals_over<FromSource, false, false>(x, faces, begin, end, residual, also);
    }
    //! face_residuals_from, knowing whether every face is a triangle (Triangles: three
    //! corners at 3 f, a loop the compiler unrolls; the same sums) and whether the faces
    //! have weights of their own.
    template <bool FromSource, bool Triangles, bool Weighted, typename Also>
    Scalar residuals_over(const Scalar* x, const Index* faces, Index begin, Index end,
                          Scalar* residual, Also& also) const
    {
        // 1/n_f (and mu/n_f with one weight) for the last face size met: most meshes have
        // one or two sizes, so this saves divisions per face (face_residual's values).
        Index last_n = 0;
        Scalar inv = 0, w = 0, energy = 0;
        const Scalar* face_weight = face_weight_.data();
        for (Index k = begin; k < end; ++k)
        {
            const Index f = faces != nullptr ? faces[k] : k;
            const Index n = Triangles ? 3 : mesh_->face_size(f);
            if (n != last_n)
            {
                last_n = n;
                inv = Scalar(1) / n;
                w = mu_ / n;
            }
            Scalar* out = residual + 3 * static_cast<std::ptrdiff_t>(f);
            const Vec3 sum = corner_sum<Triangles>(x, f);
            if constexpr (Weighted) // mu_f/n_f per face, as face_residual computes it
                energy += face_weight[f] *
                          residual_of<FromSource, Triangles>(sum, f, inv, face_weight[f] / n, out);
            else
                energy += residual_of<FromSource, Triangles>(sum, f, inv, w, out);
            also(f);
        }
        // One weight: mu times the sum, as energy() computes it.
        return Weighted ? energy : mu_ * energy;
    }
    //! face_corner_sum of face f; with Triangles, of the three corners at 3 f (the same sum).
    template <bool Triangles>
    [[gnu::always_inline]] Vec3 corner_sum(const Scalar* x, Index f) const
    {
        if constexpr (Triangles)
        {
            const Index* corners = mesh_->face_vertices.data() + 3 * static_cast<std::ptrdiff_t>(f);
            Vec3 c{0, 0, 0};
            for (int k = 0; k < 3; ++k)
                for (int a = 0; a < 3; ++a)
                    c[a] += x[3 * static_cast<std::ptrdiff_t>(corners[k]) + a];
            return c;
        }
        else
            return face_corner_sum(*mesh_, x, f);
    }
    //! x0_f: stored, or the centroid of f in centroid_source_ (face_centroid's expression,
    //! with inv = 1/n_f).
    template <bool FromSource, bool Triangles = false>
    Vec3 target_of(Index f, Scalar inv) const
    {
        if constexpr (FromSource)
        {
            Vec3 t = corner_sum<Triangles>(centroid_source_.data(), f);
            for (int a = 0; a < 3; ++a)
                t[a] *= inv;
            return t;
        }
        else
        {
            const Scalar* t = &target_[3 * static_cast<size_t>(f)];
            return {t[0], t[1], t[2]};
        }
    }
    Vec3 target(Index f) const
    {
        const Scalar inv = Scalar(1) / mesh_->face_size(f);
        return centroid_source_.empty() ? target_of<false>(f, inv) : target_of<true>(f, inv);
    }
    //! out = w (x0_f - sum inv), sum being the sum of f's corners; returns |x0_f - sum inv|^2.
    template <bool FromSource, bool Triangles = false>
    Scalar residual_of(const Vec3& sum, Index f, Scalar inv, Scalar w, Scalar* out) const
    {
        const Vec3 t = target_of<FromSource, Triangles>(f, inv);
        Scalar squared = 0;
        for (int a = 0; a < 3; ++a)
        {
            const Scalar d = t[a] - sum[a] * inv;
            out[a] = w * d;
            squared += d * d;
        }
        return squared;
    }

    const Mesh* mesh_;
    const Topology* topology_;
    Scalar mu_;
    CentroidDenominator denominator_;
    IndexList faces_;                         //!< no list stored when every face, in order
    std::vector<char> constrained_;           //!< #F
    std::vector<Scalar> target_;              //!< 3 #F, or empty while centroid_source_ is used
    std::span<const Scalar> centroid_source_; //!< 3 #V (use_centroids_of), or empty
    std::vector<Scalar> face_weight_;         //!< #F: mu_f = mu w_f; empty without weights
    CornerWalk walk_;
    bool all_faces_; //!< every face constrained: the sweep tests no flag
};

} // namespace meshfair
