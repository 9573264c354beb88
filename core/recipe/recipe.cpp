// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/recipe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/errors.h"

namespace meshfair {

namespace {

// Names the entries of an element list and of the lists that follow it (targets, normals,
// weights) in messages: "hard.vertices[1]", or, for a set merged from a JSON list of sets,
// "soft[1].vertices[0]".
class ListKey
{
public:
    ListKey(std::string section, std::string list, const SetEnds& ends = {}, size_t size = 0)
        : section_(std::move(section)), list_(std::move(list))
    {
        // Ends that do not describe the list (a recipe edited after parsing) name it whole.
        if (!ends.empty() && ends.back() == size && std::is_sorted(ends.begin(), ends.end()))
            ends_ = ends;
    }
    //! The same sets for another list of the section ("targets" after "vertices").
    ListKey sibling(std::string list) const
    {
        ListKey key(section_, std::move(list));
        key.ends_ = ends_;
        return key;
    }
    std::string whole() const { return section_ + "." + list_; }
    std::string operator()(size_t k) const
    {
        if (ends_.empty())
            return recipe_item_key(whole(), k);
        const size_t s = set_of(k);
        return recipe_item_key(set_name(s) + "." + list_, k - (s == 0 ? 0 : ends_[s - 1]));
    }
    size_t set_of(size_t k) const
    {
        const auto s = std::upper_bound(ends_.begin(), ends_.end(), k) - ends_.begin();
        return std::min(static_cast<size_t>(s), ends_.empty() ? 0 : ends_.size() - 1);
    }
    std::string set_name(size_t s) const { return recipe_item_key(section_, s); }

private:
    std::string section_, list_;
    SetEnds ends_;
};

// Range and uniqueness of one index list; `seen` is a scratch marker array.
void check_indices(const std::vector<Index>& list, Index limit, const ListKey& key,
                   const char* element, const char* elements, std::vector<char>& seen)
{
    seen.assign(limit, 0);
    for (size_t k = 0; k < list.size(); ++k)
    {
        const Index v = list[k];
        const std::string name = std::string(element) + " " + std::to_string(v);
        if (v < 0 || v >= limit)
            throw RecipeError(key(k), name + " is out of range (the mesh has " +
                                          std::to_string(limit) + " " + elements + ")");
        if (seen[v])
        {
            // Where it was met first: searched for only now, so that the markers stay bytes.
            const auto first = static_cast<size_t>(
                std::find(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(k), v) -
                list.begin());
            if (key.set_of(first) == key.set_of(k))
                throw RecipeError(key(k), name + " is listed twice");
            throw RecipeError(key(k), name + " is already in " + key.set_name(key.set_of(first)));
        }
        seen[v] = 1;
    }
}

void check_count(size_t given, size_t expected, const std::string& key, const std::string& what)
{
    if (given != 0 && given != expected)
        throw RecipeError(key, "has " + std::to_string(given) + " entries but " + what + " has " +
                                   std::to_string(expected));
}

void check_finite(const std::vector<Vec3>& points, const ListKey& key)
{
    for (size_t k = 0; k < points.size(); ++k)
        for (int a = 0; a < 3; ++a)
            if (!(std::abs(points[k][a]) <= kMaxCoordinate)) // also false for NaN
                throw RecipeError(key(k), "must be finite and within +-1e100");
}

void check_directions(const std::vector<Vec3>& normals, const ListKey& key)
{
    check_finite(normals, key);
    for (size_t k = 0; k < normals.size(); ++k)
    {
        const Vec3& n = normals[k];
        if (!(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0))
            throw RecipeError(key(k), "a normal must not be the zero vector");
    }
}

void check_weight(Scalar w, const std::string& key)
{
    if (!std::isfinite(w) || w < 0)
        throw RecipeError(key, "must be finite and >= 0");
}

// Per-element weights: one per element (`count` of them, named `elements` as in "6
// vertices"), each finite and >= 0, and mu times each finite (the weight the solver uses).
void check_weights(const std::vector<Scalar>& weights, Scalar mu, size_t count,
                   const std::string& elements, const ListKey& key)
{
    if (weights.empty())
        return;
    if (weights.size() != count)
        throw RecipeError(key.whole(), std::to_string(weights.size()) + " weights for " +
                                           std::to_string(count) + " " + elements);
    for (size_t k = 0; k < weights.size(); ++k)
    {
        check_weight(weights[k], key(k));
        if (!std::isfinite(mu * weights[k]))
            throw RecipeError(key(k), "times mu is not finite");
    }
}

} // namespace

void check_recipe(const Recipe& r, const Mesh& mesh)
{
    const Index nv = mesh.vertex_count(), nf = mesh.face_count();
    for (size_t k = 0; k < mesh.positions.size(); ++k)
        if (!(std::abs(mesh.positions[k]) <= kMaxCoordinate))
        {
            char value[32];
            std::snprintf(value, sizeof value, "%g", mesh.positions[k]);
            throw InvalidInputError("vertex " + std::to_string(k / 3) + " has the coordinate " +
                                    value +
                                    ", beyond the +-1e100 that smoothing supports (squared "
                                    "distances would overflow): scale the mesh down");
        }
    if (nf == 0 && nv > 0)
        throw InvalidInputError("the mesh has no faces (a point cloud of " + std::to_string(nv) +
                                " vertices): there is no surface to smooth");
    std::vector<char> seen;
    if (r.iterations < 0)
        throw RecipeError("iterations", "must be >= 0");
    if (!r.optimal_step && !(std::isfinite(r.lambda) && r.lambda > 0))
        throw RecipeError("lambda", "must be finite and > 0");
    check_weight(r.tolerance, "tolerance");
    if (r.region)
    {
        check_indices(r.region->vertices, nv, {"region", "vertices"}, "vertex", "vertices", seen);
        check_indices(r.region->faces, nf, {"region", "faces"}, "face", "faces", seen);
    }
    std::vector<char> hard(nv, 0);
    if (r.hard)
    {
        check_indices(r.hard->vertices, nv, {"hard", "vertices"}, "vertex", "vertices", seen);
        check_count(r.hard->targets.size(), r.hard->vertices.size(), "hard.targets",
                    "hard.vertices");
        check_finite(r.hard->targets, {"hard", "targets"});
        for (const Index v : r.hard->vertices)
            hard[v] = 1;
    }
    if (r.soft)
    {
        const SoftVertices& soft = *r.soft;
        check_weight(soft.mu, "soft.mu");
        const auto& list = soft.vertices.indices;
        const ListKey key("soft", "vertices", soft.set_ends, list.size());
        if (soft.vertices.all)
        {
            check_count(soft.targets.size(), nv, "soft.targets",
                        "the mesh (soft.vertices is \"all\")");
            check_weights(soft.weights, soft.mu, nv, "vertices (soft.vertices is \"all\")",
                          key.sibling("weights"));
        }
        else
        {
            check_indices(list, nv, key, "vertex", "vertices", seen);
            check_count(soft.targets.size(), list.size(), "soft.targets", "soft.vertices");
            check_weights(soft.weights, soft.mu, list.size(), "vertices", key.sibling("weights"));
            for (size_t k = 0; k < list.size(); ++k)
                if (hard[list[k]])
                    throw RecipeError(key(k), "vertex " + std::to_string(list[k]) +
                                                  " is also in hard.vertices (hard and soft "
                                                  "vertex sets must be disjoint)");
        }
        check_finite(soft.targets, key.sibling("targets"));
    }
    if (r.centroid)
    {
        const CentroidConstraints& c = *r.centroid;
        check_weight(c.mu, "centroid.mu");
        const ListKey key("centroid", "faces", c.set_ends, c.faces.indices.size());
        if (c.faces.all)
        {
            check_count(c.targets.size(), nf, "centroid.targets",
                        "the mesh (centroid.faces is \"all\")");
            check_weights(c.weights, c.mu, nf, "faces (centroid.faces is \"all\")",
                          key.sibling("weights"));
        }
        else
        {
            check_indices(c.faces.indices, nf, key, "face", "faces", seen);
            check_count(c.targets.size(), c.faces.indices.size(), "centroid.targets",
                        "centroid.faces");
            check_weights(c.weights, c.mu, c.faces.indices.size(), "faces", key.sibling("weights"));
        }
        check_finite(c.targets, key.sibling("targets"));
    }
    if (r.normal)
    {
        const NormalConstraints& n = *r.normal;
        check_weight(n.mu, "normal.mu");
        const size_t faces = n.faces.all ? nf : n.faces.indices.size();
        const ListKey key("normal", "faces", n.set_ends, n.faces.indices.size());
        if (!n.faces.all)
            check_indices(n.faces.indices, nf, key, "face", "faces", seen);
        check_weights(n.weights, n.mu, faces,
                      n.faces.all ? "faces (normal.faces is \"all\")" : "faces",
                      key.sibling("weights"));
        if (n.source == NormalSource::Custom)
        {
            if (n.normals.size() != faces)
                throw RecipeError("normal.normals", "has " + std::to_string(n.normals.size()) +
                                                        " entries but normal.faces has " +
                                                        std::to_string(faces));
            check_directions(n.normals, key.sibling("normals"));
        }
    }
    if (r.normal_smoothing)
    {
        const NormalSmoothing& ns = *r.normal_smoothing;
        if (!r.normal)
            throw RecipeError("normal_smoothing",
                              "needs a \"normal\" section: smoothed normals act on the mesh "
                              "through the face-normal term");
        if (ns.iterations < 0)
            throw RecipeError("normal_smoothing.iterations", "must be >= 0");
        if (ns.adaptive)
        {
            check_weight(ns.adaptive->per_noise, "normal_smoothing.iterations_per_noise");
            if (!(std::isfinite(ns.adaptive->strength) && ns.adaptive->strength >= 0 &&
                  ns.adaptive->strength <= 10))
                throw RecipeError("normal_smoothing.strength", "must be between 0 and 10");
        }
        if (!(std::isfinite(ns.lambda) && ns.lambda > 0))
            throw RecipeError("normal_smoothing.lambda", "must be finite and > 0");
        check_indices(ns.hard.faces, nf, {"normal_smoothing.hard", "faces"}, "face", "faces", seen);
        check_count(ns.hard.normals.size(), ns.hard.faces.size(), "normal_smoothing.hard.normals",
                    "normal_smoothing.hard.faces");
        check_directions(ns.hard.normals, {"normal_smoothing.hard", "normals"});
        std::vector<char> hard_faces(nf, 0);
        for (const Index f : ns.hard.faces)
            hard_faces[f] = 1;
        check_weight(ns.soft.mu, "normal_smoothing.soft.mu");
        check_indices(ns.soft.faces, nf, {"normal_smoothing.soft", "faces"}, "face", "faces", seen);
        check_count(ns.soft.normals.size(), ns.soft.faces.size(), "normal_smoothing.soft.normals",
                    "normal_smoothing.soft.faces");
        check_weights(ns.soft.weights, ns.soft.mu, ns.soft.faces.size(), "faces",
                      {"normal_smoothing.soft", "weights"});
        check_directions(ns.soft.normals, {"normal_smoothing.soft", "normals"});
        if (ns.bilateral)
        {
            const BilateralWeights& b = *ns.bilateral;
            if (!(std::isfinite(b.sigma_s) && b.sigma_s > 0))
                throw RecipeError("normal_smoothing.bilateral.sigma_s", "must be finite and > 0");
            if (!(std::isfinite(b.sigma_r) && b.sigma_r > 0))
                throw RecipeError("normal_smoothing.bilateral.sigma_r", "must be finite and > 0");
            if (b.reweight_every < 1)
                throw RecipeError("normal_smoothing.bilateral.reweight_every", "must be >= 1");
            check_weight(b.noise_scale, "normal_smoothing.bilateral.noise_scale");
        }
        for (size_t k = 0; k < ns.soft.faces.size(); ++k)
            if (hard_faces[ns.soft.faces[k]])
                throw RecipeError(recipe_item_key("normal_smoothing.soft.faces", k),
                                  "face " + std::to_string(ns.soft.faces[k]) +
                                      " is also in normal_smoothing.hard.faces (hard and soft "
                                      "normal sets must be disjoint)");
    }
    if (r.joint)
    {
        check_weight(r.joint->gamma, "joint.gamma");
        if (!r.normal)
            throw RecipeError("joint",
                              "needs a \"normal\" section (its faces and mu couple x "
                              "and u)");
    }
    if (r.bending)
    {
        check_weight(r.bending->mu, "bending.mu");
        check_weight(r.bending->membrane, "bending.membrane");
    }
    if (r.falloff)
    {
        const Falloff& f = *r.falloff;
        if (!(std::isfinite(f.radius) && f.radius >= 0))
            throw RecipeError("falloff.radius", "must be finite and >= 0");
        check_weight(f.mu, "falloff.mu");
        if (!f.border && !f.pins)
            throw RecipeError("falloff.around", "must name \"border\", \"pins\" or both");
        // Nothing to fade from (no region, no pins) is no error: the Session notes it.
    }
    if (r.method == Method::Taubin)
    {
        if (!(std::isfinite(r.taubin_mu) && r.taubin_mu < -r.lambda))
            throw RecipeError("taubin_mu",
                              "must be finite and below -lambda (Taubin's mu < "
                              "-lambda < 0 keeps the low frequencies)");
        if (r.optimal_step)
            throw RecipeError("lambda",
                              "\"optimal\" is not a step length of method \"taubin\" "
                              "(its two steps have fixed lengths)");
        if (r.joint)
            throw RecipeError("joint",
                              "is not available with method \"taubin\" (the normals "
                              "have no lambda|mu pair)");
    }
    if (!std::isfinite(r.factor_budget_mb) || r.factor_budget_mb < 0)
        throw RecipeError("factor_budget_mb", "must be finite and >= 0");
    if (r.method == Method::Implicit)
    {
        if (!(std::isfinite(r.time) && r.time > 0))
            throw RecipeError("time", "must be finite and > 0 (the time of each implicit step)");
        if (r.optimal_step)
            throw RecipeError("lambda",
                              "\"optimal\" is not a step length of method \"implicit\" "
                              "(its steps are given by \"time\")");
        if (r.joint)
            throw RecipeError("joint",
                              "is not available with method \"implicit\" yet (the "
                              "normals of joint mode move with the positions; use "
                              "\"jacobi\")");
    }
    if (solves_for_minimizer(r.method))
    {
        const std::string name = r.method == Method::Direct ? "\"direct\"" : "\"cg\"";
        if (r.optimal_step)
            throw RecipeError("lambda", "\"optimal\" is not a step length of method " + name +
                                            " (each of its steps solves for the minimizer)");
        if (r.joint)
            throw RecipeError("joint", "is not available with method " + name +
                                           " (the normals of joint mode move with the "
                                           "positions, and Jacobi steps reach their fixed "
                                           "point sooner: docs/math.md, \"The direct "
                                           "method\"); use \"jacobi\"");
    }
}

Recipe renumber_recipe(const Recipe& recipe, std::span<const Index> new_vertex,
                       std::span<const Index> new_face)
{
    const auto map = [](std::vector<Index>& items, std::span<const Index> to) {
        for (Index& k : items)
            k = to[static_cast<size_t>(k)];
    };
    // With "all", per-element lists follow the elements' own order: permute them.
    const auto permute = []<typename T>(std::vector<T>& items, std::span<const Index> to) {
        std::vector<T> moved(items.size());
        for (size_t k = 0; k < items.size(); ++k)
            moved[static_cast<size_t>(to[k])] = items[k];
        items = std::move(moved);
    };
    Recipe r = recipe;
    if (r.soft && r.soft->vertices.all)
    {
        permute(r.soft->targets, new_vertex);
        permute(r.soft->weights, new_vertex);
    }
    if (r.centroid && r.centroid->faces.all)
    {
        permute(r.centroid->targets, new_face);
        permute(r.centroid->weights, new_face);
    }
    if (r.normal && r.normal->faces.all)
    {
        permute(r.normal->normals, new_face);
        permute(r.normal->weights, new_face);
    }
    if (r.region)
    {
        map(r.region->vertices, new_vertex);
        map(r.region->faces, new_face);
    }
    if (r.hard)
        map(r.hard->vertices, new_vertex);
    if (r.soft)
        map(r.soft->vertices.indices, new_vertex);
    if (r.centroid)
        map(r.centroid->faces.indices, new_face);
    if (r.normal)
        map(r.normal->faces.indices, new_face);
    if (r.normal_smoothing)
    {
        map(r.normal_smoothing->hard.faces, new_face);
        map(r.normal_smoothing->soft.faces, new_face);
    }
    return r;
}

} // namespace meshfair
