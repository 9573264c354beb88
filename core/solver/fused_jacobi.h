// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/energies/edge_term.h"
#include "core/energies/face_centroid_term.h"
#include "core/energies/face_normal_term.h"
#include "core/energies/position_term.h"
#include "core/energies/soft_vertex_term.h"
#include "core/solver/jacobi_system.h"

namespace meshfair {

//! The terms a fused step reads, by their own types: the sweep inlines each vertex's part.
struct FusedTerms
{
    const EdgeTerm* edge = nullptr; //!< the paper's, of weight 1
    const SoftVertexTerm* soft = nullptr;
    const FaceCentroidTerm* centroid = nullptr;
    const FaceNormalTerm* normal = nullptr;
    std::span<const Scalar> normals; //!< 3 #F with the normal term, held fixed
};

//! \brief The generalized Jacobi step \cite taubin_2012 of the paper's terms as one sweep
//! over the free vertices: each vertex adds every term's part of r_i (the terms'
//! add_vertex_rhs, in the order TermSet sums them), solves its 3x3 or scalar system and
//! writes y_i = x_i + step dx_i. The same operations as a step through the terms'
//! whole-mesh add_rhs without its right-hand-side and displacement arrays and their
//! passes over memory; one instance per combination of terms, so that the sweep tests
//! nothing per vertex (the plain Laplacian step is a bare gather loop).
//!
//! With centroid constraints a pass over the constrained faces first computes each face's
//! residual once (FaceCentroidTerm::face_residuals), which the face's corners then add
//! (add_corner_shares: the same bits as add_vertex_rhs). With normal_shares, the same pass
//! adds the normal term's share of each face (FaceNormalTerm::face_share), and the solve
//! takes the rest of its part (solve_less_block): the corners read one 3-vector per face
//! instead of the face's normal and their two neighbours, the same result to rounding.
//!
//! The step can also give E(x), the energy of the positions it starts from: each free
//! vertex adds its parts while it computes its step (-(x_i - c)^T r_i for the edge term,
//! EdgeTerm::vertex_part; mu_i |x_i - t_i|^2 for its anchor; the face-normal pairs that
//! start at it); the centroid faces' energies (and with normal_shares the normal term's,
//! by faces) come from the face pass. The fixed vertices' parts are summed once per set of
//! positions and targets, except those of fixed vertices next to a free one, summed every
//! step. The sums run in blocks that depend on the counts only: the same energy for any
//! thread count.
class FusedJacobi
{
public:
    //! \pre the terms, the free vertices (ascending), `system` (its inverses or diagonal,
    //! read at each step) and the mesh outlive the object; `fixed` holds #V flags (not
    //! free); `centre` is the point of the vertex parts and the normal term's shares
    //! (its FaceNormalTerm's centre). normal_shares needs a normal term on triangles.
    FusedJacobi(const Mesh& mesh, const Topology& topology, FusedTerms terms,
                std::span<const Index> free, const std::vector<char>& fixed,
                const JacobiSystem& system, bool normal_shares, const Vec3& centre);
    // The face shares' buffer is its own, and the passes point into it.
    FusedJacobi(const FusedJacobi&) = delete;
    FusedJacobi& operator=(const FusedJacobi&) = delete;

    //! One step from x into y (which must not overlap; y is written at free vertices only).
    //! With energy, returns E(x); otherwise zeros. With energy and `gradient`, also sets
    //! *gradient to |r(x)| over the free vertices (each vertex's A_i dx_i: its r_i, whole
    //! also where the normal term's shares left part of it to the solve), summed in the
    //! energy's blocks: the same for any thread count.
    TermEnergies step(std::span<const Scalar> x, std::span<Scalar> y, bool energy, Scalar step,
                      Scalar* gradient = nullptr);
    //! The fixed vertices' constant part of the energy is summed again at the next step
    //! with energy: after new positions or targets.
    void forget_fixed_energy() { fixed_constant_valid_ = false; }

private:
    //! What a sweep sums: the energy's parts and |r|^2.
    struct Sums
    {
        TermEnergies energy;
        Scalar gradient_squared = 0;
        Sums& operator+=(const Sums& o)
        {
            energy += o.energy;
            gradient_squared += o.gradient_squared;
            return *this;
        }
    };
    //! The faces of a per-face pass (faces nullptr: the k-th face is k).
    struct FacePass
    {
        const Index* faces = nullptr;
        Index count = 0;
    };
    //! A term's faces with a free vertex: `active`, or when that is empty the term's own
    //! `listed` faces (the constructor leaves it empty when they are the same list).
    static FacePass face_pass(const std::vector<Index>& active, const IndexList& listed);
    FacePass centroid_pass() const { return face_pass(centroid_active_, terms_.centroid->faces()); }
    FacePass normal_pass() const { return face_pass(normal_active_, terms_.normal->faces()); }
    //! The step for one combination of active terms. With Energy, returns the parts of
    //! E(x) that the free vertices and the centroid faces with a free corner own.
    template <bool Soft, bool Centroid, bool Normal, bool Energy>
    Sums sweep(const Scalar* x, Scalar* y, Scalar step, bool gradient);
    //! The sweep over free[begin .. end) (AllFree: every vertex free, i = k; NormalWeighted:
    //! the normal term's faces have weights of their own; gradient: |r_i|^2 summed too).
    template <bool Soft, bool Centroid, bool Normal, bool NormalWeighted, bool AllFree, bool Energy>
    Sums range(const Scalar* x, Scalar* y, Scalar step, bool gradient, Index begin,
               Index end) const;
    //! The parts of E(x) of `vertices` (fixed ones: the sweep leaves them out), in blocks.
    TermEnergies vertex_parts(const Scalar* x, std::span<const Index> vertices) const;
    //! e += vertex i's parts at x.
    void add_vertex_parts(const Scalar* x, Index i, TermEnergies& e) const;
    //! The parts of the fixed vertices and of the constrained faces without a free vertex:
    //! the constant part once per set of positions, the border's every call.
    TermEnergies fixed_energy(const Scalar* x);

    const Mesh* mesh_;
    const Topology* topology_;
    FusedTerms terms_;
    std::span<const Index> free_;
    const JacobiSystem* system_;
    Index vertex_count_;
    bool normal_shares_;
    //! c of the vertex parts -(x_i - c)^T r_i (the bounding box's middle)
    Vec3 centre_;
    //! 3 #F: this step's per-face shares of the right-hand side: the centroid residual,
    //! plus the normal term's share with normal_shares_; else empty
    std::vector<Scalar> face_share_;
    //! Which faces' shares a corner adds (either term constrains them); nullptr: every
    //! face. Points into a term or share_flag_own_.
    const char* share_flag_ = nullptr;
    std::vector<char> share_flag_own_; //!< #F when both terms list faces, else empty
    //! The constrained faces with a free vertex, ascending; empty when that is every
    //! constrained face and the term lists them ascending (the pass reads its list)
    std::vector<Index> centroid_active_;
    //! The normal term's faces with a free vertex, ascending, likewise
    std::vector<Index> normal_active_;
    //! The centroid and normal passes walk the same faces: the sweep makes them one
    bool shared_face_pass_ = false;
    //! The normal term's faces without a free vertex, ascending, when normal_shares_: the
    //! energy then counts the normal term by faces, not by vertices
    std::vector<Index> normal_inactive_;
    //! The constrained faces without a free vertex, ascending (their energy is constant)
    std::vector<Index> centroid_inactive_;
    //! Fixed vertices with a free neighbour, ascending: their parts of the energy change
    //! with the free positions
    std::vector<Index> energy_border_;
    //! The parts of the other fixed vertices and of centroid_inactive_, while valid
    TermEnergies fixed_constant_;
    bool fixed_constant_valid_ = false;
};

} // namespace meshfair
