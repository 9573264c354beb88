// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/energies/position_term.h"
#include "core/recipe/pin_response.h"
#include "core/recipe/recipe.h"
#include "core/recipe/run.h"
#include "core/recipe/term_set.h"
#include "core/solver/flip_guard.h"
#include "core/solver/free_system.h"
#include "core/solver/fused_jacobi.h"
#include "core/solver/jacobi_system.h"
#include "core/solver/volume_minimizer.h"

namespace meshfair {

//! Why Taubin's steps have no minimizer to converge to (Session::notes, the editor).
inline constexpr const char* kTaubinHasNoMinimizer =
    "Taubin's lambda|mu steps keep the shape's low frequencies (they do not shrink it) "
    "instead of converging to the energy's minimizer: its gradient need not fall";

//! What one step did.
struct StepInfo
{
    Scalar lambda = 0; //!< step length used (the line search's choice when optimal)
    //! With Recipe::prevent_flips: the vertices whose steps FlipGuard shortened (one
    //! shortened again after the volume's correction counts again)
    Index shortened = 0;
    //! |r(x)| over the free vertices where the step started, r = -1/2 dE/dx
    //! (Session::Residual::gradient): the direct and implicit methods' and the general
    //! step's always, the fused step's with step(before, true); else -1.
    Scalar gradient = -1;
    //! Conjugate gradients: the iterations of the step's solve (summed over the coordinates
    //! when they are solved apart); 0 for the other methods.
    int inner_iterations = 0;
};

//! \brief All smoothing strategies of \cite taubin_2012 combined in one solver, shaped
//! like libigl's min_quad_with_fixed: the constructor precomputes everything that depends
//! on the topology, the constraint sets and their weights; step() then runs one step of
//! the recipe's method without allocating: a generalized Jacobi step in linear time (fused
//! into one sweep, FusedJacobi, where it can be), a line search's, Taubin's pair, or a
//! solve of the direct or implicit method with the factor kept (FreeSystemSolver).
//!
//! The energy is the recipe's TermSet: E = E_L + E_B + E_S + E_C + E_N (+ the normal terms
//! of joint mode) over the free vertices: those in the region (all when there is none)
//! that are not hard and have a non-zero Jacobi diagonal. Every other vertex is never
//! written.
//!
//! What invalidates the precomputation: another mesh connectivity, another recipe (sets,
//! weights, normal sources, method) -> construct again or set_recipe(). Moved hard, soft
//! or centroid targets only change the right-hand side: set_*_targets() does not
//! precompute again. Positions passed to step() must have 3 #V entries.
//! The mesh and topology must outlive the session; targets and normals that the recipe
//! leaves out are taken from mesh.positions at precomputation time.
class Session
{
public:
    //! \pre check_recipe(recipe, mesh) holds; topology is build_topology(mesh, parts) with
    //! at least required_topology(recipe) (else SolverError).
    //! \throw RecipeError if the recipe does not fit the mesh.
    //! `file_vertex`: the file's number of each vertex, for the messages that name one (a
    //! LocalityRun's order; empty: the mesh's own numbers); it must outlive the session.
    //! `analysed`: a factorization handed over by an earlier session of this mesh
    //! (take_factorization): when this recipe's system has its pattern (only weights
    //! differ), its analysis is kept and only the numeric factorization is done.
    Session(const Mesh& mesh, const Topology& topology, const Recipe& recipe,
            std::span<const Index> file_vertex = {},
            std::unique_ptr<SparseCholesky> analysed = nullptr);
    // The terms point at one another (joint mode, bilateral weights): not copied, not moved.
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    //! Replaces the recipe and precomputes again. The direct method's analysis is kept
    //! when the new system has the same pattern (a weight changed): factorization only.
    void set_recipe(const Recipe& recipe);
    const Recipe& recipe() const { return recipe_; }

    //! Writes the hard vertices' targets (when the recipe gives any) into x; the paper
    //! moves constrained vertices first and then keeps them fixed.
    void apply_hard_targets(std::span<Scalar> x) const;
    //! New targets, 3 per vertex of the hard set (in recipe order); right-hand side only.
    void set_hard_targets(std::span<const Scalar> targets);
    //! \brief A pin drag's move: set_hard_targets, and the kept positions' pins placed at
    //! the targets. The free vertices stay where they are, and with them the record that
    //! they are the direct method's minimizer for the pins before (follow_pins).
    void move_pins(std::span<const Scalar> targets);
    //! \brief The direct method's minimizer for the pins as they are, from the one a direct
    //! step left for earlier pins, without a solve: the minimizer is affine in the pins
    //! (PinResponses; the first move of a group of pins solves for its response, later
    //! ones are a pass over the free vertices). False, and nothing changed, when the
    //! session cannot: no minimizer on record (another method, conjugate gradients, a step
    //! the flip guard shortened, positions set since), the normal term's coupled
    //! coordinates, or a face the move would turn over; a step then solves.
    bool follow_pins();
    //! True when follow_pins may follow: a minimizer on record for other pins than these.
    bool can_follow_pins() const
    {
        return !minimizer_pins_.empty() && has_positions_ && !hard_targets_.empty() &&
               minimizer_pins_ != hard_targets_;
    }
    //! New soft targets, 3 per soft vertex (in soft_vertices() order).
    void set_soft_targets(std::span<const Scalar> targets)
    {
        terms_->set_soft_targets(targets);
        forget_fixed_energy();
        minimizer_pins_.clear();
    }
    //! New centroid targets, 3 per constrained face (in centroid_faces() order).
    void set_centroid_targets(std::span<const Scalar> targets)
    {
        terms_->set_centroid_targets(targets);
        forget_fixed_energy();
        minimizer_pins_.clear();
    }

    //! One step: assemble r, solve each free vertex's system, choose lambda, move.
    //! In joint mode the normals are updated in the same step, from the same old values.
    //! \throw SolverError when x does not hold 3 #V values.
    StepInfo step(std::span<Scalar> x);

    TermEnergies energy(std::span<const Scalar> x) const { return terms_->energy(x); }
    //! \brief Each vertex's share of a term's energy at x (per_vertex: #V values, set): the
    //! edge and normal terms give half of each edge's part to each end, the centroid term
    //! 1/n_f of a face's to each corner, so the shares sum to the term's energy(x). Total is
    //! the sum of the position terms (the normal-smoothing terms of joint mode have no
    //! vertex). Where constraints fight the smoothing, both shares are high.
    void vertex_energy(std::span<const Scalar> x, EnergyTerm term,
                       std::span<Scalar> per_vertex) const;
    //! \brief The part of each position term's energy at x that no step changes: its elements
    //! (edges, anchors, faces, umbrellas) without a free vertex. energy(x) minus it is the
    //! energy of what moves, which a run lowers (the editor's plot of a region); it stays
    //! the same while the fixed vertices do (a pin moved changes it).
    TermEnergies held_energy(std::span<const Scalar> x) const;
    //! The free vertices as #V flags (1: free), for per-vertex displays of what moves.
    std::vector<char> free_flags() const;

    //! \brief Positions kept by the session, for callers that step many times (run(),
    //! the editor): step() then works on them without copying, alternating two buffers
    //! when the step can be fused (FusedJacobi). Allocates; step() does not.
    //! \throw SolverError when x does not hold 3 #V values.
    void set_positions(std::span<const Scalar> x);
    //! set_positions without the copy: the session takes over x's buffer, so a caller
    //! that needs the positions only after the run (the CLI) holds them once, not twice.
    //! \throw SolverError when x does not hold 3 #V values.
    void adopt_positions(std::vector<Scalar>&& x);
    //! Hands the kept positions back; the session then has none until set_positions or
    //! adopt_positions.
    std::vector<Scalar> release_positions();
    //! True once set_positions or adopt_positions has given the session positions.
    bool has_positions() const { return has_positions_; }
    //! The kept positions (empty before set_positions).
    std::span<const Scalar> positions() const { return x_; }
    //! One step on the kept positions: the same bits as step(x), except with
    //! normal_shares(), where the two agree to rounding (tested).
    StepInfo step();
    //! \brief One step on the kept positions that also gives `before`, the energy of the
    //! positions the step starts from. When fuses_energy(), the step's own sweep computes
    //! it (FusedJacobi); otherwise energy() runs first. The same positions as step(); the
    //! energy agrees with energy() to rounding and is the same for any thread count.
    //! With `gradient`, StepInfo::gradient is |r| where the step starts (the fused sweep
    //! sums it; Taubin's fused pair takes a pass of its own) and revert_step() can undo
    //! the step whatever the method (the others keep a copy of the positions).
    StepInfo step(TermEnergies& before, bool gradient = false);
    //! True when step(before) finds the energy in the step's own sweep and revert_step()
    //! can undo a step: the fused Jacobi step (FusedJacobi). Taubin's method fuses its
    //! two steps but not the energy: the second starts where the first ends.
    bool fuses_energy() const { return fused() && recipe_.method != Method::Taubin; }
    //! \brief True when the fused step takes the normal term's corner parts from per-face
    //! shares (a normal term on a mesh of triangles: FaceNormalTerm::face_share): it
    //! then sums the terms' parts in another order than step(x) does, and its positions
    //! agree with step(x)'s to rounding (about 1e-16 of the mesh's size per step), not
    //! bit for bit.
    bool normal_shares() const { return normal_shares_; }
    //! \brief Puts back the kept positions of before the last step: for a run that learns
    //! from step(before, true) one step late that the positions the step started from had
    //! converged.
    //! \throw SolverError unless the last call was a step(before, true), a step(before)
    //! with fuses_energy(), or a fused Jacobi step() on the kept positions.
    void revert_step();
    //! The energy of the kept positions.
    TermEnergies energy() const { return energy(x_); }
    //! How far positions are from the minimizer, from one assembly of r = -1/2 dE/dx (the
    //! normals held) at the free vertices.
    struct Residual
    {
        //! |r(x)|, the Euclidean norm over the free vertices: 0 exactly at the minimizer.
        //! The direct method's stopping rule compares it with the input's. With the volume
        //! kept by the direct or CG method, r less its part along each component's volume
        //! gradient: 0 at the minimizer under the constraint.
        Scalar gradient = 0;
        //! The largest length of a free vertex's generalized Jacobi displacement A_i^-1 r_i:
        //! how far one more Jacobi step would move a vertex.
        Scalar jacobi_displacement = 0;
    };
    Residual residual(std::span<const Scalar> x);
    //! Residual::gradient alone: one assembly of r, no displacements.
    Scalar gradient(std::span<const Scalar> x);
    //! \brief Why the recipe's energy has no unique minimizer over the free vertices: the
    //! first free part (connected through edges) that nothing holds (no fixed vertex next
    //! to it, no anchor, no constrained face), named by its size and its lowest vertex in
    //! the file's numbering; nullopt when every part is held. The direct method refuses
    //! such a recipe; steps of it only shrink such a part, toward a point.
    std::optional<std::string> unheld_part() const
    {
        return terms_->unheld_part(free_, file_vertex_);
    }
    //! The direct method's factorization (nullptr for the other methods, and when conjugate
    //! gradients solve in its place).
    const SparseCholesky* factorization() const
    {
        return linear_ ? linear_->factorization() : nullptr;
    }
    //! Hands the factorization over to a session of another recipe of this mesh (its
    //! constructor's `analysed`); this session cannot step afterwards. nullptr without one.
    //! (A step then throws SolverError.)
    std::unique_ptr<SparseCholesky> take_factorization();
    //! True when the minimizer's steps are solved by conjugate gradients ("cg", or the
    //! direct method over its factor budget: notes() says why).
    bool conjugate_gradients() const { return linear_ && linear_->conjugate_gradients(); }
    //! \brief The minimizer's step solved by conjugate gradients over several calls (the
    //! editor's frames on a system it does not factor, FreeSystemSolver::begin_progressive):
    //! possible for the direct and CG methods without a factor nor the volume.
    bool can_solve_progressively() const
    {
        return linear_ && linear_->conjugate_gradients() && !minimizes_under_volume() &&
               solves_for_minimizer(recipe_.method);
    }
    //! Begins the step at the kept positions (the right-hand side there).
    //! \pre can_solve_progressively().
    void begin_progressive_solve();
    //! \brief At most `limit` more iterations a coordinate of the step begun; the kept
    //! positions become its start plus the solution so far (whose energy falls from call to
    //! call), through the flip guard, which shortens it toward the start (below the start's
    //! energy, but not always below the last call's). `finished`: the step is solved (the
    //! tolerance, or conjugate gradients' cap). StepInfo::gradient is the gradient where the step
    //! began, inner_iterations the iterations of this call.
    StepInfo advance_progressive_solve(int limit, bool& finished);
    //! A progressive step is begun and not finished, and the kept positions are its own
    //! (any other step, new positions or pins end it).
    bool progressive_solve_under_way() const { return !progressive_start_.empty(); }

    std::span<const Index> free_vertices() const { return free_; }
    //! Current face normals u (3 #F) used by the normal terms; empty when unused.
    std::span<const Scalar> normals() const { return terms_->normals(); }
    //! E_U before and after each normal-smoothing iteration (normals "smoothed"); with
    //! bilateral weights, the robust energy E_R + the soft part (BilateralFaceWeights).
    const std::vector<Scalar>& normal_smoothing_trace() const { return terms_->smoothing_trace(); }
    //! The noise found in the mesh when normal smoothing's iterations are "auto"
    //! (estimate_noise over the vertices of the normal term's faces, at the start).
    const std::optional<NoiseEstimate>& noise_estimate() const { return terms_->noise_estimate(); }
    //! The normal-smoothing iterations taken: the recipe's count, or those from the noise.
    int normal_smoothing_iterations() const { return terms_->smoothing_iterations(); }
    //! What the run does besides the recipe's letter, for reports: how open components'
    //! volumes are kept (or that they are not), a falloff with nothing to fade from.
    const std::vector<std::string>& notes() const { return notes_; }
    //! The volume constraint, when the recipe keeps volumes.
    const VolumeConstraint* volume() const { return terms_->volume(); }
    //! How many times the precomputation ran (1 after construction).
    int precompute_count() const { return precompute_count_; }

private:
    void precompute(std::unique_ptr<SparseCholesky> analysed);
    //! The Jacobi blocks of the normal term at the current normals, inverted.
    void invert_blocks();
    //! True when step() can be fused: the Jacobi method (or Taubin's, two Jacobi steps)
    //! with a fixed lambda and fixed normals (no line search, no joint mode), of the
    //! paper's terms (FusedJacobi; the bending term takes the general step).
    bool fused() const;
    //! The general step (separate right-hand side, displacement, line search, joint
    //! update), in place on x.
    StepInfo general_step(std::span<Scalar> x);
    //! The right-hand side and the displacements dx_ of the free vertices at x.
    void assemble_displacements(std::span<const Scalar> x, bool use_blocks);
    //! system_.rhs at the free vertices: r(x) = -1/2 dE/dx.
    void assemble_rhs(std::span<const Scalar> x);
    //! One step of the direct or implicit method: dx_f = A_ff^-1 r_f(x), then the flip
    //! guard (guard_jump; general_step keeps the start) and an implicit step's volume
    //! (direct_step.cpp, with the right-hand side and the gradient).
    StepInfo direct_step(std::span<Scalar> x);
    //! The direct or CG method with the volume kept: the minimizer under the constraint.
    bool minimizes_under_volume() const
    {
        return terms_->volume() != nullptr && solves_for_minimizer(recipe_.method);
    }
    //! After a direct step on x: the minimizer's pins on record when x is the kept
    //! positions and follow_pins can follow it (pin_response.cpp).
    void note_minimizer(std::span<const Scalar> x, Index shortened);
    //! The fused step's constant energy parts are stale (new positions or targets).
    void forget_fixed_energy()
    {
        if (fused_)
            fused_->forget_fixed_energy();
    }
    //! x_ holds new positions.
    void positions_given();
    FlipGuard* guard() { return guard_ ? &*guard_ : nullptr; }
    void check_size(std::span<const Scalar> x, const char* what) const;

    const Mesh* mesh_;
    const Topology* topology_;
    std::span<const Index> file_vertex_; //!< the file's vertex numbers (messages); or empty
    //! #V, from the topology: the mesh's positions may be handed to adopt_positions.
    Index vertex_count_ = 0;
    Recipe recipe_;
    int precompute_count_ = 0;

    std::vector<Index> free_;
    std::vector<Index> hard_;
    std::vector<Scalar> hard_targets_; //!< 3 per hard vertex; empty: no targets
    std::unique_ptr<TermSet> terms_;
    std::optional<FlipGuard> guard_;
    //! 3 #V: the positions a step starts from, when the guard needs them kept (Taubin's
    //! two passes, the general step); else empty
    std::vector<Scalar> guard_start_;
    std::vector<std::string> notes_;
    JacobiSystem system_;
    //! The fused step takes the normal term's corner parts from per-face shares
    //! (triangles): FusedJacobi
    bool normal_shares_ = false;
    std::unique_ptr<FusedJacobi> fused_; //!< when fused()
    //! The direct and implicit methods' solver of A_ff
    std::unique_ptr<FreeSystemSolver> linear_;
    //! The pins' targets (3 each) for which the kept positions are the direct method's
    //! minimizer (a direct step on them, not shortened, by the factor, of an isotropic
    //! recipe); empty: none on record
    std::vector<Scalar> minimizer_pins_;
    PinResponses pin_responses_;
    //! The direct method with the volume: where the step started, and its minimizer.
    std::vector<Scalar> volume_at_;
    //! The progressive step: where it began, and the gradient there.
    std::vector<Scalar> progressive_start_;
    Scalar progressive_gradient_ = 0;
    VolumeMinimizer volume_minimizer_;
    std::vector<Scalar> dx_;   //!< 3 #V, zero on non-free vertices
    std::vector<Scalar> x_;    //!< kept positions (set_positions)
    std::vector<Scalar> next_; //!< 3 #V: the fused step's output, when fused()
    //! 3 #V: the positions before the last step(before, true) of a step that is not the
    //! fused Jacobi step (revert_step); else empty
    std::vector<Scalar> previous_;
    bool revert_to_previous_ = false; //!< revert_step() takes previous_, not next_
    bool can_revert_ = false;         //!< the last call was a fused step on the kept positions
    bool has_positions_ = false;      //!< positions were given (x_ may be empty: #V = 0)
};

} // namespace meshfair
