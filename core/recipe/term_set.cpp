// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/term_set.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "core/energies/falloff.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"

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

FixedVertices fixed_vertices(const Recipe& recipe, const Mesh& mesh)
{
    const Index nv = mesh.vertex_count();
    FixedVertices out;
    out.hard.assign(nv, 0);
    if (recipe.hard)
        for (const Index v : recipe.hard->vertices)
            out.hard[v] = 1;
    out.fixed = out.hard;
    if (recipe.region)
    {
        std::vector<char> inside(nv, 0);
        for (const Index v : recipe.region->vertices)
            inside[v] = 1;
        for (const Index f : recipe.region->faces)
            for (const Index v : mesh.face(f))
                inside[v] = 1;
        for (Index v = 0; v < nv; ++v)
            out.fixed[v] = out.fixed[v] || !inside[v];
    }
    return out;
}

TermSet::TermSet(const Mesh& mesh, const Topology& topology, const Recipe& recipe,
                 const std::vector<char>& fixed, const std::vector<char>& is_hard,
                 std::span<const Index> hard, std::span<const Scalar> hard_targets,
                 const Vec3& centre)
    : mesh_(&mesh), topology_(&topology), recipe_(&recipe), edge_(topology)
{
    if (topology.vertex_count != mesh.vertex_count() || topology.face_count != mesh.face_count())
        throw SolverError("Session: the topology was built for another mesh");
    if (!has_parts(topology.parts, required_topology(recipe)))
        throw SolverError(
            "Session: the topology lacks parts this recipe needs (build it "
            "with required_topology(recipe))");
    const std::span<const Scalar> x0 = mesh.positions;
    // The terms take their index lists by move, and targets at the initial positions (the
    // default of soft and centroid constraints) are read from one copy of them shared by
    // both terms: no gathered or per-term copies (a million-vertex mesh would keep their
    // pages resident). A copy, not the mesh's positions: a session may step those
    // (Session::adopt_positions).
    const bool soft_at_x0 = !recipe.falloff && recipe.soft && recipe.soft->targets.empty();
    const bool centroids_at_x0 = recipe.centroid && recipe.centroid->targets.empty();
    if (soft_at_x0 || centroids_at_x0)
        initial_.assign(x0.begin(), x0.end());
    if (recipe.falloff)
    {
        build_falloff_anchors(fixed, is_hard, hard);
        update_falloff_targets(hard_targets);
    }
    else if (recipe.soft)
        build_soft(is_hard);
    if (recipe.centroid)
    {
        const CentroidConstraints& c = *recipe.centroid;
        centroid_.emplace(mesh, topology,
                          c.faces.all ? all_indices(mesh.face_count()) : c.faces.indices, c.mu,
                          c.denominator, c.weights);
        if (c.targets.empty())
            centroid_->use_centroids_of(initial_);
        else
            centroid_->set_targets(flatten(c.targets));
    }
    if (recipe.normal)
        build_normal_terms(centre);
    if (recipe.volume)
    {
        volume_.emplace(mesh, topology, x0, fixed, recipe.volume->open,
                        recipe.volume->free_components_only);
        notes_.insert(notes_.end(), volume_->notes().begin(), volume_->notes().end());
    }
    edge_.set_weight(recipe.bending ? recipe.bending->membrane : Scalar(1));
    if (recipe.bending)
        bending_.emplace(topology, recipe.bending->mu);

    // The registration: every sum over the terms takes this order.
    position_terms_.push_back(&edge_);
    if (bending_)
        position_terms_.push_back(&*bending_);
    if (soft_)
        position_terms_.push_back(&*soft_);
    if (centroid_)
        position_terms_.push_back(&*centroid_);
    if (normal_)
        position_terms_.push_back(&*normal_);
}

void TermSet::build_soft(const std::vector<char>& is_hard)
{
    const SoftVertices& s = *recipe_->soft;
    const Index nv = mesh_->vertex_count();
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

void TermSet::build_normal_terms(const Vec3& centre)
{
    const Mesh& mesh = *mesh_;
    const std::span<const Scalar> x0 = mesh.positions;
    const NormalConstraints& n = *recipe_->normal;
    std::vector<Index> faces = n.faces.all ? all_indices(mesh.face_count()) : n.faces.indices;
    normals_ = face_normals(mesh, x0);
    const NormalSmoothing ns = recipe_->normal_smoothing.value_or(NormalSmoothing{});
    // The smoothing constraints' normals default to the initial ones: gathered before
    // normals_ (the initial normals until here) gets the custom directions.
    const std::vector<Scalar> hard_normals =
        ns.hard.normals.empty() ? gather3(normals_, ns.hard.faces) : unit_normals(ns.hard.normals);
    const std::vector<Scalar> soft_normals =
        ns.soft.normals.empty() ? gather3(normals_, ns.soft.faces) : unit_normals(ns.soft.normals);
    if (n.source == NormalSource::Custom)
    {
        const std::vector<Scalar> given = unit_normals(n.normals);
        for (size_t k = 0; k < faces.size(); ++k)
            std::copy_n(&given[3 * k], 3, &normals_[3 * faces[k]]);
    }
    normal_.emplace(mesh, *topology_, std::move(faces), n.mu, n.weights, centre);
    normal_->view_normals(normals_);
    smoothing_.emplace(*topology_, ns.hard.faces, hard_normals, ns.soft.faces, ns.soft.mu,
                       soft_normals, ns.soft.weights);
    smoothing_->apply_hard(normals_);
    const bool smooths = n.source == NormalSource::Smoothed || recipe_->joint;
    // Scratch normals for normal smoothing and the joint update only.
    if (smooths)
        scratch_u_.assign(3 * static_cast<size_t>(mesh.face_count()), 0);
    if (smooths && ns.bilateral)
    {
        bilateral_.emplace(mesh, *topology_, *ns.bilateral, x0);
        bilateral_->reweight(x0, normals_);
        smoothing_->set_weights(&*bilateral_);
    }
    smoothing_iterations_ = ns.iterations;
    if (n.source == NormalSource::Smoothed && ns.adaptive)
    {
        // The noise of the vertices whose faces the normal term holds.
        std::vector<char> counted(static_cast<size_t>(mesh.vertex_count()), 0);
        for (const Index f : normal_->faces())
            for (const Index v : mesh.face(f))
                counted[v] = 1;
        noise_ = estimate_noise(mesh, *topology_, x0, counted);
        const Scalar wanted = ns.adaptive->per_noise * ns.adaptive->strength * noise_->sigma;
        smoothing_iterations_ =
            static_cast<int>(std::lround(std::clamp<Scalar>(wanted, 1, kMaxAdaptiveIterations)));
        char note[160];
        std::snprintf(note, sizeof note,
                      "normal smoothing: noise of %.3g mean edge lengths found in the mesh: %d "
                      "iterations (strength %.3g)",
                      noise_->sigma, smoothing_iterations_, ns.adaptive->strength);
        notes_.push_back(note);
    }
    if (n.source == NormalSource::Smoothed)
    {
        // Normal smoothing first, then integration of the smoothed normals through the
        // face-normal term (the paper's two-stage process). With bilateral weights the
        // trace follows the robust energy that the reweighting lowers.
        const auto smoothing_energy = [&] {
            return (bilateral_ ? bilateral_->robust_energy(normals_)
                               : smoothing_->dual_energy(normals_)) +
                   smoothing_->soft_energy(normals_);
        };
        smoothing_trace_.push_back(smoothing_energy());
        for (int k = 0; k < smoothing_iterations_; ++k)
        {
            if (bilateral_ && k > 0 && k % bilateral_->reweight_every() == 0)
                bilateral_->reweight(x0, normals_);
            smoothing_->step(normals_, ns.lambda, scratch_u_);
            smoothing_trace_.push_back(smoothing_energy());
        }
    }
    if (recipe_->joint)
        joint_.emplace(*normal_, *smoothing_, *topology_, recipe_->joint->gamma);
}

void TermSet::build_falloff_anchors(const std::vector<char>& fixed,
                                    const std::vector<char>& is_hard, std::span<const Index> hard)
{
    // Every anchor of a vertex, the soft section's and the falloff's, merges into one:
    // sum_c m_c |x - t_c|^2 = M |x - (sum_c m_c t_c) / M|^2 + const, M = sum_c m_c.
    const Mesh& mesh = *mesh_;
    const Index nv = mesh.vertex_count();
    const std::span<const Scalar> x0 = mesh.positions;
    const Falloff& f = *recipe_->falloff;
    hard_.assign(hard.begin(), hard.end());
    std::vector<Scalar> weight(nv, 0), target_sum(3 * static_cast<size_t>(nv), 0);
    std::vector<Scalar> pin_share(nv, 0);
    std::vector<Index> pin(nv, kInvalidIndex);
    const auto add = [&](Index v, Scalar m, const Scalar* t) {
        weight[v] += m;
        for (int a = 0; a < 3; ++a)
            target_sum[3 * v + a] += m * t[a];
    };
    if (recipe_->soft)
    {
        const SoftVertices& s = *recipe_->soft;
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
    const bool from_border = f.border && recipe_->region, from_pins = f.pins && !hard_.empty();
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
                    // so that moving the pins moves these targets: move_pins).
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
}

void TermSet::update_falloff_targets(std::span<const Scalar> hard_targets)
{
    if (falloff_pin_.empty())
    {
        soft_->set_targets(falloff_base_);
        return;
    }
    std::vector<Scalar> targets = falloff_base_;
    const std::span<const Scalar> x0 = mesh_->positions;
    for (size_t k = 0; k < falloff_pin_.size(); ++k)
        if (const Index p = falloff_pin_[k]; p != kInvalidIndex && !hard_targets.empty())
            for (int a = 0; a < 3; ++a)
                targets[3 * k + a] +=
                    falloff_share_[k] * (hard_targets[3 * p + a] - x0[3 * hard_[p] + a]);
    soft_->set_targets(targets);
}

void TermSet::move_pins(std::span<const Scalar> hard_targets)
{
    if (!falloff_pin_.empty())
        update_falloff_targets(hard_targets); // the anchors around the pins follow them
}

void TermSet::set_soft_targets(std::span<const Scalar> targets)
{
    if (!soft_ || targets.size() != 3 * soft_->vertices().size())
        throw InvalidInputError("Session::set_soft_targets: expected 3 values per soft vertex");
    soft_->set_targets(targets);
}

void TermSet::set_centroid_targets(std::span<const Scalar> targets)
{
    if (!centroid_ || targets.size() != 3 * centroid_->faces().size())
        throw InvalidInputError(
            "Session::set_centroid_targets: expected 3 values per constrained face");
    centroid_->set_targets(targets);
}

void TermSet::set_free(std::span<const Index> free)
{
    if (bending_)
        bending_->set_free(free);
}

TermEnergies TermSet::energy(std::span<const Scalar> x) const
{
    TermEnergies e;
    for (const PositionTerm* term : position_terms_)
        e.at(term->kind()) = term->energy(x);
    if (joint_)
    {
        e.normal_smoothing = joint_->dual_energy(normals_);
        e.normal_soft = smoothing_->soft_energy(normals_);
    }
    return e;
}

void TermSet::vertex_energy(std::span<const Scalar> x, EnergyTerm term,
                            std::span<Scalar> per_vertex) const
{
    std::fill(per_vertex.begin(), per_vertex.end(), Scalar(0));
    for (const PositionTerm* t : position_terms_)
        if (term == EnergyTerm::Total || term == t->kind())
            t->add_vertex_energy(x, per_vertex);
}

TermEnergies TermSet::held_energy(std::span<const Scalar> x, std::span<const char> is_free) const
{
    TermEnergies e;
    for (const PositionTerm* t : position_terms_)
        e.at(t->kind()) = t->held_energy(x, is_free);
    return e;
}

void TermSet::add_diagonal(std::span<Scalar> diagonal) const
{
    for (const PositionTerm* term : position_terms_)
        term->add_diagonal(diagonal);
}

void TermSet::add_rhs(std::span<const Scalar> x, std::span<const Index> free,
                      std::span<Scalar> rhs) const
{
    for (const PositionTerm* term : position_terms_)
        term->add_rhs(x, free, rhs);
}

void TermSet::add_hessian_column(Index i, HessianColumn& column) const
{
    for (const PositionTerm* term : position_terms_)
        term->add_hessian_column(i, column);
}

SymmetricMatrix TermSet::free_hessian(std::span<const Index> free, bool blocks, Scalar shift) const
{
    return assemble_free_hessian(topology_->vertex_count, free, blocks,
                                 [&](Index i, HessianColumn& column) {
                                     if (shift != 0) // (the implicit method's I / t)
                                         column.add(i, shift);
                                     add_hessian_column(i, column);
                                 });
}

std::unique_ptr<FreeSystemSolver> TermSet::factor(std::span<const Index> free,
                                                  std::span<const Index> file_vertex,
                                                  std::vector<std::string>& notes,
                                                  std::unique_ptr<SparseCholesky> analysed) const
{
    // With the normal term the coordinates couple (u u^T): one system of 3 #free unknowns.
    // Without it the matrix is the same for x, y and z: #free unknowns, 3 right-hand sides.
    const bool blocks = normal_.has_value();
    // Checked before the factorization, which may well factor a singular matrix in
    // doubles (a pivot of rounding size) and return garbage. An implicit step's matrix,
    // I / t + A_ff, is positive definite whatever holds the mesh.
    const Recipe& recipe = *recipe_;
    const bool implicit = recipe.method == Method::Implicit;
    if (!implicit)
        if (const std::optional<std::string> why = unheld_part(free, file_vertex))
            throw RecipeError(
                "method", (recipe.method == Method::Direct ? "\"direct\": " : "\"cg\": ") + *why);
    const SymmetricMatrix a = free_hessian(free, blocks, implicit ? 1 / recipe.time : 0);
    try
    {
        return std::make_unique<FreeSystemSolver>(
            a, blocks ? 3 : 1, recipe.method == Method::ConjugateGradient,
            recipe.factor_budget_mb * 1e6, notes, std::move(analysed));
    }
    catch (const NotPositiveDefiniteError& e)
    {
        throw RecipeError("method", (e.factored() ? "\"direct\": " : "") + std::string(e.what()));
    }
}

Scalar TermSet::quadratic(std::span<const Scalar> dx) const
{
    Scalar q = 0;
    for (const PositionTerm* term : position_terms_)
        q += term->quadratic(dx);
    return q;
}

void TermSet::add_blocks(std::span<const Index> vertices, std::span<Scalar> block) const
{
    if (normal_)
        normal_->add_block(normals_, vertices, block);
}

void TermSet::update_normals(std::span<const Scalar> x, Scalar lambda)
{
    // Bilateral weights: a new stage of the robust energy every reweight_every steps (the
    // first stage's weights come from the construction).
    if (bilateral_ && joint_steps_ > 0 && joint_steps_ % bilateral_->reweight_every() == 0)
        bilateral_->reweight(x, normals_);
    ++joint_steps_;
    joint_->update_normals(x, normals_, lambda, scratch_u_);
}

std::optional<std::string> TermSet::unheld_part(std::span<const Index> free,
                                                std::span<const Index> file_vertex) const
{
    // A free part (connected through edges) is held when it touches a fixed vertex (an
    // edge to one), has an anchor with mu > 0, or a constrained face with mu_f > 0 among
    // its faces: otherwise the edge term is flat along its translations, in every
    // coordinate, and no term adds curvature there.
    const Index nv = topology_->vertex_count;
    std::vector<Index> part(static_cast<size_t>(nv), kInvalidIndex);
    std::vector<char> is_free(static_cast<size_t>(nv), 0);
    for (const Index v : free)
        is_free[v] = 1;
    const auto file_number = [&](Index v) {
        return file_vertex.empty() ? v : file_vertex[static_cast<size_t>(v)];
    };
    std::vector<Index> stack;
    Index parts = 0;
    for (const Index seed : free)
    {
        if (part[seed] != kInvalidIndex)
            continue;
        bool held = false;
        Index count = 0;
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

} // namespace meshfair
