// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/session.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "core/solver/free_hessian.h"
#include "core/solver/solver.h"

namespace meshfair {

Session::Session(const Mesh& mesh, const Topology& topology, const Recipe& recipe,
                 std::span<const Index> file_vertex, std::unique_ptr<SparseCholesky> analysed)
    : mesh_(&mesh), topology_(&topology), file_vertex_(file_vertex), recipe_(recipe)
{
    precompute(std::move(analysed));
}

void Session::set_recipe(const Recipe& recipe)
{
    recipe_ = recipe;
    precompute(take_factorization());
}

void Session::precompute(std::unique_ptr<SparseCholesky> analysed)
{
    check_recipe(recipe_, *mesh_); // before the sets are read
    ++precompute_count_;
    vertex_count_ = topology_->vertex_count;
    const Mesh& mesh = *mesh_;
    const Index nv = mesh.vertex_count();
    const std::span<const Scalar> x0 = mesh.positions;
    // The point the homogeneous terms' vertex parts are taken about (EdgeTerm::vertex_part)
    // and the normal term's shares' c (FaceNormalTerm::face_share): the middle of the
    // bounding box, where the products stay the size of the mesh.
    const Vec3 centre = bounding_box(x0).centre();

    // Fixed vertices: hard ones, and everything outside the region.
    const FixedVertices fixed_sets = fixed_vertices(recipe_, mesh);
    const std::vector<char>& fixed = fixed_sets.fixed;
    hard_.clear();
    hard_targets_.clear();
    if (recipe_.hard)
    {
        hard_ = recipe_.hard->vertices;
        for (const Vec3& t : recipe_.hard->targets)
            hard_targets_.insert(hard_targets_.end(), t.begin(), t.end());
    }
    fused_.reset();
    linear_.reset();
    minimizer_pins_.clear();
    pin_responses_.clear();
    terms_.reset(); // (its arrays go before the next one's are built)
    terms_ = std::make_unique<TermSet>(mesh, *topology_, recipe_, fixed, fixed_sets.hard, hard_,
                                       hard_targets_, centre);
    notes_ = terms_->notes();
    guard_.reset();
    guard_start_ = {};
    if (recipe_.prevent_flips)
    {
        guard_.emplace(mesh, *topology_, x0, fixed);
        if (recipe_.method == Method::Taubin || !fused())
            guard_start_.assign(3 * static_cast<size_t>(nv), 0);
    }

    // The Jacobi system: constant diagonal, blocks while the normals stay fixed.
    system_.diagonal.assign(nv, 0);
    terms_->add_diagonal(system_.diagonal);
    free_.clear();
    for (Index v = 0; v < nv; ++v)
        if (!fixed[v] && system_.diagonal[v] > 0)
            free_.push_back(v);
    terms_->set_free(free_);
    system_.block.clear();
    system_.inverse.clear();
    // On triangles the fused step takes the normal term's corner parts from per-face
    // shares, and solves with the diagonal beside the inverses (solve_less_block).
    const FaceNormalTerm* normal = terms_->normal();
    normal_shares_ = normal && fused() && normal->triangles();
    if (normal && recipe_.method != Method::GradientDescent)
    {
        system_.block.assign(6 * static_cast<size_t>(nv), 0);
        if (terms_->joint()) // the blocks are rebuilt and inverted again every step
            system_.inverse.assign(6 * static_cast<size_t>(nv), 0);
        invert_blocks();
    }
    can_revert_ = false;
    // The fused step needs no right-hand side nor displacement arrays, only an output.
    // Kept positions stay (a new recipe on the same mesh).
    if (fused())
    {
        fused_ =
            std::make_unique<FusedJacobi>(mesh, *topology_,
                                          FusedTerms{&terms_->edge(), terms_->soft(),
                                                     terms_->centroid(), normal, terms_->normals()},
                                          free_, fixed, system_, normal_shares_, centre);
        system_.rhs = {};
        dx_ = {};
        // (general_step allocates both if step(x) is ever called.)
        if (x_.empty())
            next_.assign(3 * static_cast<size_t>(nv), 0);
        else
            next_ = x_;
    }
    else
    {
        system_.rhs.assign(3 * static_cast<size_t>(nv), 0);
        dx_.assign(3 * static_cast<size_t>(nv), 0);
        next_ = {};
    }
    if (solves_linear_system(recipe_.method))
        linear_ = terms_->factor(free_, file_vertex_, notes_, std::move(analysed));
    else if (recipe_.tolerance > 0 && recipe_.method == Method::Taubin)
        notes_.push_back(std::string("tolerance: ") + kTaubinHasNoMinimizer +
                         ", so the tolerance may never stop them");
    else if (recipe_.tolerance > 0)
        if (const std::optional<std::string> why = unheld_part())
            notes_.push_back("tolerance: " + *why +
                             ". Steps only shrink such a part toward a point: the tolerance "
                             "stops them where the shrinking slows, not at a minimizer");
}

std::unique_ptr<SparseCholesky> Session::take_factorization()
{
    if (!linear_ || linear_->factorization() == nullptr)
        return nullptr;
    std::unique_ptr<SparseCholesky> factor = linear_->take_factorization();
    linear_.reset(); // nothing left to solve with: nor a minimizer to follow
    minimizer_pins_.clear();
    pin_responses_.clear();
    return factor;
}

void Session::invert_blocks()
{
    for (const Index i : free_)
        std::fill_n(&system_.block[6 * i], 6, Scalar(0));
    terms_->add_blocks(free_, system_.block);
    // Without joint mode the normals never move: the blocks are inverted in place, and the
    // inverses are all a step needs.
    const bool joint = terms_->joint() != nullptr;
    if (!meshfair::invert_blocks(system_, free_, joint))
        // Positive definite in exact arithmetic (docs/math.md); in doubles only while the
        // normal term's weights stay within some 1e15 of the diagonal's: a recipe beyond
        // that is refused as the input it is.
        throw RecipeError("normal",
                          "its weights overwhelm the other terms at a vertex: the vertex's "
                          "3x3 system is not positive definite in double precision (a "
                          "smaller mu or smaller per-face weights make it so)");
    if (!joint && !normal_shares_)
        system_.diagonal = {}; // in the inverses now; only joint mode inverts again
}

void Session::apply_hard_targets(std::span<Scalar> x) const
{
    for (size_t k = 0; k < hard_.size() && !hard_targets_.empty(); ++k)
        std::copy_n(&hard_targets_[3 * k], 3, &x[3 * hard_[k]]);
}

void Session::set_hard_targets(std::span<const Scalar> targets)
{
    progressive_start_.clear(); // the kept positions move otherwise
    if (targets.size() != 3 * hard_.size())
        throw InvalidInputError("Session::set_hard_targets: expected " +
                                std::to_string(3 * hard_.size()) + " values");
    hard_targets_.assign(targets.begin(), targets.end());
    forget_fixed_energy();
    terms_->move_pins(hard_targets_);
    minimizer_pins_.clear();
}

void Session::check_size(std::span<const Scalar> x, const char* what) const
{
    if (x.size() != 3 * static_cast<size_t>(vertex_count_))
        throw SolverError(std::string("Session::") + what + ": positions hold " +
                          std::to_string(x.size()) + " values, the mesh needs " +
                          std::to_string(3 * static_cast<size_t>(vertex_count_)));
}

bool Session::fused() const
{
    // Taubin's method is two such steps, of lambda and of mu.
    return (recipe_.method == Method::Jacobi || recipe_.method == Method::Taubin) &&
           !recipe_.optimal_step && !terms_->joint() && !recipe_.bending;
}

void Session::set_positions(std::span<const Scalar> x)
{
    check_size(x, "set_positions");
    x_.assign(x.begin(), x.end()); // (no allocation when the size is the same)
    positions_given();
}

void Session::adopt_positions(std::vector<Scalar>&& x)
{
    check_size(x, "adopt_positions");
    x_ = std::move(x);
    positions_given();
}

void Session::positions_given()
{
    progressive_start_.clear(); // the kept positions move otherwise
    minimizer_pins_.clear();
    has_positions_ = true;
    forget_fixed_energy();
    can_revert_ = false;
    if (fused())
        next_.assign(x_.begin(), x_.end()); // the vertices a step never writes agree
}

std::vector<Scalar> Session::release_positions()
{
    progressive_start_.clear(); // the kept positions move otherwise
    std::vector<Scalar> out;
    out.swap(x_);
    has_positions_ = false;
    forget_fixed_energy();
    can_revert_ = false;
    return out;
}

StepInfo Session::step()
{
    progressive_start_.clear(); // the kept positions move otherwise
    if (!has_positions_)
        throw SolverError("Session::step: no positions (call set_positions first)");
    can_revert_ = revert_to_previous_ = false;
    minimizer_pins_.clear(); // (a direct step records it again)
    if (!fused())
        return general_step(x_);
    const bool taubin = recipe_.method == Method::Taubin;
    if (guard_ && taubin) // the second pass overwrites the buffer the first one read
        std::copy(x_.begin(), x_.end(), guard_start_.begin());
    fused_->step(x_, next_, false, recipe_.lambda);
    std::swap(x_, next_);
    if (taubin)
    {
        // The second of Taubin's steps, from the first one's positions, as general_step
        // takes it. The positions before both are gone: nothing to revert to.
        fused_->step(x_, next_, false, recipe_.taubin_mu);
        std::swap(x_, next_);
    }
    StepInfo info{recipe_.lambda};
    // (The Jacobi step read next_, which the step left as it was.)
    info.shortened = guard_step(guard(), terms_->volume(),
                                taubin ? std::span<const Scalar>(guard_start_) : next_, x_);
    can_revert_ = !taubin;
    return info;
}

StepInfo Session::step(TermEnergies& before, bool gradient)
{
    progressive_start_.clear(); // the kept positions move otherwise
    if (!has_positions_)
        throw SolverError("Session::step: no positions (call set_positions first)");
    can_revert_ = false;
    if (!fuses_energy())
    {
        before = energy();
        if (gradient) // kept to revert to
            previous_.assign(x_.begin(), x_.end());
        StepInfo info = step();
        if (gradient && info.gradient < 0) // Taubin's fused pair finds none
        {
            assemble_rhs(previous_);
            info.gradient = rhs_norm(system_, free_);
        }
        can_revert_ = revert_to_previous_ = gradient;
        return info;
    }
    StepInfo info{recipe_.lambda};
    before = fused_->step(x_, next_, true, recipe_.lambda, gradient ? &info.gradient : nullptr);
    std::swap(x_, next_);
    info.shortened = guard_step(guard(), terms_->volume(), next_, x_);
    can_revert_ = true;
    revert_to_previous_ = false;
    return info;
}

void Session::revert_step()
{
    progressive_start_.clear(); // the kept positions move otherwise
    if (!can_revert_)
        throw SolverError("Session::revert_step: no step to undo");
    // The fused step's buffer it read is untouched: it wrote the other one (the free
    // vertices; the fixed ones agree in both). Other steps kept a copy.
    if (revert_to_previous_)
        x_.swap(previous_);
    else
        std::swap(x_, next_);
    can_revert_ = false;
}

StepInfo Session::step(std::span<Scalar> x)
{
    check_size(x, "step");
    return general_step(x);
}

StepInfo Session::general_step(std::span<Scalar> x)
{
    if (dx_.size() != 3 * static_cast<size_t>(vertex_count_))
    { // the first general step of a fused session
        system_.rhs.assign(3 * static_cast<size_t>(vertex_count_), 0);
        dx_.assign(3 * static_cast<size_t>(vertex_count_), 0);
    }
    if (guard_)
    {
        guard_start_.resize(x.size()); // a fused session's first general step allocates
        std::copy(x.begin(), x.end(), guard_start_.begin());
    }
    if (solves_linear_system(recipe_.method))
        return direct_step(x);
    const bool use_blocks = !system_.inverse.empty();
    if (terms_->joint() && use_blocks)
        invert_blocks(); // the normals moved in the previous step
    const auto finish = [&](StepInfo info) {
        info.shortened = guard_step(guard(), terms_->volume(), guard_start_, x);
        return info;
    };
    assemble_displacements(x, use_blocks);
    StepInfo info;
    info.lambda = recipe_.lambda;
    info.gradient = rhs_norm(system_, free_); // r where the step starts
    if (recipe_.method == Method::Taubin)
    {
        // lambda, then mu < -lambda from the new positions: Taubin's two passes.
        apply_displacements(free_, dx_, recipe_.lambda, x);
        assemble_displacements(x, use_blocks);
        apply_displacements(free_, dx_, recipe_.taubin_mu, x);
        return finish(info);
    }
    if (recipe_.optimal_step)
        info.lambda = optimal_step(rhs_dot(system_, free_, dx_), terms_->quadratic(dx_));
    // Joint mode updates u from the old x and old u, like x: one Jacobi step on both.
    // The line search is exact for x with u held; u never steps past its minimizer.
    if (terms_->joint())
        terms_->update_normals(x, std::min<Scalar>(info.lambda, 1));
    apply_displacements(free_, dx_, info.lambda, x);
    return finish(info);
}

void Session::assemble_displacements(std::span<const Scalar> x, bool use_blocks)
{
    assemble_rhs(x);
    if (recipe_.method == Method::GradientDescent)
        gradient_displacements(system_, free_, dx_);
    else // Jacobi, and each of Taubin's two passes
        jacobi_displacements(system_, free_, use_blocks, dx_);
}

void Session::vertex_energy(std::span<const Scalar> x, EnergyTerm term,
                            std::span<Scalar> per_vertex) const
{
    check_size(x, "vertex_energy");
    terms_->vertex_energy(x, term, per_vertex);
}

std::vector<char> Session::free_flags() const
{
    std::vector<char> is_free(mesh_->vertex_count(), 0);
    for (const Index i : free_)
        is_free[i] = 1;
    return is_free;
}

TermEnergies Session::held_energy(std::span<const Scalar> x) const
{
    check_size(x, "held_energy");
    return terms_->held_energy(x, free_flags());
}

} // namespace meshfair
