// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/locality_run.h"

#include <utility>

#include "core/errors.h"

namespace meshfair {

namespace {

// The members are built in order: the numbering, the renumbered mesh, its topology.
LocalityOrder order_of(const Mesh& mesh)
{
    return locality_order(mesh);
}

} // namespace

LocalityRun::LocalityRun(Mesh mesh, const Recipe& recipe)
    : order_(order_of(mesh)),
      mesh_(reorder_mesh(std::exchange(mesh, Mesh{}), order_)),
      topology_(build_topology(mesh_, required_topology(recipe))),
      session_(mesh_, topology_, renumber_recipe(recipe, order_.vertex_index, order_.face_index))
{
    session_.apply_hard_targets(mesh_.positions);
    // The session holds the only copy of the positions while it runs.
    session_.adopt_positions(std::move(mesh_.positions));
}

LocalityRun::LocalityRun(Mesh renumbered_mesh, LocalityOrder order, const Recipe& renumbered_recipe)
    : order_(std::move(order)),
      mesh_(std::move(renumbered_mesh)),
      topology_(build_topology(mesh_, required_topology(renumbered_recipe))),
      session_(mesh_, topology_, renumbered_recipe)
{
    session_.apply_hard_targets(mesh_.positions);
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
                         Topology topology)
    : order_(std::move(order)),
      mesh_(std::move(renumbered_mesh)),
      topology_(checked(std::move(topology), mesh_, renumbered_recipe)),
      session_(mesh_, topology_, renumbered_recipe)
{
    session_.apply_hard_targets(mesh_.positions);
    session_.adopt_positions(std::move(mesh_.positions));
}

Topology LocalityRun::take_topology() &&
{
    return std::move(topology_);
}

LocalityRun::Released LocalityRun::release() &&
{
    mesh_.positions = session_.release_positions();
    return {std::move(mesh_), std::move(order_)};
}

Mesh file_order_mesh(LocalityRun::Released released)
{
    return reorder_mesh(released.mesh, inverse_order(std::move(released.order)));
}

} // namespace meshfair
