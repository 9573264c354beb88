// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "app/edit/constraint_sets.h"
#include "app/render/camera.h"
#include "app/render/mesh_draw_data.h"
#include "core/io/io.h"
#include "core/mesh/mesh.h"
#include "core/select/mesh_select.h"
#include "core/topology/topology.h"
#include "core/topology/vertex_order.h"

namespace meshfair::app {

//! \brief How many times each part of a document changed: what the renderer, the solver,
//! the glyphs and the autosave compare with what they last saw, instead of being told of
//! each change. Bumped by EditorSession::dispatch for what a command edits, by undo and redo
//! for what they restore, and by the solver for the positions it publishes.
struct DocumentVersions
{
    std::uint64_t selection = 0, sets = 0, settings = 0, positions = 0, base = 0;
    std::uint64_t set_members = 0; //!< bumped with sets when their elements change
    //! Bumps the parts of `parts` (EditPart flags of history.h).
    void bump(unsigned parts);
    //! Every change so far (the autosave's "something changed"; members change with sets).
    std::uint64_t total() const { return selection + sets + settings + positions + base; }
};

//! The sets and settings whose steps made a shape (what its steps from the base ran with).
struct ShapeRecipe
{
    std::vector<ConstraintSet> sets;
    SolverSettings solver;
};

//! \brief The mesh the editor shows, with what it derives from it once per connectivity:
//! the topology (edges, corners), the draw data and the bounding box. The editor owns
//! the interaction state; this is the data everything else reads.
struct Document
{
    std::string path; //!< the file it came from or was last saved to
    //! Unique to each document made (make_document): with versions.base, what keys the
    //! base shape the solver shares (SolverController), so that a copy is made only when the
    //! base changes, never per restart.
    std::uint64_t id = 0;
    //! \brief The mesh in the locality numbering MeshFair solves in (as meshfair-cli does),
    //! so that the solver, the normals and the tools stream memory on large meshes. Every
    //! index the editor keeps (selections, sets) is in this numbering; files (meshes,
    //! recipes) keep the file's, through `order`.
    Mesh mesh;
    //! internal vertex k is file vertex order.vertex_order[k] (identity for make_document)
    LocalityOrder order;
    io::ReadReport report;
    //! Everything the file holds besides positions and faces (texture coordinates, normals,
    //! colours, groups, other properties), in the file's numbering: a save writes it back.
    io::MeshAttributes attributes;
    Topology topology;
    MeshDrawData draw_data;
    Box3 box;
    SelectionMask selected_vertices; //!< #V flags
    SelectionMask selected_faces;    //!< #F flags
    //! \brief The shape the recipe starts from: the positions read, until Apply makes the
    //! current shape the new start. mesh.positions is the current shape.
    std::vector<Scalar> base_positions;
    //! Solver steps from the base shape to the current one, and whether they all ran with
    //! the current recipe (then the exported recipe reproduces the shape).
    int steps_from_base = 0;
    bool reproducible = true;
    //! The recipe the last steps ran with (null: none since the base, or not known), so that
    //! a run restarted from this shape with the same recipe stays reproducible.
    std::shared_ptr<const ShapeRecipe> shape_recipe;
    std::vector<ConstraintSet> sets; //!< the recipe's constraint sets
    SolverSettings solver;           //!< the recipe's weights and iteration settings
    bool modified = false;           //!< changed since it was read or saved
    //! \brief The mesh's up axis, as the view shows it (the camera's, which the session
    //! copies here before each command and frame): what travels with the file's edit state
    //! (recovery, Save As, Export recipe).
    UpAxis up_axis = UpAxis::Y;
    DocumentVersions versions;
};

//! \brief Reads a mesh file into a document.
//! \throw InvalidInputError (FormatError included) naming the file and what is wrong.
Document load_document(const std::string& path);

//! \brief A document of a mesh already in memory (a test fixture, a generated mesh), named
//! `path`, in the mesh's own numbering (order: the identity).
Document make_document(Mesh mesh, std::string path);

//! The identity numbering of a mesh of these counts.
LocalityOrder identity_order(Index vertices, Index faces);

//! The document's current mesh in the file's numbering (what Save writes).
Mesh file_order_mesh(const Document& document);

//! The box around the positions (3 #V values).
Box3 bounding_box(std::span<const Scalar> positions);

//! \brief The box around the selected vertices and the vertices of the selected faces, for
//! "frame selection"; the whole mesh's box when nothing is selected.
Box3 selection_box(const Document& document);

//! "34,835 vertices" style thousands separators for the status bar.
std::string with_separators(std::int64_t n);

} // namespace meshfair::app
