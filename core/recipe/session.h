// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/energies/bending_term.h"
#include "core/energies/edge_term.h"
#include "core/energies/face_centroid_term.h"
#include "core/energies/face_normal_term.h"
#include "core/energies/joint_term.h"
#include "core/energies/normal_smoothing_term.h"
#include "core/energies/soft_vertex_term.h"
#include "core/energies/volume_constraint.h"
#include "core/recipe/recipe.h"
#include "core/solver/conjugate_gradient.h"
#include "core/solver/flip_guard.h"
#include "core/solver/jacobi_system.h"
#include "core/solver/sparse_cholesky.h"

namespace meshfair {

//! Value of each term of the recipe's energy; inactive terms are 0.
struct TermEnergies
{
    Scalar edge = 0;             //!< sum_E |x_j - x_i|^2
    Scalar soft = 0;             //!< soft vertex constraints
    Scalar centroid = 0;         //!< soft face-centroid constraints
    Scalar normal = 0;           //!< face-normal constraints, each face-edge pair once
    Scalar normal_smoothing = 0; //!< joint mode: gamma sum_{E*} |u_f - u_g|^2
    Scalar normal_soft = 0;      //!< joint mode: soft normal constraints on u
    Scalar bending = 0;          //!< mu sum_k |u_k|^2, the squared umbrella operator
    Scalar total() const
    {
        return edge + soft + centroid + normal + normal_smoothing + normal_soft + bending;
    }
    TermEnergies& operator+=(const TermEnergies& o)
    {
        edge += o.edge;
        soft += o.soft;
        centroid += o.centroid;
        normal += o.normal;
        normal_smoothing += o.normal_smoothing;
        normal_soft += o.normal_soft;
        bending += o.bending;
        return *this;
    }
};

//! The terms of the energy that a heat map can show, or all of them.
enum class EnergyTerm
{
    Total,
    Edge,
    Soft,
    Centroid,
    Normal,
    Bending
};

//! What one step did.
struct StepInfo
{
    Scalar lambda = 0; //!< step length used (the line search's choice when optimal)
    //! With Recipe::prevent_flips: the vertices whose steps FlipGuard shortened (one
    //! shortened again after the volume's correction counts again)
    Index shortened = 0;
    //! The direct method: |r(x)| over the free vertices where the step started, r = -1/2
    //! dE/dx (Session::Residual::gradient); -1 for the other methods, which do not compute it.
    Scalar gradient = -1;
    //! Conjugate gradients: the iterations of the step's solve (summed over the coordinates
    //! when they are solved apart); 0 for the other methods.
    int inner_iterations = 0;
};

//! \brief All smoothing strategies of \cite taubin_2012 combined in one solver, shaped
//! like libigl's min_quad_with_fixed: the constructor precomputes everything that depends
//! on the topology, the constraint sets and their weights; step() then runs one
//! generalized Jacobi step in linear time without allocating.
//!
//! The energy is E = E_L + E_S + E_C + E_N (+ the normal terms of joint mode) over the
//! free vertices: those in the region (all when there is none) that are not hard and
//! have a non-zero Jacobi diagonal. Every other vertex is never written.
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
    Session(const Mesh& mesh, const Topology& topology, const Recipe& recipe,
            std::span<const Index> file_vertex = {});
    // The terms point at one another (joint mode, bilateral weights): not copied, not moved.
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    //! Replaces the recipe and precomputes again.
    void set_recipe(const Recipe& recipe);
    const Recipe& recipe() const { return recipe_; }

    //! Writes the hard vertices' targets (when the recipe gives any) into x; the paper
    //! moves constrained vertices first and then keeps them fixed.
    void apply_hard_targets(std::span<Scalar> x) const;
    //! New targets, 3 per vertex of the hard set (in recipe order); right-hand side only.
    void set_hard_targets(std::span<const Scalar> targets);
    //! New soft targets, 3 per soft vertex (in soft_vertices() order).
    void set_soft_targets(std::span<const Scalar> targets);
    //! New centroid targets, 3 per constrained face (in centroid_faces() order).
    void set_centroid_targets(std::span<const Scalar> targets);

    //! One step: assemble r, solve each free vertex's system, choose lambda, move.
    //! In joint mode the normals are updated in the same step, from the same old values.
    //! \throw SolverError when x does not hold 3 #V values.
    StepInfo step(std::span<Scalar> x);

    TermEnergies energy(std::span<const Scalar> x) const;
    //! \brief Each vertex's share of a term's energy at x (per_vertex: #V values, set): the
    //! edge and normal terms give half of each edge's part to each end, the centroid term
    //! 1/n_f of a face's to each corner, so the shares sum to the term's energy(x). Total is
    //! the sum of the position terms (the normal-smoothing terms of joint mode have no
    //! vertex). Where constraints fight the smoothing, both shares are high.
    void vertex_energy(std::span<const Scalar> x, EnergyTerm term,
                       std::span<Scalar> per_vertex) const;

    //! \brief Positions kept by the session, for callers that step many times (run(),
    //! the editor): step() then works on them without copying, alternating two buffers
    //! when the step can be fused (see fused_step). Allocates; step() does not.
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
    //! it: each free vertex adds its parts of the energy while it computes its step,
    //! -(x_i - c)^T r_i for the edge term (EdgeTerm::vertex_part), mu_i |x_i - t_i|^2 for its
    //! anchor, the face-normal pairs that start at it; the centroid faces' energies (and
    //! with normal_shares() the normal term's, by faces) come from the pass that computes
    //! their per-face shares. The fixed vertices' parts are summed once per
    //! set of positions, except those of fixed vertices next to a free one, which are summed every
    //! step. Otherwise energy() runs first. The same positions as step(); the energy agrees with
    //! energy() to rounding and is the same for any thread count.
    StepInfo step(TermEnergies& before);
    //! True when step(before) finds the energy in the step's own sweep and revert_step()
    //! can undo a step: the fused Jacobi step (see fused_step). Taubin's method fuses its
    //! two steps but not the energy: the second starts where the first ends.
    bool fuses_energy() const { return fused() && recipe_.method != Method::Taubin; }
    //! \brief True when the fused step takes the normal term's corner parts from per-face
    //! shares (a normal term on a mesh of triangles: FaceNormalTerm::face_share): it
    //! then sums the terms' parts in another order than step(x) does, and its positions
    //! agree with step(x)'s to rounding (about 1e-16 of the mesh's size per step), not
    //! bit for bit.
    bool normal_shares() const { return normal_shares_; }
    //! \brief Puts back the kept positions of before the last step: for a run that learns
    //! from step(before) one step late that the step before it had converged.
    //! \throw SolverError unless the last call was a step() or step(before) on the kept
    //! positions with fuses_energy().
    void revert_step();
    //! The energy of the kept positions.
    TermEnergies energy() const { return energy(x_); }
    //! How far positions are from the minimizer, from one assembly of r = -1/2 dE/dx (the
    //! normals held) at the free vertices.
    struct Residual
    {
        //! |r(x)|, the Euclidean norm over the free vertices: 0 exactly at the minimizer.
        //! The direct method's stopping rule compares it with the input's.
        Scalar gradient = 0;
        //! The largest length of a free vertex's generalized Jacobi displacement A_i^-1 r_i:
        //! how far one more Jacobi step would move a vertex.
        Scalar jacobi_displacement = 0;
    };
    Residual residual(std::span<const Scalar> x);
    //! \brief Why the recipe's energy has no unique minimizer over the free vertices: the
    //! first free part (connected through edges) that nothing holds (no fixed vertex next
    //! to it, no anchor, no constrained face), named by its size and its lowest vertex in
    //! the file's numbering; nullopt when every part is held. The direct method refuses
    //! such a recipe; steps of it only shrink such a part, toward a point.
    std::optional<std::string> unheld_part() const;
    //! The direct method's factorization (nullptr for the other methods, and when conjugate
    //! gradients solve in its place).
    const SparseCholesky* factorization() const { return cholesky_.get(); }
    //! True when the minimizer's steps are solved by conjugate gradients ("cg", or the
    //! direct method over its factor budget: notes() says why).
    bool conjugate_gradients() const { return cg_.has_value(); }

    std::span<const Index> free_vertices() const { return free_; }
    //! Current face normals u (3 #F) used by the normal terms; empty when unused.
    std::span<const Scalar> normals() const { return normals_; }
    //! E_U before and after each normal-smoothing iteration (normals "smoothed"); with
    //! bilateral weights, the robust energy E_R + the soft part (BilateralFaceWeights).
    const std::vector<Scalar>& normal_smoothing_trace() const { return smoothing_trace_; }
    //! What the run does besides the recipe's letter, for reports: how open components'
    //! volumes are kept (or that they are not), a falloff with nothing to fade from.
    const std::vector<std::string>& notes() const { return notes_; }
    //! The volume constraint, when the recipe keeps volumes.
    const VolumeConstraint* volume() const { return volume_ ? &*volume_ : nullptr; }
    //! How many times the precomputation ran (1 after construction).
    int precompute_count() const { return precompute_count_; }

private:
    void precompute();
    //! The soft term from the soft section's anchors and the falloff's, merged per vertex.
    void build_falloff_anchors(const std::vector<char>& fixed, const std::vector<char>& is_hard);
    //! The merged soft targets for the current hard targets (the falloff moves with pins).
    void update_falloff_targets();
    void invert_blocks();
    //! With prevent_flips, in place of the volume's correction after a step from `start`
    //! to x: shortens the steps that turn faces over, restores the volumes, and checks that
    //! correction in turn (the vertices shortened then stay, the others restore the
    //! volumes: VolumeConstraint::project with `hold`), up to 3 rounds. Returns the count
    //! of shortened vertex steps.
    Index guard_step(std::span<const Scalar> start, std::span<Scalar> x);
    //! \brief The flip guard on a step of the direct method: the whole step start -> x
    //! shortened by the largest factor 2^-k (k <= 20, else 0) at which no face is turned
    //! over that was not at `start` (FlipGuard::turned_after_jump).
    //! Returns how many vertex steps it shortened (every free vertex's, or none).
    Index guard_direct_step(std::span<const Scalar> start, std::span<Scalar> x);
    //! True when step() can be fused: the Jacobi method (or Taubin's, two Jacobi steps)
    //! with a fixed lambda and fixed normals (no line search, no joint mode).
    bool fused() const;
    //! The faces of a per-face pass of the fused step (faces nullptr: the k-th face is k).
    struct FacePass
    {
        const Index* faces = nullptr;
        Index count = 0;
    };
    //! A term's faces with a free vertex: `active`, or when that is empty the term's own
    //! `listed` faces (precompute leaves it empty when they are the same list).
    static FacePass face_pass(const std::vector<Index>& active, const IndexList& listed);
    //! The centroid term's faces with a free vertex (its residual pass).
    FacePass centroid_pass() const { return face_pass(centroid_active_, centroid_->faces()); }
    //! The normal term's faces with a free vertex (its share pass).
    FacePass normal_pass() const { return face_pass(normal_active_, normal_->faces()); }
    //! \brief The fused step: one sweep over the free vertices in which each vertex adds
    //! every term's part of r_i (the terms' add_vertex_rhs, in the order general_step adds them),
    //! solves its 3x3 or scalar system and writes y_i = x_i + step dx_i. The same operations as
    //! general_step without its right-hand-side and displacement arrays and their passes
    //! over memory. With centroid constraints a pass over the constrained faces first
    //! computes each face's residual once (FaceCentroidTerm::face_residuals), which the
    //! face's corners then add (add_corner_shares: the same bits as add_vertex_rhs). With
    //! normal_shares(), the same pass adds the normal term's share of each face
    //! (FaceNormalTerm::face_share), and the solve takes the rest of its part
    //! (solve_less_block): the corners read one 3-vector per face instead of
    //! the face's normal and their two neighbours, the same result to rounding.
    //! x and y must not overlap; y is written at free vertices only.
    //! With energy, returns the energy of x (fused_sweep's parts and fixed_energy's).
    TermEnergies fused_step(std::span<const Scalar> x, std::span<Scalar> y, bool energy,
                            Scalar step);
    //! fused_step for one combination of active terms, so that the sweep tests nothing
    //! per vertex: the plain Laplacian step is a bare gather loop. (The Jacobi method
    //! solves 3x3 blocks exactly when the normal term is on.)
    //! With Energy, returns the parts of E(x) that the free vertices and the centroid
    //! faces with a free corner own, summed in blocks that depend on the counts only.
    template <bool Soft, bool Centroid, bool Normal, bool Energy>
    TermEnergies fused_sweep(const Scalar* x, Scalar* y, Scalar step);
    //! The sweep over free[begin .. end) (AllFree: every vertex free, i = k; NormalWeighted:
    //! the normal term's faces have weights of their own; Energy: the range's owned parts of
    //! the energy are summed and returned).
    template <bool Soft, bool Centroid, bool Normal, bool NormalWeighted, bool AllFree, bool Energy>
    TermEnergies fused_range(const Scalar* x, Scalar* y, Scalar step, Index begin, Index end) const;
    //! The parts of E(x) of the vertices of `vertices` (fixed ones: the sweep leaves them
    //! out), summed in blocks.
    TermEnergies vertex_parts(const Scalar* x, std::span<const Index> vertices) const;
    //! e += vertex i's parts at x: -(x_i - c)^T r_i of the edge term (EdgeTerm::vertex_part),
    //! its anchor's mu_i |x_i - t_i|^2, the face-normal pairs that start at it.
    void add_vertex_parts(const Scalar* x, Index i, TermEnergies& e) const;
    //! The parts of the fixed vertices and of the centroid faces without a free corner at
    //! x: the constant part once per set of positions, the border's every call.
    TermEnergies fixed_energy(const Scalar* x);
    //! The general step (separate right-hand side, displacement, line search, joint
    //! update), in place on x.
    StepInfo general_step(std::span<Scalar> x);
    //! The right-hand side and the displacements dx_ of the free vertices at x.
    void assemble_displacements(std::span<const Scalar> x, bool use_blocks);
    //! system_.rhs at the free vertices: r(x) = -1/2 dE/dx.
    void assemble_rhs(std::span<const Scalar> x);
    //! |system_.rhs| over the free vertices, the same for any thread count.
    Scalar rhs_norm() const;
    //! The direct method's precomputation: A_ff assembled, analysed and factored.
    //! \throw RecipeError when A_ff is singular (a free part that nothing holds).
    void factor_direct();
    //! One step of the direct method: dx_f = A_ff^-1 r_f(x), then the flip guard if any.
    StepInfo direct_step(std::span<Scalar> x);
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

    EdgeTerm edge_;
    //! 3 #V: the initial positions, when soft or centroid targets are at them (the terms
    //! read them here); declared before the terms, which view it.
    std::vector<Scalar> initial_;
    std::optional<SoftVertexTerm> soft_;
    std::optional<FaceCentroidTerm> centroid_;
    std::optional<FaceNormalTerm> normal_;
    std::optional<NormalSmoothingTerm> smoothing_;
    std::optional<BilateralFaceWeights> bilateral_; //!< the smoothing term's weights, if any
    std::optional<JointTerm> joint_;
    std::optional<BendingTerm> bending_;
    int joint_steps_ = 0; //!< joint steps since the precomputation (for reweighting)
    std::optional<VolumeConstraint> volume_;
    std::optional<FlipGuard> guard_;
    //! 3 #V: the positions a step starts from, when the guard needs them kept (Taubin's
    //! two passes, the general step); else empty
    std::vector<Scalar> guard_start_;
    std::vector<std::string> notes_;
    //! Falloff, per soft vertex: its nearest pin (index into hard_) or kInvalidIndex, its
    //! target with the pins unmoved (3 each) and the share of the pin's displacement it
    //! follows. Empty without falloff; falloff_pin_ is empty when no pin moves a target.
    std::vector<Index> falloff_pin_;
    std::vector<Scalar> falloff_base_, falloff_share_;

    std::vector<Scalar> normals_; //!< 3 #F
    std::vector<Scalar> smoothing_trace_;
    JacobiSystem system_;
    //! The direct method's factor of A_ff (nullptr for the other methods), and whether A_ff
    //! has 3x3 blocks (the normal term): 3 #free unknowns, else #free for 3 right-hand sides
    std::unique_ptr<SparseCholesky> cholesky_;
    //! Conjugate gradients' matrix (A_ff by rows) and its inverted diagonal blocks, in place
    //! of the factor
    struct ConjugateGradientSystem
    {
        SymmetricRows a;
        std::vector<Scalar> inverse;
        int block = 1;
    };
    std::optional<ConjugateGradientSystem> cg_;
    bool direct_blocks_ = false;
    std::vector<Scalar> direct_rhs_; //!< 3 #free: r_f, then dx_f, in the solver's order
    std::vector<Scalar> dx_;         //!< 3 #V, zero on non-free vertices
    std::vector<Scalar> scratch_u_;  //!< 3 #F for normal smoothing and joint mode, else empty
    std::vector<Scalar> x_;          //!< kept positions (set_positions)
    std::vector<Scalar> next_;       //!< 3 #V: the fused step's output, when fused()
    //! 3 #F: this step's per-face shares of the right-hand side for the fused step: the
    //! centroid residual, plus the normal term's share (FaceNormalTerm::face_share) when
    //! normal_shares_; else empty
    std::vector<Scalar> face_share_;
    //! Which faces' shares a corner adds (either term constrains them); nullptr: every
    //! face. Points into a term or share_flag_own_.
    const char* share_flag_ = nullptr;
    std::vector<char> share_flag_own_; //!< #F when both terms list faces, else empty
    //! The fused step takes the normal term's corner parts from face_share_ (triangles)
    bool normal_shares_ = false;
    //! The constrained faces with a free vertex, ascending; empty when that is every
    //! constrained face and the term lists them ascending (the pass reads its list)
    std::vector<Index> centroid_active_;
    //! The normal term's faces with a free vertex, ascending; empty when that is every
    //! constrained face and the term lists them ascending
    std::vector<Index> normal_active_;
    //! The centroid and normal passes walk the same faces: fused_sweep makes them one
    bool shared_face_pass_ = false;
    //! The normal term's faces without a free vertex, ascending, when normal_shares_:
    //! kept: the fused step's energy then counts the normal term by faces, not by vertices
    std::vector<Index> normal_inactive_;
    //! The constrained faces without a free vertex, ascending (fused steps; their energy
    //! is constant)
    std::vector<Index> centroid_inactive_;
    //! Fixed vertices with a free neighbour, ascending: their parts of the energy change
    //! with the free positions (fused steps)
    std::vector<Index> energy_border_;
    //! c of the vertex parts -(x_i - c)^T r_i (the bounding box's middle)
    std::array<Scalar, 3> energy_centre_{};
    //! The parts of the other fixed vertices and of centroid_inactive_, for the kept
    //! positions and targets, while fixed_constant_valid_
    TermEnergies fixed_constant_;
    bool fixed_constant_valid_ = false;
    bool can_revert_ = false;    //!< the last call was a fused step on the kept positions
    bool has_positions_ = false; //!< positions were given (x_ may be empty: #V = 0)
};

//! \brief The parts of a Topology a Session with `recipe` reads: V(i) always, the corners
//! for the face terms, the dual graph for normal smoothing and joint mode.
TopologyParts required_topology(const Recipe& recipe);

//! \brief The direct method's stopping rule, for run() and the editor's runs: after each
//! step, the gradient |r| at its result relative to the gradient where the first step
//! started (the input's) must be at most the tolerance (1e-12 when it is 0), or the step
//! stops when it no longer halves the gradient (rounding: the minimizer is reached).
class DirectConvergence
{
public:
    explicit DirectConvergence(Scalar tolerance)
        : tolerance_(tolerance > 0 ? tolerance : Scalar(1e-12))
    {
    }
    //! A step that started at gradient `started` (StepInfo::gradient) and ended at `now`;
    //! true when the run stops here.
    bool stop_after(Scalar started, Scalar now)
    {
        if (steps_++ == 0)
            first_ = started;
        relative_ = first_ > 0 ? now / first_ : 0;
        const bool stalled = steps_ > 1 && now >= Scalar(0.5) * last_;
        last_ = now;
        return relative_ <= tolerance_ || stalled;
    }
    //! The last step's gradient relative to the first's start.
    Scalar relative() const { return relative_; }

private:
    Scalar tolerance_;
    Scalar first_ = 0, last_ = 0, relative_ = 0;
    int steps_ = 0;
};

//! The outcome of a whole run.
struct SmoothResult
{
    std::vector<TermEnergies> energies; //!< before the first step, then after each one
    std::vector<Scalar> lambdas;        //!< per step
    std::vector<Index> shortened;       //!< per step: StepInfo::shortened
    //! The direct method: |r(x)| / |r(x_0)| after each step (x_0 the input, r = -1/2 dE/dx
    //! over the free vertices); empty for the other methods.
    std::vector<Scalar> gradients;
    //! Conjugate gradients: each step's iterations (StepInfo::inner_iterations); else empty.
    std::vector<int> inner_iterations;
    //! The direct method: the largest free vertex's Jacobi displacement at the result
    //! (Session::Residual), how far one more Jacobi step would move it; -1
    //! for the other methods.
    Scalar jacobi_displacement = -1;
    int iterations = 0; //!< steps taken
    bool stopped_by_tolerance = false;
};

//! \brief Runs session.recipe().iterations steps on x (modified in place), stopping early
//! by the recipe's tolerance; `on_step` (optional) sees each step's energies. The direct
//! method stops when the gradient relative to the input's falls to the tolerance (1e-12
//! when it is 0), or stops falling (rounding): a quadratic recipe after one or two steps.
SmoothResult run(Session& session, std::span<Scalar> x,
                 const std::function<void(int, const TermEnergies&)>& on_step = {});
//! The same on the session's kept positions (set_positions or adopt_positions first).
//! \throw SolverError when the session keeps no positions.
SmoothResult run(Session& session,
                 const std::function<void(int, const TermEnergies&)>& on_step = {});

//! \brief One-liner: check the recipe, precompute, move hard vertices to their targets
//! and run. mesh.positions are modified in place.
//! \throw RecipeError when the recipe does not fit the mesh.
SmoothResult smooth(Mesh& mesh, const Topology& topology, const Recipe& recipe);

} // namespace meshfair
