// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/recipe/session.h"
#include "core/topology/vertex_order.h"

namespace meshfair {

//! \brief A smoothing run the way MeshFair runs one, for a caller that speaks the file's
//! numbering: the mesh is renumbered into the locality order (LocalityOrder), the topology
//! and the Session are built there, the hard vertices moved to their targets, and the
//! session keeps the positions. meshfair-cli smooth and the editor both run through this
//! class, so the editor's result after n steps is bit for bit the command line's with
//! "iterations": n.
//!
//! Construction is the precomputation (once per recipe); step() is linear and allocates
//! nothing.
class LocalityRun
{
public:
    //! \pre check_recipe(recipe, mesh) holds (file numbering); validate_mesh(mesh) holds.
    //! Takes the mesh (move it in: the one copy is renumbered in place).
    LocalityRun(Mesh mesh, const Recipe& recipe);
    //! \brief The same run for a mesh already renumbered by `order` (reorder_mesh(file mesh,
    //! locality_order(file mesh))) and a recipe already in that numbering
    //! (renumber_recipe(file recipe, order.vertex_index, order.face_index)): what the
    //! editor, which keeps its document in the locality numbering, runs. The same Session
    //! inputs as the first constructor's, so the same bits.
    //! \pre check_recipe(recipe, mesh) holds.
    LocalityRun(Mesh renumbered_mesh, LocalityOrder order, const Recipe& renumbered_recipe);
    //! \brief The same, with the topology already built: what a run restarted for a new
    //! recipe of the same mesh (the editor's, at each dab of the smoothing brush) takes from
    //! the run before it (take_topology) instead of building it again. The same bits as the
    //! constructor above.
    //! `analysed`: the run before's factorization (session().take_factorization()), whose
    //! analysis the session keeps when only weights changed (a slider).
    //! \pre topology is build_topology(renumbered_mesh, required_topology(renumbered_recipe)).
    //! \throw SolverError when its counts or parts are not those (what can be checked cheaply).
    LocalityRun(Mesh renumbered_mesh, LocalityOrder order, const Recipe& renumbered_recipe,
                Topology topology, std::unique_ptr<SparseCholesky> analysed = nullptr);
    //! \brief The same run on a mesh and an order shared with the caller, never copied (the
    //! editor's document: one connectivity for the document, every restart's run and the
    //! display; a restart per slider value or brush dab copies no mesh). The session keeps
    //! positions of its own: `start` (3 #V, pins placed by the caller), or the mesh's with
    //! the pins at their targets when empty. release() copies the shared mesh.
    //! \pre as above; the mesh and order stay unchanged while the run holds them.
    LocalityRun(std::shared_ptr<const Mesh> renumbered_mesh,
                std::shared_ptr<const LocalityOrder> order, const Recipe& renumbered_recipe,
                Topology topology, std::unique_ptr<SparseCholesky> analysed,
                std::vector<Scalar> start);

    //! One step on the kept positions.
    StepInfo step() { return session_.step(); }
    TermEnergies energy() const { return session_.energy(); }
    Session& session() { return session_; }
    const Session& session() const { return session_; }
    //! The mesh in the locality numbering (its positions are the session's until released).
    const Mesh& mesh() const { return shared_mesh_ ? *shared_mesh_ : mesh_; }
    //! The shared mesh, or nullptr when the run owns its mesh.
    const std::shared_ptr<const Mesh>& shared_mesh() const { return shared_mesh_; }
    const Topology& topology() const { return topology_; }
    //! The numbering, internal to file: vertex_order and face_order. Their inverses (file
    //! to internal; 12 bytes a vertex the solve does not read) are dropped before the
    //! topology and the session are built; file_order_mesh rebuilds them.
    const LocalityOrder& order() const { return shared_order_ ? *shared_order_ : order_; }

    //! \brief Ends the run: the renumbered mesh with the current positions, and its order.
    //! Renumber it back with file_order_mesh once the run is gone, so that the solver's
    //! arrays are freed before the file-order copy is made.
    struct Released
    {
        Mesh mesh;
        LocalityOrder order;
    };
    Released release() &&;
    //! Ends the run, keeping its topology for the next run of the same mesh.
    Topology take_topology() &&;

private:
    //! The file's mesh and recipe renumbered, and the order (its inverses are dropped by
    //! the constructor that takes it, before the topology is built).
    struct Renumbered
    {
        Mesh mesh;
        LocalityOrder order;
        Recipe recipe;
    };
    static Renumbered renumber(Mesh mesh, const Recipe& recipe);
    explicit LocalityRun(Renumbered r);

    // Owned (the command line's, Python's), or shared (the editor's): mesh() and order().
    LocalityOrder order_;
    std::shared_ptr<const LocalityOrder> shared_order_;
    Mesh mesh_;
    std::shared_ptr<const Mesh> shared_mesh_;
    Topology topology_;
    Session session_;
};

//! The released mesh in the file's numbering (the order's inverses rebuilt when dropped).
Mesh file_order_mesh(LocalityRun::Released released);

} // namespace meshfair
