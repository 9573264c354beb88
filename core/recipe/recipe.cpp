// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/recipe.h"

#include <cmath>
#include <cstdio>

#include "core/errors.h"

namespace meshfair {

namespace {

std::string item(const std::string& key, size_t k)
{
    return key + "[" + std::to_string(k) + "]";
}

// Range and uniqueness of one index list; `seen` is a scratch marker array.
void check_indices(const std::vector<Index>& list, Index limit, const std::string& key,
                   const char* element, const char* elements, std::vector<char>& seen)
{
    seen.assign(limit, 0);
    for (size_t k = 0; k < list.size(); ++k)
    {
        const Index v = list[k];
        if (v < 0 || v >= limit)
            throw RecipeError(item(key, k), std::string(element) + " " + std::to_string(v) +
                                                " is out of range (the mesh has " +
                                                std::to_string(limit) + " " + elements + ")");
        if (seen[v])
            throw RecipeError(item(key, k),
                              std::string(element) + " " + std::to_string(v) + " is listed twice");
        seen[v] = 1;
    }
}

void check_count(size_t given, size_t expected, const std::string& key, const std::string& what)
{
    if (given != 0 && given != expected)
        throw RecipeError(key, "has " + std::to_string(given) + " entries but " + what + " has " +
                                   std::to_string(expected));
}

void check_finite(const std::vector<Vec3>& points, const std::string& key)
{
    for (size_t k = 0; k < points.size(); ++k)
        for (int a = 0; a < 3; ++a)
            if (!(std::abs(points[k][a]) <= kMaxCoordinate)) // also false for NaN
                throw RecipeError(item(key, k), "must be finite and within +-1e100");
}

void check_directions(const std::vector<Vec3>& normals, const std::string& key)
{
    check_finite(normals, key);
    for (size_t k = 0; k < normals.size(); ++k)
    {
        const Vec3& n = normals[k];
        if (!(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0))
            throw RecipeError(item(key, k), "a normal must not be the zero vector");
    }
}

void check_weight(Scalar w, const std::string& key)
{
    if (!std::isfinite(w) || w < 0)
        throw RecipeError(key, "must be finite and >= 0");
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
    std::vector<char> seen;
    if (r.iterations < 0)
        throw RecipeError("iterations", "must be >= 0");
    if (!r.optimal_step && !(std::isfinite(r.lambda) && r.lambda > 0))
        throw RecipeError("lambda", "must be finite and > 0");
    check_weight(r.tolerance, "tolerance");
    if (r.region)
    {
        check_indices(r.region->vertices, nv, "region.vertices", "vertex", "vertices", seen);
        check_indices(r.region->faces, nf, "region.faces", "face", "faces", seen);
    }
    std::vector<char> hard(nv, 0);
    if (r.hard)
    {
        check_indices(r.hard->vertices, nv, "hard.vertices", "vertex", "vertices", seen);
        check_count(r.hard->targets.size(), r.hard->vertices.size(), "hard.targets",
                    "hard.vertices");
        check_finite(r.hard->targets, "hard.targets");
        for (const Index v : r.hard->vertices)
            hard[v] = 1;
    }
    if (r.soft)
    {
        check_weight(r.soft->mu, "soft.mu");
        const auto& list = r.soft->vertices.indices;
        if (r.soft->vertices.all)
            check_count(r.soft->targets.size(), nv, "soft.targets",
                        "the mesh (soft.vertices is \"all\")");
        else
        {
            check_indices(list, nv, "soft.vertices", "vertex", "vertices", seen);
            check_count(r.soft->targets.size(), list.size(), "soft.targets", "soft.vertices");
            for (size_t k = 0; k < list.size(); ++k)
                if (hard[list[k]])
                    throw RecipeError(item("soft.vertices", k),
                                      "vertex " + std::to_string(list[k]) +
                                          " is also in hard.vertices (hard and soft vertex "
                                          "sets must be disjoint)");
        }
        check_finite(r.soft->targets, "soft.targets");
    }
    if (r.centroid)
    {
        check_weight(r.centroid->mu, "centroid.mu");
        if (r.centroid->faces.all)
            check_count(r.centroid->targets.size(), nf, "centroid.targets",
                        "the mesh (centroid.faces is \"all\")");
        else
        {
            check_indices(r.centroid->faces.indices, nf, "centroid.faces", "face", "faces", seen);
            check_count(r.centroid->targets.size(), r.centroid->faces.indices.size(),
                        "centroid.targets", "centroid.faces");
        }
        check_finite(r.centroid->targets, "centroid.targets");
    }
    if (r.normal)
    {
        check_weight(r.normal->mu, "normal.mu");
        const size_t faces = r.normal->faces.all ? nf : r.normal->faces.indices.size();
        if (!r.normal->faces.all)
            check_indices(r.normal->faces.indices, nf, "normal.faces", "face", "faces", seen);
        if (r.normal->source == NormalSource::Custom)
        {
            if (r.normal->normals.size() != faces)
                throw RecipeError("normal.normals",
                                  "has " + std::to_string(r.normal->normals.size()) +
                                      " entries but normal.faces has " + std::to_string(faces));
            check_directions(r.normal->normals, "normal.normals");
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
        if (!(std::isfinite(ns.lambda) && ns.lambda > 0))
            throw RecipeError("normal_smoothing.lambda", "must be finite and > 0");
        check_indices(ns.hard.faces, nf, "normal_smoothing.hard.faces", "face", "faces", seen);
        check_count(ns.hard.normals.size(), ns.hard.faces.size(), "normal_smoothing.hard.normals",
                    "normal_smoothing.hard.faces");
        check_directions(ns.hard.normals, "normal_smoothing.hard.normals");
        std::vector<char> hard_faces(nf, 0);
        for (const Index f : ns.hard.faces)
            hard_faces[f] = 1;
        check_weight(ns.soft.mu, "normal_smoothing.soft.mu");
        check_indices(ns.soft.faces, nf, "normal_smoothing.soft.faces", "face", "faces", seen);
        check_count(ns.soft.normals.size(), ns.soft.faces.size(), "normal_smoothing.soft.normals",
                    "normal_smoothing.soft.faces");
        check_directions(ns.soft.normals, "normal_smoothing.soft.normals");
        for (size_t k = 0; k < ns.soft.faces.size(); ++k)
            if (hard_faces[ns.soft.faces[k]])
                throw RecipeError(item("normal_smoothing.soft.faces", k),
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
}

Recipe renumber_recipe(const Recipe& recipe, std::span<const Index> new_vertex,
                       std::span<const Index> new_face)
{
    const auto map = [](std::vector<Index>& items, std::span<const Index> to) {
        for (Index& k : items)
            k = to[static_cast<size_t>(k)];
    };
    // With "all", per-element lists follow the elements' own order: permute them.
    const auto permute = [](std::vector<Vec3>& items, std::span<const Index> to) {
        std::vector<Vec3> moved(items.size());
        for (size_t k = 0; k < items.size(); ++k)
            moved[static_cast<size_t>(to[k])] = items[k];
        items = std::move(moved);
    };
    Recipe r = recipe;
    if (r.soft && r.soft->vertices.all && !r.soft->targets.empty())
        permute(r.soft->targets, new_vertex);
    if (r.centroid && r.centroid->faces.all && !r.centroid->targets.empty())
        permute(r.centroid->targets, new_face);
    if (r.normal && r.normal->faces.all && !r.normal->normals.empty())
        permute(r.normal->normals, new_face);
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
