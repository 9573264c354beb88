// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/session.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "core/energies/falloff.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "core/solver/free_hessian.h"
#include "core/solver/solver.h"

namespace meshfair {

namespace {

std::vector<Index> all_indices(Index n)
{
    std::vector<Index> v(n);
    for (Index i = 0; i < n; ++i)
        v[i] = i;
    return v;
}

std::vector<Scalar> flatten(const std::vector<Vec3>& points)
{
    std::vector<Scalar> flat;
    flat.reserve(3 * points.size());
    for (const Vec3& p : points)
        flat.insert(flat.end(), p.begin(), p.end());
    return flat;
}

std::vector<Scalar> gather3(std::span<const Scalar> values, std::span<const Index> items)
{
    std::vector<Scalar> out;
    out.reserve(3 * items.size());
    for (const Index k : items)
        out.insert(out.end(), values.begin() + 3 * k, values.begin() + 3 * k + 3);
    return out;
}

std::vector<Scalar> unit_normals(const std::vector<Vec3>& normals)
{
    std::vector<Scalar> flat = flatten(normals);
    for (size_t k = 0; k < flat.size(); k += 3)
        normalize3(&flat[k]);
    return flat;
}

} // namespace

namespace {

// Conjugate gradients stop at this residual relative to the step's right-hand side: the
// minimizer to rounding, as the factor gives it (the run's rule then stops the steps).
constexpr Scalar kConjugateGradientTolerance = 1e-13;

// The direct method's factor budget in bytes: the recipe's, or half the physical memory.
double factor_budget_bytes(Scalar budget_mb)
{
    if (budget_mb > 0)
        return budget_mb * 1e6;
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? 0.5 * static_cast<double>(pages) * static_cast<double>(page)
                                 : 1e300;
}

} // namespace

Session::Session(const Mesh& mesh, const Topology& topology, const Recipe& recipe,
                 std::span<const Index> file_vertex)
    : mesh_(&mesh),
      topology_(&topology),
      file_vertex_(file_vertex),
      recipe_(recipe),
      edge_(topology)
{
    precompute();
}

void Session::set_recipe(const Recipe& recipe)
{
    recipe_ = recipe;
    precompute();
}

TopologyParts required_topology(const Recipe& recipe)
{
    TopologyParts parts = TopologyParts::Neighbors;
    if (recipe.centroid || recipe.normal)
        parts = parts | TopologyParts::Corners;
    if (recipe.normal && (recipe.normal->source == NormalSource::Smoothed || recipe.joint))
        parts = parts | TopologyParts::Dual;
    if (recipe.volume)
        parts = parts | TopologyParts::Corners | TopologyParts::Edges;
    if (recipe.bending) // its umbrellas follow the open boundaries
        parts = parts | TopologyParts::Edges;
    if (recipe.prevent_flips)
        parts = parts | TopologyParts::Corners;
    return parts;
}

void Session::precompute()
{
    check_recipe(recipe_, *mesh_);
    if (topology_->vertex_count != mesh_->vertex_count() ||
        topology_->face_count != mesh_->face_count())
        throw SolverError("Session: the topology was built for another mesh");
    if (!has_parts(topology_->parts, required_topology(recipe_)))
        throw SolverError(
            "Session: the topology lacks parts this recipe needs (build it "
            "with required_topology(recipe))");
    ++precompute_count_;
    notes_.clear();
    vertex_count_ = topology_->vertex_count;
    const Mesh& mesh = *mesh_;
    const Index nv = mesh.vertex_count(), nf = mesh.face_count();
    const std::span<const Scalar> x0 = mesh.positions;
    // The point the homogeneous terms' vertex parts are taken about (EdgeTerm::vertex_part)
    // and the normal term's shares' c (FaceNormalTerm::face_share): the middle of the
    // bounding box, where the products stay the size of the mesh.
    energy_centre_ = bounding_box(x0).centre();

    // Fixed vertices: hard ones, and everything outside the region.
    std::vector<char> fixed(nv, 0);
    hard_.clear();
    hard_targets_.clear();
    if (recipe_.hard)
    {
        hard_ = recipe_.hard->vertices;
        hard_targets_ = flatten(recipe_.hard->targets);
        for (const Index v : hard_)
            fixed[v] = 1;
    }
    std::vector<char> is_hard(fixed);
    if (recipe_.region)
    {
        std::vector<char> inside(nv, 0);
        for (const Index v : recipe_.region->vertices)
            inside[v] = 1;
        for (const Index f : recipe_.region->faces)
            for (const Index v : mesh.face(f))
                inside[v] = 1;
        for (Index v = 0; v < nv; ++v)
            fixed[v] = fixed[v] || !inside[v];
    }

    // The terms take their index lists by move, and targets at the initial positions (the
    // default of soft and centroid constraints) are read from one copy of them shared by
    // both terms: no gathered or per-term copies (a million-vertex mesh would keep their
    // pages resident). A copy, not the mesh's positions: the session may step those
    // (adopt_positions).
    const bool soft_at_x0 = !recipe_.falloff && recipe_.soft && recipe_.soft->targets.empty();
    const bool centroids_at_x0 = recipe_.centroid && recipe_.centroid->targets.empty();
    soft_.reset();
    centroid_.reset();
    if (soft_at_x0 || centroids_at_x0)
        initial_.assign(x0.begin(), x0.end());
    else
        std::vector<Scalar>().swap(initial_);
    falloff_pin_ = {};
    falloff_base_ = {};
    falloff_share_ = {};
    if (recipe_.falloff)
        build_falloff_anchors(fixed, is_hard);
    else if (recipe_.soft)
    {
        const SoftVertices& s = *recipe_.soft;
        std::vector<Index> vertices;
        std::vector<Scalar> weights; // per listed vertex; with "all", of the vertices kept
        if (s.vertices.all)
        {
            vertices.reserve(static_cast<size_t>(nv));
            for (Index v = 0; v < nv; ++v)
                if (!is_hard[v])
                    vertices.push_back(v);
            if (!s.weights.empty())
            {
                weights.reserve(vertices.size());
                for (const Index v : vertices)
                    weights.push_back(s.weights[v]);
            }
        }
        else
            vertices = s.vertices.indices;
        soft_.emplace(
            nv, std::move(vertices), s.mu, std::span<const Scalar>{},
            s.vertices.all ? std::span<const Scalar>(weights) : std::span<const Scalar>(s.weights));
        if (s.targets.empty())
            soft_->view_targets(initial_);
        else if (s.vertices.all) // one target per vertex of the mesh
            soft_->set_targets_at(flatten(s.targets));
        else
            soft_->set_targets(flatten(s.targets));
    }

    if (recipe_.centroid)
    {
        const CentroidConstraints& c = *recipe_.centroid;
        centroid_.emplace(mesh, *topology_, c.faces.all ? all_indices(nf) : c.faces.indices, c.mu,
                          c.denominator, c.weights);
        if (c.targets.empty())
            centroid_->use_centroids_of(initial_);
        else
            centroid_->set_targets(flatten(c.targets));
    }

    normal_.reset();
    smoothing_.reset();
    bilateral_.reset();
    joint_.reset();
    joint_steps_ = 0;
    normals_.clear();
    smoothing_trace_.clear();
    if (recipe_.normal)
    {
        const NormalConstraints& n = *recipe_.normal;
        std::vector<Index> faces = n.faces.all ? all_indices(nf) : n.faces.indices;
        normals_ = face_normals(mesh, x0);
        const NormalSmoothing ns = recipe_.normal_smoothing.value_or(NormalSmoothing{});
        // The smoothing constraints' normals default to the initial ones: gathered before
        // normals_ (the initial normals until here) gets the custom directions.
        const std::vector<Scalar> hard_normals = ns.hard.normals.empty()
                                                     ? gather3(normals_, ns.hard.faces)
                                                     : unit_normals(ns.hard.normals);
        const std::vector<Scalar> soft_normals = ns.soft.normals.empty()
                                                     ? gather3(normals_, ns.soft.faces)
                                                     : unit_normals(ns.soft.normals);
        if (n.source == NormalSource::Custom)
        {
            const std::vector<Scalar> given = unit_normals(n.normals);
            for (size_t k = 0; k < faces.size(); ++k)
                std::copy_n(&given[3 * k], 3, &normals_[3 * faces[k]]);
        }
        normal_.emplace(mesh, *topology_, std::move(faces), n.mu, n.weights, energy_centre_);
        smoothing_.emplace(*topology_, ns.hard.faces, hard_normals, ns.soft.faces, ns.soft.mu,
                           soft_normals, ns.soft.weights);
        smoothing_->apply_hard(normals_);
        const bool smooths = n.source == NormalSource::Smoothed || recipe_.joint;
        // Scratch normals for normal smoothing and the joint update only.
        if (smooths)
            scratch_u_.assign(3 * static_cast<size_t>(nf), 0);
        else
            scratch_u_ = {};
        if (smooths && ns.bilateral)
        {
            bilateral_.emplace(mesh, *topology_, *ns.bilateral, x0);
            bilateral_->reweight(x0, normals_);
            smoothing_->set_weights(&*bilateral_);
        }
        if (n.source == NormalSource::Smoothed)
        {
            // Normal smoothing first, then integration of the smoothed normals through
            // the face-normal term (the paper's two-stage process). With bilateral
            // weights the trace follows the robust energy that the reweighting lowers.
            const auto smoothing_energy = [&] {
                return (bilateral_ ? bilateral_->robust_energy(normals_)
                                   : smoothing_->dual_energy(normals_)) +
                       smoothing_->soft_energy(normals_);
            };
            smoothing_trace_.push_back(smoothing_energy());
            for (int k = 0; k < ns.iterations; ++k)
            {
                if (bilateral_ && k > 0 && k % bilateral_->reweight_every() == 0)
                    bilateral_->reweight(x0, normals_);
                smoothing_->step(normals_, ns.lambda, scratch_u_);
                smoothing_trace_.push_back(smoothing_energy());
            }
        }
        if (recipe_.joint)
            joint_.emplace(*normal_, *smoothing_, *topology_, recipe_.joint->gamma);
    }

    volume_.reset();
    if (recipe_.volume)
    {
        volume_.emplace(mesh, *topology_, x0, fixed, recipe_.volume->open,
                        recipe_.volume->free_components_only);
        notes_.insert(notes_.end(), volume_->notes().begin(), volume_->notes().end());
    }
    guard_.reset();
    guard_start_ = {};
    if (recipe_.prevent_flips)
    {
        guard_.emplace(mesh, *topology_, x0, fixed);
        if (recipe_.method == Method::Taubin || !fused())
            guard_start_.assign(3 * static_cast<size_t>(nv), 0);
    }

    edge_.set_weight(recipe_.bending ? recipe_.bending->membrane : Scalar(1));
    bending_.reset();
    if (recipe_.bending)
        bending_.emplace(*topology_, recipe_.bending->mu);

    // The Jacobi system: constant diagonal, blocks while the normals stay fixed.
    system_.diagonal.assign(nv, 0);
    edge_.add_diagonal(system_.diagonal);
    if (bending_)
        bending_->add_diagonal(system_.diagonal);
    if (soft_)
        soft_->add_diagonal(system_.diagonal);
    if (centroid_)
        centroid_->add_diagonal(system_.diagonal);
    free_.clear();
    for (Index v = 0; v < nv; ++v)
        if (!fixed[v] && system_.diagonal[v] > 0)
            free_.push_back(v);
    if (bending_)
        bending_->set_free(free_);
    system_.block.clear();
    system_.inverse.clear();
    // On triangles the fused step takes the normal term's corner parts from per-face
    // shares, and solves with the diagonal beside the inverses (solve_less_block).
    normal_shares_ = normal_ && fused() && normal_->triangles();
    if (normal_ && recipe_.method != Method::GradientDescent)
    {
        system_.block.assign(6 * static_cast<size_t>(nv), 0);
        if (joint_) // the blocks are rebuilt and inverted again every step
            system_.inverse.assign(6 * static_cast<size_t>(nv), 0);
        invert_blocks();
    }
    // The fused step computes each constrained face's centroid residual once per step,
    // for the faces with a free vertex (when that is not all of them, they are listed).
    // A face's vertex is free exactly when it is not fixed: it has n_i >= 2 > 0.
    const auto has_free_vertex = [&](Index f) {
        return std::ranges::any_of(mesh.face(f), [&](Index v) { return fixed[v] == 0; });
    };
    // In the mesh's order: a list given in another numbering (a file's, renumbered for
    // locality) would read faces, corners and positions all over memory, which made
    // the pass slower than the whole sweep. A face's residual does not depend on the
    // order; the energy's sum does, by rounding only. Empty when the term's own list is
    // that list already.
    const auto active_faces = [&](const IndexList& listed, std::vector<Index>* inactive) {
        std::vector<Index> active;
        for (const Index f : listed)
            if (has_free_vertex(f))
                active.push_back(f);
            else if (inactive != nullptr)
                inactive->push_back(f);
        std::ranges::sort(active);
        if (active.size() == listed.size() &&
            (listed.identity() || std::is_sorted(listed.data(), listed.data() + listed.size())))
            active = {};
        return active;
    };
    face_share_ = {};
    centroid_active_ = {};
    centroid_inactive_ = {};
    normal_active_ = {};
    normal_inactive_ = {};
    share_flag_own_ = {};
    share_flag_ = nullptr;
    if (centroid_ && fused())
    {
        centroid_active_ = active_faces(centroid_->faces(), &centroid_inactive_);
        std::ranges::sort(centroid_inactive_);
        share_flag_ = centroid_->flags();
    }
    if (normal_shares_)
    {
        normal_active_ = active_faces(normal_->faces(), &normal_inactive_);
        std::ranges::sort(normal_inactive_);
        // A corner takes its face's share where either term constrains the face.
        const char* normal_flags = normal_->flags();
        if (!centroid_ || normal_flags == nullptr)
            share_flag_ = normal_flags;
        else if (share_flag_ != nullptr)
        {
            share_flag_own_.assign(share_flag_, share_flag_ + nf);
            for (Index f = 0; f < nf; ++f)
                share_flag_own_[f] = static_cast<char>(share_flag_own_[f] | normal_flags[f]);
            share_flag_ = share_flag_own_.data();
        }
    }
    if ((centroid_ && fused()) || normal_shares_)
        face_share_.assign(3 * static_cast<size_t>(nf), 0);
    shared_face_pass_ = false;
    if (centroid_ && fused() && normal_shares_)
    {
        const FacePass c = centroid_pass(), n = normal_pass();
        shared_face_pass_ =
            c.count == n.count && (c.faces == nullptr || n.faces == nullptr
                                       ? c.faces == n.faces
                                       : std::equal(c.faces, c.faces + c.count, n.faces));
    }
    // The fixed vertices whose parts of the energy move with the free ones.
    energy_border_ = {};
    if (fused() && free_.size() < static_cast<size_t>(nv))
    {
        std::vector<char> is_free(nv, 0);
        for (const Index v : free_)
            is_free[v] = 1;
        for (Index v = 0; v < nv; ++v)
            if (!is_free[v] &&
                std::ranges::any_of(topology_->neighbors(v), [&](Index j) { return is_free[j]; }))
                energy_border_.push_back(v);
    }
    fixed_constant_valid_ = false;
    can_revert_ = false;
    // The fused step needs no right-hand side nor displacement arrays, only an output.
    // Kept positions stay (a new recipe on the same mesh).
    if (fused())
    {
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
    cholesky_.reset();
    cg_.reset();
    direct_rhs_ = {};
    if (solves_linear_system(recipe_.method))
        factor_direct();
    else if (recipe_.tolerance > 0)
        if (const std::optional<std::string> why = unheld_part())
            notes_.push_back("tolerance: " + *why +
                             ". Steps only shrink such a part toward a point: the tolerance "
                             "stops them where the shrinking slows, not at a minimizer");
}

void Session::factor_direct()
{
    // With the normal term the coordinates couple (u u^T): one system of 3 #free unknowns.
    // Without it the matrix is the same for x, y and z: #free unknowns, 3 right-hand sides.
    direct_blocks_ = normal_.has_value();
    // Checked before the factorization, which may well factor a singular matrix in
    // doubles (a pivot of rounding size) and return garbage. An implicit step's matrix,
    // I / t + A_ff, is positive definite whatever holds the mesh.
    const bool implicit = recipe_.method == Method::Implicit;
    if (!implicit)
        if (const std::optional<std::string> why = unheld_part())
            throw RecipeError(
                "method", (recipe_.method == Method::Direct ? "\"direct\": " : "\"cg\": ") + *why);
    const Scalar shift = implicit ? 1 / recipe_.time : 0;
    const SymmetricMatrix a = assemble_free_hessian(
        vertex_count_, free_, direct_blocks_, [&](Index i, HessianColumn& col) {
            if (implicit)
                col.add(i, shift);
            edge_.add_hessian_column(i, col);
            if (bending_)
                bending_->add_hessian_column(i, col);
            if (soft_)
                soft_->add_hessian_column(i, col);
            if (centroid_)
                centroid_->add_hessian_column(i, col);
            if (normal_)
                normal_->add_hessian_column(i, normals_, col);
        });
    direct_rhs_.assign(3 * free_.size(), 0);
    // Conjugate gradients: asked for, or in place of a factor that would not fit.
    const auto use_conjugate_gradients = [&] {
        cholesky_.reset();
        ConjugateGradientSystem cg;
        cg.a = SymmetricRows::from_upper(a);
        cg.block = direct_blocks_ ? 3 : 1;
        try
        {
            cg.inverse = block_jacobi_inverse(cg.a, cg.block);
        }
        catch (const SolverError&)
        {
            throw RecipeError("method",
                              "the system of the free vertices is not positive "
                              "definite in double precision (weights many orders "
                              "of magnitude apart: closer ones make it so)");
        }
        cg_ = std::move(cg);
    };
    if (recipe_.method == Method::ConjugateGradient)
    {
        use_conjugate_gradients();
        return;
    }
    cholesky_ = std::make_unique<SparseCholesky>();
    try
    {
        cholesky_->analyse(a);
    }
    catch (const SolverError& e)
    {
        notes_.push_back(std::string(e.what()) + ": solved by conjugate gradients instead");
        use_conjugate_gradients();
        return;
    }
    const double budget = factor_budget_bytes(recipe_.factor_budget_mb);
    if (cholesky_->stats().factor_bytes() > budget)
    {
        notes_.push_back("the factor would take " +
                         std::to_string(std::lround(cholesky_->stats().factor_bytes() / 1e6)) +
                         " MB, over the factor budget of " +
                         std::to_string(std::lround(budget / 1e6)) +
                         " MB: solved by conjugate gradients instead");
        use_conjugate_gradients();
        return;
    }
    bool positive = false;
    try
    {
        positive = cholesky_->factor(a);
    }
    catch (const SolverError& e)
    {
        notes_.push_back(std::string(e.what()) + ": solved by conjugate gradients instead");
        use_conjugate_gradients();
        return;
    }
    if (!positive)
        throw RecipeError("method",
                          "\"direct\": the system of the free vertices is not positive definite "
                          "in double precision (weights many orders of magnitude apart: closer "
                          "ones make it so)");
}

std::optional<std::string> Session::unheld_part() const
{
    // A free part (connected through edges) is held when it touches a fixed vertex (an
    // edge to one), has an anchor with mu > 0, or a constrained face with mu_f > 0 among
    // its faces: otherwise the edge term is flat along its translations, in every
    // coordinate, and no term adds curvature there.
    const Index nv = vertex_count_;
    std::vector<Index> part(static_cast<size_t>(nv), kInvalidIndex);
    std::vector<char> is_free(static_cast<size_t>(nv), 0);
    for (const Index v : free_)
        is_free[v] = 1;
    std::vector<Index> stack;
    Index parts = 0;
    for (const Index seed : free_)
    {
        if (part[seed] != kInvalidIndex)
            continue;
        bool held = false;
        Index count = 0;
        const auto file_number = [&](Index v) {
            return file_vertex_.empty() ? v : file_vertex_[static_cast<size_t>(v)];
        };
        Index lowest = file_number(seed);
        part[seed] = parts;
        stack.assign(1, seed);
        while (!stack.empty())
        {
            const Index v = stack.back();
            stack.pop_back();
            ++count;
            lowest = std::min(lowest, file_number(v));
            if (soft_ && soft_->weight(v) > 0)
                held = true;
            if (centroid_)
                for (const Index c : topology_->corners_of_vertex(v))
                    if (const Index f = topology_->face_of_corner(c);
                        centroid_->constrains(f) && centroid_->face_weight(f) > 0)
                        held = true;
            for (const Index j : topology_->neighbors(v))
                if (!is_free[j])
                    held = true;
                else if (part[j] == kInvalidIndex)
                {
                    part[j] = parts;
                    stack.push_back(j);
                }
        }
        if (!held)
            return "the free part of " + std::to_string(count) + " vertices that holds vertex " +
                   std::to_string(lowest) +
                   " is held by nothing (no pin, anchor, centroid constraint or fixed "
                   "vertex next to it), so the energy has no unique minimizer; pin a "
                   "vertex of it, anchor it (\"soft\"), or smooth it as part of a region";
        ++parts;
    }
    return std::nullopt;
}

void Session::build_falloff_anchors(const std::vector<char>& fixed,
                                    const std::vector<char>& is_hard)
{
    // Every anchor of a vertex, the soft section's and the falloff's, merges into one:
    // sum_c m_c |x - t_c|^2 = M |x - (sum_c m_c t_c) / M|^2 + const, M = sum_c m_c.
    const Mesh& mesh = *mesh_;
    const Index nv = mesh.vertex_count();
    const std::span<const Scalar> x0 = mesh.positions;
    const Falloff& f = *recipe_.falloff;
    std::vector<Scalar> weight(nv, 0), target_sum(3 * static_cast<size_t>(nv), 0);
    std::vector<Scalar> pin_sum(3 * static_cast<size_t>(nv), 0); // sum of m w (pin moves)
    std::vector<Scalar> pin_share(nv, 0);
    std::vector<Index> pin(nv, kInvalidIndex);
    const auto add = [&](Index v, Scalar m, const Scalar* t) {
        weight[v] += m;
        for (int a = 0; a < 3; ++a)
            target_sum[3 * v + a] += m * t[a];
    };
    if (recipe_.soft)
    {
        const SoftVertices& s = *recipe_.soft;
        const std::vector<Scalar> targets = flatten(s.targets);
        const auto one = [&](Index v, size_t k) {
            const Scalar m = s.weights.empty() ? s.mu : s.mu * s.weights[s.vertices.all ? v : k];
            const Scalar* t = targets.empty()
                                  ? &x0[3 * v]
                                  : &targets[3 * (s.vertices.all ? static_cast<size_t>(v) : k)];
            add(v, m, t);
        };
        if (s.vertices.all)
        {
            for (Index v = 0; v < nv; ++v)
                if (!is_hard[v])
                    one(v, 0);
        }
        else
            for (size_t k = 0; k < s.vertices.indices.size(); ++k)
                one(s.vertices.indices[k], k);
    }
    const Scalar radius =
        f.radius * (f.radius_in_edge_lengths ? mean_edge_length(*topology_, x0) : 1);
    const bool from_border = f.border && recipe_.region, from_pins = f.pins && !hard_.empty();
    if (!from_border && !from_pins)
        notes_.push_back(
            "falloff: no region border or pins to fade from: no anchors fade in "
            "(the whole mesh is free)");
    if (from_border)
    {
        // From the rest's ring around the region: the fixed vertices (not pins) next to a
        // free one.
        std::vector<Index> ring;
        for (Index v = 0; v < nv; ++v)
            if (fixed[v] && !is_hard[v] &&
                std::ranges::any_of(topology_->neighbors(v), [&](Index j) { return !fixed[j]; }))
                ring.push_back(v);
        const SurfaceDistances d = surface_distances(*topology_, x0, ring, radius);
        for (Index v = 0; v < nv; ++v)
            if (!fixed[v])
                if (const Scalar w = falloff_weight(f.curve, d.distance[v], radius); w > 0)
                    add(v, f.mu * w, &x0[3 * v]);
    }
    if (from_pins)
    {
        const SurfaceDistances d = surface_distances(*topology_, x0, hard_, radius);
        for (Index v = 0; v < nv; ++v)
            if (!fixed[v])
                if (const Scalar w = falloff_weight(f.curve, d.distance[v], radius); w > 0)
                {
                    // Toward x0 moved by w times the nearest pin's displacement (set apart,
                    // so that moving the pins moves these targets: set_hard_targets).
                    add(v, f.mu * w, &x0[3 * v]);
                    pin[v] = d.source[v];
                    pin_share[v] = f.mu * w * w;
                }
    }
    std::vector<Index> vertices;
    std::vector<Scalar> weights;
    for (Index v = 0; v < nv; ++v)
        if (!fixed[v] && weight[v] > 0)
        {
            vertices.push_back(v);
            weights.push_back(weight[v]);
            falloff_pin_.push_back(pin[v]);
            for (int a = 0; a < 3; ++a)
                falloff_base_.push_back(target_sum[3 * v + a] / weight[v]);
            falloff_share_.push_back(pin_share[v] / weight[v]);
        }
    if (std::ranges::none_of(falloff_pin_, [](Index k) { return k != kInvalidIndex; }))
        falloff_pin_ = {}; // no pin moves any target
    soft_.emplace(nv, std::move(vertices), Scalar(1), std::span<const Scalar>{}, weights);
    update_falloff_targets();
}

void Session::update_falloff_targets()
{
    if (falloff_pin_.empty())
    {
        soft_->set_targets(falloff_base_);
        return;
    }
    std::vector<Scalar> targets = falloff_base_;
    const std::span<const Scalar> x0 = mesh_->positions;
    for (size_t k = 0; k < falloff_pin_.size(); ++k)
        if (const Index p = falloff_pin_[k]; p != kInvalidIndex && !hard_targets_.empty())
            for (int a = 0; a < 3; ++a)
                targets[3 * k + a] +=
                    falloff_share_[k] * (hard_targets_[3 * p + a] - x0[3 * hard_[p] + a]);
    soft_->set_targets(targets);
}

void Session::invert_blocks()
{
    for (const Index i : free_)
        std::fill_n(&system_.block[6 * i], 6, Scalar(0));
    normal_->add_block(normals_, free_, system_.block);
    // Without joint mode the normals never move: the blocks are inverted in place and the
    // inverses are all a step needs (no second 6 #V array, even while inverting).
    Scalar* inverse = joint_ ? system_.inverse.data() : system_.block.data();
    for (const Index i : free_)
        if (!spd_inverse3(system_.diagonal[i], &system_.block[6 * i], &inverse[6 * i]))
            // Positive definite in exact arithmetic (docs/math.md); in doubles only while
            // the normal term's weights stay within some 1e15 of the diagonal's: a recipe
            // beyond that is refused as the input it is.
            throw RecipeError("normal",
                              "its weights overwhelm the other terms at a vertex: the vertex's "
                              "3x3 system is not positive definite in double precision (a "
                              "smaller mu or smaller per-face weights make it so)");
    if (!joint_)
    {
        system_.inverse = std::move(system_.block);
        if (!normal_shares_)
            system_.diagonal = {}; // in the inverses now; only joint mode inverts again
    }
}

void Session::apply_hard_targets(std::span<Scalar> x) const
{
    for (size_t k = 0; k < hard_.size() && !hard_targets_.empty(); ++k)
        std::copy_n(&hard_targets_[3 * k], 3, &x[3 * hard_[k]]);
}

void Session::set_hard_targets(std::span<const Scalar> targets)
{
    if (targets.size() != 3 * hard_.size())
        throw InvalidInputError("Session::set_hard_targets: expected " +
                                std::to_string(3 * hard_.size()) + " values");
    hard_targets_.assign(targets.begin(), targets.end());
    fixed_constant_valid_ = false;
    if (!falloff_pin_.empty())
        update_falloff_targets(); // the anchors around the pins follow them
}

void Session::set_soft_targets(std::span<const Scalar> targets)
{
    if (!soft_ || targets.size() != 3 * soft_->vertices().size())
        throw InvalidInputError("Session::set_soft_targets: expected 3 values per soft vertex");
    soft_->set_targets(targets);
    fixed_constant_valid_ = false;
}

void Session::set_centroid_targets(std::span<const Scalar> targets)
{
    if (!centroid_ || targets.size() != 3 * centroid_->faces().size())
        throw InvalidInputError(
            "Session::set_centroid_targets: expected 3 values per constrained face");
    centroid_->set_targets(targets);
    fixed_constant_valid_ = false;
}

Index Session::guard_step(std::span<const Scalar> start, std::span<Scalar> x)
{
    // The guard on the step first, then the volume's correction (usually too small to turn
    // a face), checked in turn; when the guard shortens that too, the vertices it shortened
    // stay where it left them and the others restore the volume, a few rounds at most.
    guard_->begin_step(start);
    Index shortened = guard_->limit(start, x);
    if (!volume_)
        return shortened;
    volume_->project(x);
    std::vector<Index> held;
    for (int round = 0;; ++round)
    {
        const Index again = guard_->limit(start, x);
        shortened += again;
        if (again == 0 || round == 3)
            break; // (the last check's shortening leaves the volume to the next step)
        held.insert(held.end(), guard_->shortened().begin(), guard_->shortened().end());
        volume_->project(x, held);
    }
    return shortened;
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
    // The fused kernels hold the paper's terms; the bending term (and the edge term's
    // weight that comes with it) takes the general step.
    return (recipe_.method == Method::Jacobi || recipe_.method == Method::Taubin) &&
           !recipe_.optimal_step && !joint_ && !recipe_.bending;
}

Session::FacePass Session::face_pass(const std::vector<Index>& active, const IndexList& listed)
{
    // faces nullptr: every face, in order (IndexList keeps no list of them).
    if (active.empty())
        return {listed.data(), static_cast<Index>(listed.size())};
    return {active.data(), static_cast<Index>(active.size())};
}

template <bool Soft, bool Centroid, bool Normal, bool Energy>
TermEnergies Session::fused_sweep(const Scalar* x, Scalar* y, Scalar step)
{
    TermEnergies energy;
    // Each constrained face's centroid residual and, on triangles, the normal term's
    // share (FaceNormalTerm::face_share) once per step, summed per face, for the faces a
    // free vertex reads; their corners then add that sum. The normal term's energy is
    // then summed by faces here (fixed_energy adds the faces without a free vertex).
    Scalar* share = face_share_.data();
    const Scalar* normals = normals_.data();
    if constexpr (Centroid && Normal)
        if (shared_face_pass_) // one walk over the faces for both terms
        {
            const FacePass faces = centroid_pass();
            const auto both = [&](Index begin, Index end) {
                Scalar normal_sum = 0;
                TermEnergies part;
                part.centroid = centroid_->face_residuals(
                    x, faces.faces, begin, end, share, [&](Index f) __attribute__((always_inline)) {
                        normal_sum += normal_->face_share<Energy>(x, normals, f, share, true);
                    });
                part.normal = normal_->energy_of_sum(normal_sum);
                return part;
            };
            energy = block_sums_if<Energy, TermEnergies>(faces.count, both);
        }
    if constexpr (Centroid)
        if (!(Normal && shared_face_pass_))
        {
            const FacePass faces = centroid_pass();
            const auto residuals = [&](Index begin, Index end) {
                return centroid_->face_residuals(x, faces.faces, begin, end, share);
            };
            energy.centroid = block_sums_if<Energy, Scalar>(faces.count, residuals);
        }
    if constexpr (Normal)
        if (normal_shares_ && !(Centroid && shared_face_pass_))
        {
            // After the residuals: added to them on the faces the centroid term constrains.
            const FacePass faces = normal_pass();
            const bool add_all = Centroid && centroid_->flags() == nullptr;
            const char* add = Centroid ? centroid_->flags() : nullptr;
            const auto shares = [&](Index begin, Index end) {
                return normal_->face_shares<Energy>(x, normals, faces.faces, begin, end, share,
                                                    add_all, add);
            };
            energy.normal = block_sums_if<Energy, Scalar>(faces.count, shares);
        }
    // The soft and centroid terms weigh their elements through per-vertex weights and
    // per-face residuals; only the normal term's sweep differs with weights.
    const bool all_free = free_.size() == static_cast<size_t>(vertex_count_);
    const bool weighted = Normal && normal_->has_weights();
    const Index count = static_cast<Index>(free_.size());
    // Energy: the ranges are deterministic_block_sums' blocks, so that the sums are the
    // same for any thread count; otherwise one range per thread.
    const auto sweep = [&](auto range) {
        energy += block_sums_if<Energy, TermEnergies>(count, range);
    };
    if (weighted && all_free)
        sweep([=, this](Index begin, Index end) {
            return fused_range<Soft, Centroid, Normal, true, true, Energy>(x, y, step, begin, end);
        });
    else if (weighted)
        sweep([=, this](Index begin, Index end) {
            return fused_range<Soft, Centroid, Normal, true, false, Energy>(x, y, step, begin, end);
        });
    else if (all_free)
        sweep([=, this](Index begin, Index end) {
            return fused_range<Soft, Centroid, Normal, false, true, Energy>(x, y, step, begin, end);
        });
    else
        sweep([=, this](Index begin, Index end) {
            return fused_range<Soft, Centroid, Normal, false, false, Energy>(x, y, step, begin,
                                                                             end);
        });
    return energy;
}

template <bool Soft, bool Centroid, bool Normal, bool NormalWeighted, bool AllFree, bool Energy>
TermEnergies Session::fused_range(const Scalar* x, Scalar* y, Scalar step, Index begin,
                                  Index end) const
{
    // Locals: the loop keeps them in registers (the stores to y could change the
    // session's members for the compiler, which would then load them again).
    const Index* free = free_.data();
    const Scalar* normals = normals_.data();
    const Scalar* inverse = system_.inverse.data();
    const Scalar* diagonal = system_.diagonal.data();
    const Scalar* share = face_share_.data();
    const char* share_flag = share_flag_;
    const bool normal_shares = normal_shares_;
    const CornerWalk walk(*mesh_, *topology_);
    const EdgeTerm& edge = edge_;
    const Scalar centre[3] = {energy_centre_[0], energy_centre_[1], energy_centre_[2]};
    // The range's vertices' parts of the energy, each term summed vertex by vertex.
    Scalar e_edge = 0, e_soft = 0, e_normal = 0;
    for (Index k = begin; k < end; ++k)
    {
        // Every vertex free (no region, no pins): the free list is 0, 1, ... and is not
        // read (4 bytes per vertex less to stream).
        const Index i = AllFree ? k : free[k];
        // 64 bits before the multiplications: one addressing mode each.
        const std::ptrdiff_t at = 3 * static_cast<std::ptrdiff_t>(i);
        Scalar r[3] = {0, 0, 0};
        edge.add_vertex_rhs(i, x, r);
        if constexpr (Energy) // r holds the edge term's part only here
            e_edge += EdgeTerm::vertex_part(x + at, r, centre);
        if constexpr (Soft)
            soft_->add_vertex_rhs<Energy>(i, x, r, &e_soft);
        if constexpr (Centroid || Normal)
            if (Centroid || normal_shares)
                add_corner_shares(*topology_, walk, share_flag, share, i, r);
        if constexpr (Normal)
            if (!normal_shares) // polygons: the corners' parts one by one
                normal_->add_vertex_rhs<NormalWeighted, Energy>(i, x, normals, r, &e_normal);
        Scalar dx[3];
        if constexpr (Normal) // the Jacobi method has 3x3 blocks exactly when normals are on
        {
            if (normal_shares)
            {
                // The normal term's c is the energy's centre (precompute gives it).
                const Scalar e[3] = {x[at] - centre[0], x[at + 1] - centre[1],
                                     x[at + 2] - centre[2]};
                solve_less_block(&inverse[2 * at], diagonal[i], e, r, dx);
            }
            else
                symmetric3_apply(&inverse[2 * at], r, dx);
        }
        else
        {
            const Scalar inv = Scalar(1) / diagonal[i];
            for (int a = 0; a < 3; ++a)
                dx[a] = r[a] * inv;
        }
        for (int a = 0; a < 3; ++a)
            y[at + a] = x[at + a] + step * dx[a];
    }
    TermEnergies energy;
    energy.edge = e_edge;
    energy.soft = e_soft;
    energy.normal = e_normal;
    return energy;
}

void Session::add_vertex_parts(const Scalar* x, Index i, TermEnergies& e) const
{
    e.edge += edge_.vertex_part(i, x, energy_centre_.data());
    if (soft_)
        e.soft += soft_->vertex_part(i, x);
    if (normal_ && !normal_shares_) // else counted by faces (fused_sweep, fixed_energy)
        e.normal += normal_->vertex_part(i, x, normals_.data());
}

TermEnergies Session::vertex_parts(const Scalar* x, std::span<const Index> vertices) const
{
    return deterministic_block_sums<TermEnergies>(static_cast<Index>(vertices.size()),
                                                  [&](Index begin, Index end) {
                                                      TermEnergies e;
                                                      for (Index k = begin; k < end; ++k)
                                                          add_vertex_parts(x, vertices[k], e);
                                                      return e;
                                                  });
}

TermEnergies Session::fixed_energy(const Scalar* x)
{
    if (!fixed_constant_valid_)
    {
        // Every fixed vertex that is not on the border, in order: the free list and the
        // border are ascending.
        fixed_constant_ = {};
        size_t next_free = 0, next_border = 0;
        for (Index i = 0; i < vertex_count_; ++i)
        {
            if (next_free < free_.size() && free_[next_free] == i)
            {
                ++next_free;
                continue;
            }
            if (next_border < energy_border_.size() && energy_border_[next_border] == i)
            {
                ++next_border;
                continue;
            }
            add_vertex_parts(x, i, fixed_constant_);
        }
        if (!centroid_inactive_.empty())
            fixed_constant_.centroid = centroid_->face_residuals(
                x, centroid_inactive_.data(), 0, static_cast<Index>(centroid_inactive_.size()),
                face_share_.data());
        if (!normal_inactive_.empty())
            fixed_constant_.normal =
                normal_->face_energies(x, normals_.data(), normal_inactive_.data(), 0,
                                       static_cast<Index>(normal_inactive_.size()));
        fixed_constant_valid_ = true;
    }
    TermEnergies energy = fixed_constant_;
    if (!energy_border_.empty())
        energy += vertex_parts(x, energy_border_);
    return energy;
}

namespace {

using FusedSweep = TermEnergies (Session::*)(const Scalar*, Scalar*, Scalar);

} // namespace

TermEnergies Session::fused_step(std::span<const Scalar> x, std::span<Scalar> y, bool energy,
                                 Scalar step)
{
    // One instance per combination of terms: bit 0 soft, bit 1 centroid, bit 2 normal,
    // bit 3 the energy.
    static constexpr std::array<FusedSweep, 16> sweeps = []<size_t... I>(std::index_sequence<I...>)
    {
        return std::array<FusedSweep, 16>{
            &Session::fused_sweep<(I & 1) != 0, (I & 2) != 0, (I & 4) != 0, (I & 8) != 0>...};
    }
    (std::make_index_sequence<16>{});
    const size_t which =
        (soft_ ? 1 : 0) | (centroid_ ? 2 : 0) | (normal_ ? 4 : 0) | (energy ? 8 : 0);
    TermEnergies e = (this->*sweeps[which])(x.data(), y.data(), step);
    if (energy)
    {
        // The fixed parts after the sweep's (a sum's order: free, then fixed).
        e += fixed_energy(x.data());
    }
    return e;
}

void Session::set_positions(std::span<const Scalar> x)
{
    check_size(x, "set_positions");
    has_positions_ = true;
    fixed_constant_valid_ = false;
    can_revert_ = false;
    x_.assign(x.begin(), x.end());
    if (fused())
        next_.assign(x.begin(), x.end()); // the vertices a step never writes agree
}

void Session::adopt_positions(std::vector<Scalar>&& x)
{
    check_size(x, "adopt_positions");
    has_positions_ = true;
    fixed_constant_valid_ = false;
    can_revert_ = false;
    x_ = std::move(x);
    if (fused())
        next_.assign(x_.begin(), x_.end()); // the vertices a step never writes agree
}

std::vector<Scalar> Session::release_positions()
{
    std::vector<Scalar> out;
    out.swap(x_);
    has_positions_ = false;
    fixed_constant_valid_ = false;
    can_revert_ = false;
    return out;
}

StepInfo Session::step()
{
    if (!has_positions_)
        throw SolverError("Session::step: no positions (call set_positions first)");
    can_revert_ = false;
    if (!fused())
        return general_step(x_);
    const bool taubin = recipe_.method == Method::Taubin;
    if (guard_ && taubin) // the second pass overwrites the buffer the first one read
        std::copy(x_.begin(), x_.end(), guard_start_.begin());
    fused_step(x_, next_, false, recipe_.lambda);
    std::swap(x_, next_);
    if (taubin)
    {
        // The second of Taubin's steps, from the first one's positions, as general_step
        // takes it. The positions before both are gone: nothing to revert to.
        fused_step(x_, next_, false, recipe_.taubin_mu);
        std::swap(x_, next_);
    }
    StepInfo info{recipe_.lambda};
    if (guard_) // the Jacobi step read next_, which the step left as it was
        info.shortened = guard_step(taubin ? std::span<const Scalar>(guard_start_) : next_, x_);
    else if (volume_)
        volume_->project(x_);
    can_revert_ = !taubin;
    return info;
}

StepInfo Session::step(TermEnergies& before)
{
    if (!has_positions_)
        throw SolverError("Session::step: no positions (call set_positions first)");
    can_revert_ = false;
    if (!fuses_energy())
    {
        before = energy();
        return step();
    }
    before = fused_step(x_, next_, true, recipe_.lambda);
    std::swap(x_, next_);
    StepInfo info{recipe_.lambda};
    if (guard_)
        info.shortened = guard_step(next_, x_);
    else if (volume_)
        volume_->project(x_);
    can_revert_ = true;
    return info;
}

void Session::revert_step()
{
    if (!can_revert_)
        throw SolverError("Session::revert_step: no fused step to undo");
    // The buffer the step read is untouched: it wrote the other one (the free vertices;
    // the fixed ones agree in both).
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
    if (solves_linear_system(recipe_.method))
        return direct_step(x);
    const bool use_blocks = !system_.inverse.empty();
    if (joint_ && use_blocks)
        invert_blocks(); // the normals moved in the previous step
    if (guard_)
    {
        guard_start_.resize(x.size()); // a fused session's first general step allocates
        std::copy(x.begin(), x.end(), guard_start_.begin());
    }

    assemble_displacements(x, use_blocks);
    StepInfo info;
    if (recipe_.method == Method::Taubin)
    {
        // lambda, then mu < -lambda from the new positions: Taubin's two passes.
        apply_displacements(free_, dx_, recipe_.lambda, x);
        assemble_displacements(x, use_blocks);
        apply_displacements(free_, dx_, recipe_.taubin_mu, x);
        info.lambda = recipe_.lambda;
        if (guard_)
            info.shortened = guard_step(guard_start_, x);
        else if (volume_)
            volume_->project(x);
        return info;
    }
    info.lambda = recipe_.lambda;
    if (recipe_.optimal_step)
    {
        Scalar q = edge_.quadratic(dx_);
        if (bending_)
            q += bending_->quadratic(dx_);
        if (soft_)
            q += soft_->quadratic(dx_);
        if (centroid_)
            q += centroid_->quadratic(dx_);
        if (normal_)
            q += normal_->quadratic(dx_, normals_);
        info.lambda = optimal_step(rhs_dot(system_, free_, dx_), q);
    }
    // Joint mode updates u from the old x and old u, like x: one Jacobi step on both.
    // The line search is exact for x with u held; u never steps past its minimizer.
    if (joint_)
    {
        // Bilateral weights: a new stage of the robust energy every reweight_every steps
        // (the first stage's weights come from the precomputation).
        if (bilateral_ && joint_steps_ > 0 && joint_steps_ % bilateral_->reweight_every() == 0)
            bilateral_->reweight(x, normals_);
        ++joint_steps_;
        joint_->update_normals(x, normals_, std::min<Scalar>(info.lambda, 1), scratch_u_);
    }
    apply_displacements(free_, dx_, info.lambda, x);
    if (guard_)
        info.shortened = guard_step(guard_start_, x);
    else if (volume_)
        volume_->project(x);
    return info;
}

StepInfo Session::direct_step(std::span<Scalar> x)
{
    if (guard_)
    {
        guard_start_.resize(x.size());
        std::copy(x.begin(), x.end(), guard_start_.begin());
    }
    assemble_rhs(x);
    // r_f in the solver's order: by vertex with blocks, else by coordinate (3 columns).
    const Index n = static_cast<Index>(free_.size());
    const auto at = [&](Index k, int a) {
        return direct_blocks_ ? 3 * static_cast<size_t>(k) + a
                              : static_cast<size_t>(a) * static_cast<size_t>(n) + k;
    };
    parallel_for(n, [&](Index k) {
        for (int a = 0; a < 3; ++a)
            direct_rhs_[at(k, a)] = system_.rhs[3 * static_cast<size_t>(free_[k]) + a];
    });
    StepInfo info;
    info.lambda = 1;
    info.gradient = rhs_norm();
    if (cholesky_)
        cholesky_->solve(direct_rhs_, direct_blocks_ ? 1 : 3);
    else
    {
        // A d = r from d = 0 (the step starts at the current positions, the last solution):
        // one solve of 3 #free unknowns with blocks, else one per coordinate.
        const size_t m = static_cast<size_t>(cg_->a.size);
        std::vector<Scalar> b(m);
        for (size_t c = 0; c * m < direct_rhs_.size(); ++c)
        {
            const std::span<Scalar> d(direct_rhs_.data() + c * m, m);
            std::copy(d.begin(), d.end(), b.begin());
            std::fill(d.begin(), d.end(), Scalar(0));
            const ConjugateGradientResult r = conjugate_gradient(
                cg_->a, cg_->inverse, cg_->block, b, d, kConjugateGradientTolerance,
                static_cast<int>(std::min<size_t>(4 * m + 100, 1000000)));
            info.inner_iterations += r.iterations;
        }
    }
    parallel_for(n, [&](Index k) {
        for (int a = 0; a < 3; ++a)
            x[3 * static_cast<size_t>(free_[k]) + a] += direct_rhs_[at(k, a)];
    });
    if (guard_)
        info.shortened = guard_direct_step(guard_start_, x);
    if (volume_) // an implicit step's (the minimizer's methods take no volume)
        volume_->project(x);
    return info;
}

Index Session::guard_direct_step(std::span<const Scalar> start, std::span<Scalar> x)
{
    // The whole step shortened by one factor, t = 1, 1/2, ..., 1/2^20, then 0: the energy is
    // a convex quadratic along the step to its minimizer, so it falls for every t in (0, 1]
    // (the guard's per-vertex shortening, right for Jacobi steps, could raise it here). The
    // shape is judged as it stands (FlipGuard::turned_after_jump), not against the noisy
    // surroundings the jump starts from.
    guard_->begin_jump(start);
    if (guard_->turned_after_jump(x) == 0)
        return 0;
    const std::vector<Scalar> full(x.begin(), x.end()); // the whole step, rarely needed
    Scalar t = 1;
    for (int halving = 1; halving <= 20; ++halving)
    {
        t *= 0.5;
        parallel_for(static_cast<Index>(free_.size()), [&](Index k) {
            const size_t i = 3 * static_cast<size_t>(free_[k]);
            for (int a = 0; a < 3; ++a)
                x[i + a] = start[i + a] + t * (full[i + a] - start[i + a]);
        });
        if (guard_->turned_after_jump(x) == 0)
            return static_cast<Index>(free_.size());
    }
    std::copy(start.begin(), start.end(), x.begin());
    return static_cast<Index>(free_.size());
}

void Session::assemble_rhs(std::span<const Scalar> x)
{
    if (system_.rhs.size() != 3 * static_cast<size_t>(vertex_count_))
        system_.rhs.assign(3 * static_cast<size_t>(vertex_count_), 0); // a fused session
    parallel_for(static_cast<Index>(free_.size()),
                 [&](Index k) { std::fill_n(&system_.rhs[3 * free_[k]], 3, Scalar(0)); });
    edge_.add_rhs(x, free_, system_.rhs);
    if (bending_)
        bending_->add_rhs(x, system_.rhs);
    if (soft_)
        soft_->add_rhs(x, free_, system_.rhs);
    if (centroid_)
        centroid_->add_rhs(x, free_, system_.rhs);
    if (normal_)
        normal_->add_rhs(x, normals_, free_, system_.rhs);
}

Scalar Session::rhs_norm() const
{
    return std::sqrt(deterministic_sum(static_cast<Index>(free_.size()), [&](Index k) {
        const Scalar* r = &system_.rhs[3 * static_cast<size_t>(free_[k])];
        return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    }));
}

Session::Residual Session::residual(std::span<const Scalar> x)
{
    check_size(x, "residual");
    Residual out;
    assemble_rhs(x);
    out.gradient = rhs_norm();
    if (free_.empty())
        return out;
    if (dx_.size() != 3 * static_cast<size_t>(vertex_count_))
        dx_.assign(3 * static_cast<size_t>(vertex_count_), 0);
    jacobi_displacements(system_, free_, !system_.inverse.empty(), dx_);
    for (const Index i : free_)
    {
        const Scalar* d = &dx_[3 * static_cast<size_t>(i)];
        out.jacobi_displacement =
            std::max(out.jacobi_displacement, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
    return out;
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
    std::fill(per_vertex.begin(), per_vertex.end(), Scalar(0));
    const bool all = term == EnergyTerm::Total;
    if (all || term == EnergyTerm::Edge)
        edge_.add_vertex_energy(x, per_vertex);
    if (soft_ && (all || term == EnergyTerm::Soft))
        soft_->add_vertex_energy(x, per_vertex);
    if (centroid_ && (all || term == EnergyTerm::Centroid))
        centroid_->add_vertex_energy(x, per_vertex);
    if (normal_ && (all || term == EnergyTerm::Normal))
        normal_->add_vertex_energy(x, normals_, per_vertex);
    if (bending_ && (all || term == EnergyTerm::Bending))
        bending_->add_vertex_energy(x, per_vertex);
}

TermEnergies Session::energy(std::span<const Scalar> x) const
{
    TermEnergies e;
    e.edge = edge_.energy(x);
    if (bending_)
        e.bending = bending_->energy(x);
    if (soft_)
        e.soft = soft_->energy(x);
    if (centroid_)
        e.centroid = centroid_->energy(x);
    if (normal_)
        e.normal = normal_->energy(x, normals_);
    if (joint_)
    {
        e.normal_smoothing = joint_->dual_energy(normals_);
        e.normal_soft = smoothing_->soft_energy(normals_);
    }
    return e;
}

SmoothResult run(Session& session, std::span<Scalar> x,
                 const std::function<void(int, const TermEnergies&)>& on_step)
{
    session.set_positions(x);
    SmoothResult result = run(session, on_step);
    const std::span<const Scalar> kept = session.positions();
    std::copy(kept.begin(), kept.end(), x.begin());
    return result;
}

SmoothResult run(Session& session, const std::function<void(int, const TermEnergies&)>& on_step)
{
    if (!session.has_positions())
        throw SolverError("run: the session keeps no positions (call set_positions first)");
    SmoothResult result;
    const Recipe& recipe = session.recipe();
    const auto record = [&](const TermEnergies& e) {
        result.energies.push_back(e);
        if (on_step)
            on_step(static_cast<int>(result.energies.size()) - 1, e);
    };
    if (solves_for_minimizer(recipe.method))
    {
        // Each step solves for the minimizer from where it starts; the rule is the
        // gradient's, relative to the input's.
        DirectConvergence rule(recipe.tolerance);
        record(session.energy());
        for (int k = 0; k < recipe.iterations; ++k)
        {
            const StepInfo info = session.step();
            result.lambdas.push_back(info.lambda);
            result.shortened.push_back(info.shortened);
            result.inner_iterations.push_back(info.inner_iterations);
            ++result.iterations;
            record(session.energy());
            // r at the new positions, once: the stopping rule's gradient and the report's
            // Jacobi displacement.
            const Session::Residual residual = session.residual(session.positions());
            result.jacobi_displacement = residual.jacobi_displacement;
            const bool stop = rule.stop_after(info.gradient, residual.gradient);
            result.gradients.push_back(rule.relative());
            if (stop)
            {
                result.stopped_by_tolerance = true;
                break;
            }
        }
        return result;
    }
    if (!session.fuses_energy())
    {
        record(session.energy());
        for (int k = 0; k < recipe.iterations; ++k)
        {
            const StepInfo info = session.step();
            result.lambdas.push_back(info.lambda);
            result.shortened.push_back(info.shortened);
            ++result.iterations;
            record(session.energy());
            if (converged(result.energies[k].total(), result.energies[k + 1].total(),
                          recipe.tolerance))
            {
                result.stopped_by_tolerance = true;
                break;
            }
        }
        return result;
    }
    // The fused step computes E(x_k) in the sweep that computes x_{k+1}: the tolerance
    // learns one step late that step k converged, and that step's successor is undone.
    // One pass over the mesh a step, and one for the last energy.
    for (int k = 0; k < recipe.iterations; ++k)
    {
        TermEnergies before;
        const StepInfo info = session.step(before);
        record(before);
        if (k > 0 &&
            converged(result.energies[k - 1].total(), result.energies[k].total(), recipe.tolerance))
        {
            session.revert_step();
            result.stopped_by_tolerance = true;
            return result;
        }
        result.lambdas.push_back(info.lambda);
        result.shortened.push_back(info.shortened);
        ++result.iterations;
    }
    record(session.energy());
    if (result.iterations > 0 &&
        converged(result.energies[result.iterations - 1].total(),
                  result.energies[result.iterations].total(), recipe.tolerance))
        result.stopped_by_tolerance = true;
    return result;
}

SmoothResult smooth(Mesh& mesh, const Topology& topology, const Recipe& recipe)
{
    Session session(mesh, topology, recipe);
    session.apply_hard_targets(mesh.positions);
    return run(session, mesh.positions);
}

} // namespace meshfair
