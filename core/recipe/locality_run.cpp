// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/locality_run.h"

#include <utility>

#include "core/errors.h"

namespace meshfair {

namespace {

// File to internal: read to renumber the mesh and the recipe, not by the solve; dropped
// before the topology and the session are built, so that the peak holds neither.
LocalityOrder without_inverses(LocalityOrder order)
{
    std::vector<Index>().swap(order.vertex_index);
    std::vector<Index>().swap(order.face_index);
    return order;
}

} // namespace

LocalityRun::Renumbered LocalityRun::renumber(Mesh mesh, const Recipe& recipe)
{
    LocalityOrder order = locality_order(mesh);
    Mesh renumbered = reorder_mesh(std::exchange(mesh, Mesh{}), order);
    Recipe renumbered_recipe = renumber_recipe(recipe, order.vertex_index, order.face_index);
    return {std::move(renumbered), std::move(order), std::move(renumbered_recipe)};
}

LocalityRun::LocalityRun(Mesh mesh, const Recipe& recipe)
    : LocalityRun(renumber(std::move(mesh), recipe))
{
}

LocalityRun::LocalityRun(Renumbered r)
    : LocalityRun(std::move(r.mesh), std::move(r.order), r.recipe)
{
}

LocalityRun::LocalityRun(Mesh renumbered_mesh, LocalityOrder order, const Recipe& renumbered_recipe)
    : order_(without_inverses(std::move(order))),
      mesh_(std::move(renumbered_mesh)),
      topology_(build_topology(mesh_, required_topology(renumbered_recipe))),
      session_(mesh_, topology_, renumbered_recipe, order_.vertex_order)
{
    session_.apply_hard_targets(mesh_.positions);
    // The session holds the only copy of the positions while it runs.
    session_.adopt_positions(std::move(mesh_.positions));
}

namespace {

// The checks a reused topology can pass cheaply: its counts and parts.
Topology checked(Topology topology, const Mesh& mesh, const Recipe& recipe)
{
    if (topology.vertex_count != mesh.vertex_count() || topology.face_count != mesh.face_count() ||
        topology.parts != required_topology(recipe))
        throw SolverError("LocalityRun: the topology given is not the mesh's for this recipe");
    return topology;
}

} // namespace

LocalityRun::LocalityRun(Mesh renumbered_mesh, LocalityOrder order, const Recipe& renumbered_recipe,
                         Topology topology, std::unique_ptr<SparseCholesky> analysed)
    : order_(without_inverses(std::move(order))),
      mesh_(std::move(renumbered_mesh)),
      topology_(checked(std::move(topology), mesh_, renumbered_recipe)),
      session_(mesh_, topology_, renumbered_recipe, order_.vertex_order, std::move(analysed))
{
    session_.apply_hard_targets(mesh_.positions);
    session_.adopt_positions(std::move(mesh_.positions));
}

LocalityRun::LocalityRun(std::shared_ptr<const Mesh> renumbered_mesh,
                         std::shared_ptr<const LocalityOrder> order,
                         const Recipe& renumbered_recipe, Topology topology,
                         std::unique_ptr<SparseCholesky> analysed, std::vector<Scalar> start)
    : shared_order_(std::move(order)),
      shared_mesh_(std::move(renumbered_mesh)),
      topology_(checked(std::move(topology), *shared_mesh_, renumbered_recipe)),
      session_(*shared_mesh_, topology_, renumbered_recipe, shared_order_->vertex_order,
               std::move(analysed))
{
    const bool from_mesh = start.empty();
    std::vector<Scalar> x = from_mesh ? shared_mesh_->positions : std::move(start);
    if (from_mesh)
        session_.apply_hard_targets(x);
    session_.adopt_positions(std::move(x));
}

Topology LocalityRun::take_topology() &&
{
    return std::move(topology_);
}

LocalityRun::Released LocalityRun::release() &&
{
    if (shared_mesh_)
    {
        mesh_.face_offsets = shared_mesh_->face_offsets;
        mesh_.face_vertices = shared_mesh_->face_vertices;
        order_ = *shared_order_;
    }
    mesh_.positions = session_.release_positions();
    return {std::move(mesh_), std::move(order_)};
}

Mesh file_order_mesh(LocalityRun::Released released)
{
    LocalityOrder& order = released.order;
    if (order.vertex_index.size() != order.vertex_order.size())
        order.vertex_index = inverse_permutation(order.vertex_order);
    if (order.face_index.size() != order.face_order.size())
        order.face_index = inverse_permutation(order.face_order);
    return reorder_mesh(released.mesh, inverse_order(std::move(released.order)));
}

} // namespace meshfair
