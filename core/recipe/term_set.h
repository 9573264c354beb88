// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/energies/bending_term.h"
#include "core/energies/bilateral_face_weights.h"
#include "core/energies/edge_term.h"
#include "core/energies/face_centroid_term.h"
#include "core/energies/face_normal_term.h"
#include "core/energies/joint_term.h"
#include "core/energies/normal_smoothing_term.h"
#include "core/energies/position_term.h"
#include "core/energies/soft_vertex_term.h"
#include "core/energies/volume_constraint.h"
#include "core/geometry/noise_estimate.h"
#include "core/recipe/recipe.h"
#include "core/solver/free_system.h"
#include "core/solver/sparse_cholesky.h"

namespace meshfair {

//! \brief The parts of a Topology a Session with `recipe` reads: V(i) always, the corners
//! for the face terms, the dual graph for normal smoothing and joint mode.
TopologyParts required_topology(const Recipe& recipe);

//! The vertices no step moves, as #V flags.
struct FixedVertices
{
    std::vector<char> fixed; //!< hard, or outside the region (when there is one)
    std::vector<char> hard;  //!< in the hard set (pins)
};
//! \pre check_recipe(recipe, mesh).
FixedVertices fixed_vertices(const Recipe& recipe, const Mesh& mesh);

//! \brief The recipe's energy as its terms \cite taubin_2012: every term the recipe has,
//! built once per recipe, and the position terms behind one interface (PositionTerm), in
//! the order every sum over them takes: edge, bending, soft, centroid, normal.
//!
//! Besides the position terms it holds what acts on them: the face normals u the normal
//! term reads (smoothed first when the recipe says "smoothed": the paper's two stages),
//! the normal smoothing and joint terms over u, the bilateral weights, the falloff's
//! anchors (merged into the soft term, their targets following the pins) and the volume
//! constraint. A new position term is its file, one line in the constructor that
//! registers it, and its recipe section (core/recipe/recipe.h, energy_terms.cpp).
class TermSet
{
public:
    //! \pre check_recipe(recipe, mesh); the recipe, mesh and topology outlive the set.
    //! `fixed` and `is_hard` hold #V flags (fixed_vertices); hard_targets holds 3 per hard
    //! vertex, or nothing (the pins at their positions). `centre`: the point the normal
    //! term's per-face shares are taken about (FaceNormalTerm::face_share). Targets and
    //! normals the recipe leaves out are taken from mesh.positions.
    //! \throw SolverError when the topology is another mesh's or lacks
    //! required_topology(recipe).
    TermSet(const Mesh& mesh, const Topology& topology, const Recipe& recipe,
            const std::vector<char>& fixed, const std::vector<char>& is_hard,
            std::span<const Index> hard, std::span<const Scalar> hard_targets, const Vec3& centre);
    // The terms point at one another and at the set's arrays: not copied, not moved.
    TermSet(const TermSet&) = delete;
    TermSet& operator=(const TermSet&) = delete;

    //! The position terms, in the order of every sum over them.
    std::span<PositionTerm* const> position_terms() const { return position_terms_; }
    const EdgeTerm& edge() const { return edge_; }
    const BendingTerm* bending() const { return opt(bending_); }
    const SoftVertexTerm* soft() const { return opt(soft_); }
    const FaceCentroidTerm* centroid() const { return opt(centroid_); }
    const FaceNormalTerm* normal() const { return opt(normal_); }
    const JointTerm* joint() const { return opt(joint_); }
    VolumeConstraint* volume() { return volume_ ? &*volume_ : nullptr; }
    const VolumeConstraint* volume() const { return opt(volume_); }
    //! The face normals u (3 #F) the normal term reads; empty without it.
    std::span<const Scalar> normals() const { return normals_; }
    //! E_U before and after each normal-smoothing iteration (Session::normal_smoothing_trace).
    const std::vector<Scalar>& smoothing_trace() const { return smoothing_trace_; }
    //! The noise estimated for "iterations": "auto" (Session::noise_estimate).
    const std::optional<NoiseEstimate>& noise_estimate() const { return noise_; }
    //! The normal-smoothing iterations taken (the recipe's, or those from the noise).
    int smoothing_iterations() const { return smoothing_iterations_; }
    //! What the terms do besides the recipe's letter (the volume's, the falloff's notes).
    const std::vector<std::string>& notes() const { return notes_; }

    //! The free vertices, ascending: the bending term precomputes what its right-hand
    //! side reads.
    void set_free(std::span<const Index> free);
    //! Every term's energy at x, with joint mode's energies of the normals.
    TermEnergies energy(std::span<const Scalar> x) const;
    //! Each vertex's share of one term's energy at x, or of every position term's (Total).
    void vertex_energy(std::span<const Scalar> x, EnergyTerm term,
                       std::span<Scalar> per_vertex) const;
    //! Each position term's held_energy (PositionTerm::held_energy); the normals' terms of
    //! joint mode are never held.
    TermEnergies held_energy(std::span<const Scalar> x, std::span<const char> is_free) const;
    void add_diagonal(std::span<Scalar> diagonal) const;
    //! rhs_i += r_i = -1/2 dE/dx_i for every i in `free` (the vertices given to set_free).
    void add_rhs(std::span<const Scalar> x, std::span<const Index> free,
                 std::span<Scalar> rhs) const;
    void add_hessian_column(Index i, HessianColumn& column) const;
    //! \brief shift I + A_ff, the half Hessian over the free vertices (ascending): with
    //! blocks, 3 unknowns per vertex (the normal term couples the coordinates), else one,
    //! the same matrix for x, y and z (assemble_free_hessian).
    SymmetricMatrix free_hessian(std::span<const Index> free, bool blocks, Scalar shift) const;
    //! \brief The system of the direct, "cg" and implicit methods, ready to solve: A_ff
    //! (plus I / t for an implicit step of time t) factored, or prepared for conjugate
    //! gradients (FreeSystemSolver). Notes why conjugate gradients solve in place of a
    //! factor, when they do.
    //! \throw RecipeError when A_ff has no inverse: a free part that nothing holds (named as
    //! unheld_part names it) or weights too far apart for double precision.
    //! `analysed`: an earlier system's factorization, whose analysis is kept when this
    //! system has its pattern (FreeSystemSolver).
    std::unique_ptr<FreeSystemSolver> factor(std::span<const Index> free,
                                             std::span<const Index> file_vertex,
                                             std::vector<std::string>& notes,
                                             std::unique_ptr<SparseCholesky> analysed) const;
    //! dx^T A dx over the position terms (the exact line search).
    Scalar quadratic(std::span<const Scalar> dx) const;
    //! block_i += the normal term's 3x3 Jacobi block, for each i in `vertices`.
    void add_blocks(std::span<const Index> vertices, std::span<Scalar> block) const;

    //! The pins moved to hard_targets (3 per hard vertex): the falloff's anchors follow.
    void move_pins(std::span<const Scalar> hard_targets);
    //! \throw InvalidInputError unless 3 values per soft vertex.
    void set_soft_targets(std::span<const Scalar> targets);
    //! \throw InvalidInputError unless 3 values per constrained face.
    void set_centroid_targets(std::span<const Scalar> targets);
    //! Joint mode's update of the normals from positions x, with step lambda (<= 1),
    //! preceded every few steps by a new stage of the bilateral weights.
    void update_normals(std::span<const Scalar> x, Scalar lambda);

    //! \brief The first free part (connected through edges) that nothing holds: no fixed
    //! vertex next to it, no anchor, no constrained face; named by its size and its lowest
    //! vertex in the file's numbering (file_vertex; empty: the mesh's). nullopt when every
    //! part is held. See Session::unheld_part.
    std::optional<std::string> unheld_part(std::span<const Index> free,
                                           std::span<const Index> file_vertex) const;

private:
    template <typename T>
    static const T* opt(const std::optional<T>& t)
    {
        return t ? &*t : nullptr;
    }
    void build_soft(const std::vector<char>& is_hard);
    //! The soft term from the soft section's anchors and the falloff's, merged per vertex.
    void build_falloff_anchors(const std::vector<char>& fixed, const std::vector<char>& is_hard,
                               std::span<const Index> hard);
    //! The merged soft targets for the pins' targets (the falloff moves with the pins).
    void update_falloff_targets(std::span<const Scalar> hard_targets);
    //! The normals, their smoothing (the first stage of "smoothed") and joint mode.
    void build_normal_terms(const Vec3& centre);

    const Mesh* mesh_;
    const Topology* topology_;
    const Recipe* recipe_;
    //! 3 #V: the initial positions, when soft or centroid targets are at them (the terms
    //! view them here); declared before the terms.
    std::vector<Scalar> initial_;
    EdgeTerm edge_;
    std::optional<BendingTerm> bending_;
    std::optional<SoftVertexTerm> soft_;
    std::optional<FaceCentroidTerm> centroid_;
    std::vector<Scalar> normals_; //!< 3 #F, viewed by the normal term
    std::optional<FaceNormalTerm> normal_;
    std::optional<NormalSmoothingTerm> smoothing_;
    std::optional<BilateralFaceWeights> bilateral_; //!< the smoothing term's weights, if any
    std::optional<NoiseEstimate> noise_;            //!< with adaptive iterations
    int smoothing_iterations_ = 0;
    std::optional<JointTerm> joint_;
    int joint_steps_ = 0; //!< joint updates so far (for reweighting)
    std::optional<VolumeConstraint> volume_;
    std::vector<PositionTerm*> position_terms_;
    std::vector<std::string> notes_;
    std::vector<Scalar> smoothing_trace_;
    std::vector<Scalar> scratch_u_; //!< 3 #F for normal smoothing and joint mode, else empty
    //! Falloff, per soft vertex: its nearest pin (index into the hard set) or kInvalidIndex,
    //! its target with the pins unmoved (3 each) and the share of the pin's displacement
    //! it follows. Empty without falloff; falloff_pin_ is empty when no pin moves a target.
    std::vector<Index> falloff_pin_;
    std::vector<Scalar> falloff_base_, falloff_share_;
    std::vector<Index> hard_; //!< the pins, with falloff (their rest positions move targets)
};

} // namespace meshfair
