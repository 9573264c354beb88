// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/energies/index_list.h"
#include "core/energies/position_term.h"
#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief Face-normal constraints \cite taubin_2012 ("Face Normal Constraints"), with a
//! weight per constrained face:
//!
//!     E_N(x) = sum_{f in F_N} mu_f sum_{(i,j) in E(f)} (u_f^T (x_j - x_i))^2
//!
//! mu_f = mu w_f >= 0, w_f = weights[k] for the k-th listed face (all 1 without weights:
//! the paper's single mu); unit normals u (3 #F) held constant, so E_N is quadratic and
//! homogeneous in x. Every face-edge pair counts once per face. Gradient on x_i:
//! 2 sum_{f in F_N(i)} mu_f sum_{j in V(f,i)} u_f u_f^T (x_i - x_j), where V(f,i) are the two
//! vertices next to i along the boundary of f (not V(f) intersect V(i), which for polygons
//! with more than three sides may hold a third vertex). Generalized Jacobi: the 3x3 block
//! sum_f mu_f sum_{j in V(f,i)} u_f u_f^T = 2 sum_f mu_f u_f u_f^T is added to n_i I, and
//! sum_f mu_f u_f u_f^T sum_{j in V(f,i)} (x_j - x_i) to the right-hand side: the paper's
//! equation with its n_f n_f^t read as u_f u_f^t. n_i I + block is SPD whenever n_i > 0.
class FaceNormalTerm final : public PositionTerm
{
public:
    //! \pre faces distinct and < #F; weights empty or one per listed face, each finite and
    //! >= 0 (as mu).
    FaceNormalTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces, Scalar mu,
                   std::span<const Scalar> weights = {});
    //! The same, with face_share's point c given (the Session's, which it computed already);
    //! the constructor above takes the middle of the mesh's bounding box.
    FaceNormalTerm(const Mesh& mesh, const Topology& topology, std::vector<Index> faces, Scalar mu,
                   std::span<const Scalar> weights, const Vec3& centre);

    Scalar mu() const { return mu_; }
    //! mu_f of a constrained face.
    Scalar face_weight(Index f) const { return face_weight_.empty() ? mu_ : face_weight_[f]; }
    const IndexList& faces() const { return faces_; }
    bool constrains(Index f) const { return constrained_[f] != 0; }

    //! \brief The normals u (3 #F) the PositionTerm interface reads, viewed, not copied:
    //! a session's current normals, which joint mode and normal smoothing update in place.
    //! \pre they outlive the term's use through PositionTerm, or the next view_normals.
    void view_normals(std::span<const Scalar> normals) { normals_ = normals; }
    // PositionTerm, with the normals of view_normals. The term has no scalar diagonal:
    // its Jacobi part is the 3x3 block of add_block.
    EnergyTerm kind() const override { return EnergyTerm::Normal; }
    Scalar energy(std::span<const Scalar> x) const override { return energy(x, normals_); }
    void add_vertex_energy(std::span<const Scalar> x, std::span<Scalar> per_vertex) const override
    {
        add_vertex_energy(x, normals_, per_vertex);
    }
    //! The constrained faces without a free corner.
    Scalar held_energy(std::span<const Scalar> x, std::span<const char> is_free) const override;
    Scalar quadratic(std::span<const Scalar> dx) const override { return energy(dx, normals_); }
    void add_diagonal(std::span<Scalar>) const override {}
    void add_hessian_column(Index i, HessianColumn& column) const override
    {
        add_hessian_column(i, normals_, column);
    }
    void add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                 std::span<Scalar> rhs) const override
    {
        add_rhs(x, normals_, vertices, rhs);
    }

    Scalar energy(std::span<const Scalar> x, std::span<const Scalar> normals) const;
    //! Adds each face-edge pair's mu_f (u_f^T (x_j - x_i))^2 to per_vertex (#V), half to each
    //! end.
    void add_vertex_energy(std::span<const Scalar> x, std::span<const Scalar> normals,
                           std::span<Scalar> per_vertex) const;
    Scalar quadratic(std::span<const Scalar> dx, std::span<const Scalar> normals) const
    {
        return energy(dx, normals);
    }
    //! block_i += 2 sum_{f in F_N(i)} mu_f u_f u_f^T (xx xy xz yy yz zz) for each i in vertices.
    void add_block(std::span<const Scalar> normals, std::span<const Index> vertices,
                   std::span<Scalar> block) const;
    void add_rhs(std::span<const Scalar> x, std::span<const Scalar> normals,
                 std::span<const Index> vertices, std::span<Scalar> rhs) const;
    //! Column i of the half Hessian for the normals u: for each constrained face f of i and
    //! each of its pairs (i, j), j the corner before or after i, M_f = mu_f u_f u_f^T at i
    //! and -M_f at j (the Jacobi block of add_block is the sum of those at i).
    void add_hessian_column(Index i, std::span<const Scalar> normals, HessianColumn& column) const
    {
        for (const Index c : topology_->corners_of_vertex(i))
        {
            const Index f = walk_.face(c);
            if (!all_faces_ && !constrained_[f])
                continue;
            const auto [prev, next] = walk_.neighbors(c, f);
            const Scalar* u = &normals[3 * static_cast<std::ptrdiff_t>(f)];
            const Scalar w = face_weight(f);
            const Scalar m[6] = {w * u[0] * u[0], w * u[0] * u[1], w * u[0] * u[2],
                                 w * u[1] * u[1], w * u[1] * u[2], w * u[2] * u[2]};
            column.add_block(i, m, 2);
            column.add_block(prev, m, -1);
            column.add_block(next, m, -1);
        }
    }
    //! One vertex's part, for the fused step: r += sum_{f in F_N(i)} mu_f u_f u_f^T
    //! ((x_prev - x_i) + (x_next - x_i)), with prev and next i's neighbours in face f.
    void add_vertex_rhs(Index i, const Scalar* x, const Scalar* normals, Scalar* r) const
    {
        if (has_weights())
            add_vertex_rhs<true>(i, x, normals, r);
        else
            add_vertex_rhs<false>(i, x, normals, r);
    }
    //! True when the faces have weights of their own (not all mu).
    bool has_weights() const { return !face_weight_.empty(); }
    //! True when every face of the mesh is a triangle: the fused step then takes the
    //! term's corner parts from face_share.
    bool triangles() const { return walk_.triangles(); }
    //! The point c of face_share: a point near the mesh (the middle of its bounding box), so
    //! that its sums stay the size of the mesh, not of its coordinates.
    const Vec3& centre() const { return centre_; }
    //! \brief Face f's share of its corners' right-hand sides, for the fused step on a mesh
    //! of triangles. For a triangle (a, b, d) and its corner i, (x_prev - x_i) +
    //! (x_next - x_i) = (x_a + x_b + x_d) - 3 x_i, so i's part (add_vertex_rhs) is
    //!
    //!     mu_f u_f u_f^T ((x_prev - x_i) + (x_next - x_i)) = g_f - (3/2) B_f (x_i - c),
    //!     g_f = mu_f sigma_f u_f,  sigma_f = u_f^T ((x_a - c) + (x_b - c) + (x_d - c)),
    //!
    //! B_f = 2 mu_f u_f u_f^T being the face's part of i's 3x3 block (add_block). The
    //! corners share g_f, computed once per face and step; the sum of the B_f is the block,
    //! which the Jacobi solve already holds (solve_less_block). Writes g_f to
    //! share[3 f ..], or adds it when add. With Energy, returns the face's sum of
    //! (u_f^T (x_j - x_i))^2 over its pairs, times mu_f with weights (energy_of_sum makes
    //! a sum of these an energy); else 0.
    //! \pre triangles().
    template <bool Energy>
    [[gnu::always_inline]] Scalar face_share(const Scalar* x, const Scalar* normals, Index f,
                                             Scalar* share, bool add) const
    {
        const std::ptrdiff_t at = 3 * static_cast<std::ptrdiff_t>(f);
        const Index* corners = mesh_->face_vertices.data() + at;
        const Scalar* u = normals + at;
        const Scalar* a = x + 3 * static_cast<std::ptrdiff_t>(corners[0]);
        const Scalar* b = x + 3 * static_cast<std::ptrdiff_t>(corners[1]);
        const Scalar* d = x + 3 * static_cast<std::ptrdiff_t>(corners[2]);
        const Scalar* c = centre_.data();
        const Scalar sigma = u[0] * ((a[0] - c[0]) + (b[0] - c[0]) + (d[0] - c[0])) +
                             u[1] * ((a[1] - c[1]) + (b[1] - c[1]) + (d[1] - c[1])) +
                             u[2] * ((a[2] - c[2]) + (b[2] - c[2]) + (d[2] - c[2]));
        const Scalar w = face_weight(f);
        Scalar s = 0;
        if constexpr (Energy) // before the stores, which could change x for the compiler
            s = pair_sum(u, x, std::span<const Index, 3>(corners, 3));
        for (int k = 0; k < 3; ++k)
            share[at + k] = (add ? share[at + k] : 0) + w * sigma * u[k];
        return face_weight_.empty() ? s : w * s;
    }
    //! face_share of faces[begin .. end) (faces nullptr: the k-th face is k), adding to
    //! share on every face when add_all, else where add[f] != 0 (add nullptr: nowhere);
    //! returns their part of energy(x) with Energy, else 0.
    template <bool Energy>
    Scalar face_shares(const Scalar* x, const Scalar* normals, const Index* faces, Index begin,
                       Index end, Scalar* share, bool add_all, const char* add) const;
    //! One byte per face, nonzero where constrained; nullptr when every face is.
    const char* flags() const { return all_faces_ ? nullptr : constrained_.data(); }
    //! A sum of face_share's returns made an energy: times mu without weights (one weight,
    //! as energy() computes it).
    Scalar energy_of_sum(Scalar sum) const { return face_weight_.empty() ? mu_ * sum : sum; }
    //! The part of energy(x) of faces[begin .. end) (faces nullptr: the k-th face is k),
    //! each face's pairs as energy() sums them.
    Scalar face_energies(const Scalar* x, const Scalar* normals, const Index* faces, Index begin,
                         Index end) const;
    //! add_vertex_rhs with the weighting chosen by the caller (Weighted == has_weights()):
    //! the fused step tests it once per step, and without weights the corner loop is the
    //! single-mu one, unchanged. Always inlined: the fused sweeps call it from a dozen
    //! instances, and a call would pass r through memory for every vertex.
    //! With Energy, also *energy += vertex i's part of energy(x): the face-edge pairs that
    //! start at i (i and the next corner of each constrained face), each pair once. Summed
    //! directly, not by EdgeTerm::vertex_part's identity: E_N is often near 0 (normals met),
    //! where the identity's rounding, relative to |x - c| |r|, would swamp it.
    template <bool Weighted, bool Energy = false>
    [[gnu::always_inline]] void add_vertex_rhs(Index i, const Scalar* x, const Scalar* normals,
                                               Scalar* r, Scalar* energy = nullptr) const
    {
        // Locals, not r[] and mu_: a store through r could change x, the normals or mu_
        // for the compiler, which would then load them again for every corner.
        Scalar r0 = r[0], r1 = r[1], r2 = r[2], own = 0;
        const Scalar mu = mu_;
        const Scalar* face_weight = face_weight_.data();
        const Scalar xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
        const CornerWalk walk = walk_;
        const bool all_faces = all_faces_;
        for (const Index c : topology_->corners_of_vertex(i))
        {
            const Index f = walk.face(c);
            if (!all_faces && !constrained_[f])
                continue;
            const auto [prev, next] = walk.neighbors(c, f);
            const Scalar* u = &normals[3 * static_cast<std::ptrdiff_t>(f)];
            const Scalar* a = &x[3 * static_cast<std::ptrdiff_t>(prev)];
            const Scalar* b = &x[3 * static_cast<std::ptrdiff_t>(next)];
            const Scalar s = u[0] * ((a[0] - xi0) + (b[0] - xi0)) +
                             u[1] * ((a[1] - xi1) + (b[1] - xi1)) +
                             u[2] * ((a[2] - xi2) + (b[2] - xi2));
            const Scalar w = Weighted ? face_weight[f] : mu;
            r0 += w * s * u[0];
            r1 += w * s * u[1];
            r2 += w * s * u[2];
            if constexpr (Energy)
            {
                const Scalar t = u[0] * (b[0] - xi0) + u[1] * (b[1] - xi1) + u[2] * (b[2] - xi2);
                own += w * t * t;
            }
        }
        r[0] = r0;
        r[1] = r1;
        r[2] = r2;
        if constexpr (Energy)
            *energy += own;
    }
    //! Vertex i's part of energy(x): the pairs that start at i (see add_vertex_rhs).
    Scalar vertex_part(Index i, const Scalar* x, const Scalar* normals) const
    {
        Scalar r[3] = {0, 0, 0}, e = 0;
        if (has_weights())
            add_vertex_rhs<true, true>(i, x, normals, r, &e);
        else
            add_vertex_rhs<false, true>(i, x, normals, r, &e);
        return e;
    }
    //! M_f = sum_{(i,j) in E(f)} (x_j - x_i)(x_j - x_i)^T (xx xy xz yy yz zz), so that face
    //! f's part of E_N is mu_f u_f^T M_f u_f (used by the joint update of u).
    void edge_scatter(std::span<const Scalar> x, Index f, Scalar* M) const;

private:
    //! The sum over faces[begin .. end) (faces nullptr: the k-th face is k) of each face's
    //! pair_sum, times mu_f with weights: energy() and face_energies() before
    //! energy_of_sum.
    Scalar pair_sums(const Scalar* x, const Scalar* normals, const Index* faces, Index begin,
                     Index end) const;
    //! The sum over a face's pairs (x_k, x_k+1) of (u^T (x_k+1 - x_k))^2, in energy()'s order.
    template <typename Face>
    static Scalar pair_sum(const Scalar* u, const Scalar* x, const Face& face)
    {
        Scalar s = 0;
        for (size_t k = 0; k < face.size(); ++k)
        {
            const Scalar* p = &x[3 * static_cast<std::ptrdiff_t>(face[k])];
            const Scalar* q = &x[3 * static_cast<std::ptrdiff_t>(face[(k + 1) % face.size()])];
            const Scalar d = u[0] * (q[0] - p[0]) + u[1] * (q[1] - p[1]) + u[2] * (q[2] - p[2]);
            s += d * d;
        }
        return s;
    }

    const Mesh* mesh_;
    const Topology* topology_;
    Scalar mu_;
    IndexList faces_;                 //!< no list stored when every face, in order
    std::vector<char> constrained_;   //!< #F
    std::vector<Scalar> face_weight_; //!< #F: mu_f = mu w_f; empty without weights
    CornerWalk walk_;
    Vec3 centre_;                     //!< face_share's c
    std::span<const Scalar> normals_; //!< view_normals's
    bool all_faces_;                  //!< every face constrained: the sweep tests no flag
};

} // namespace meshfair
