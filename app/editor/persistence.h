// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/edit/constraint_sets.h"
#include "app/editor/document.h"
#include "app/editor/recovery.h"

namespace meshfair::app {

//! \brief Saves the document's mesh in the file's numbering (format from the extension,
//! atomic: a failure leaves an existing file whole); the document then names that file
//! and is not modified. The attributes read with the mesh are written back as
//! io::write_mesh writes them (normals recomputed from the shape saved); the result is
//! its notes, naming what the format cannot hold.
//! \throw WriteError (and InvalidInputError for an unknown extension).
std::vector<std::string> save_document(Document& document, const std::string& path);

//! \brief The recipe of the sets and settings with the steps taken from the base shape, in
//! the document's (locality) numbering: what `meshfair-cli smooth BASE --recipe R.json`
//! runs to reproduce the current shape (bit for bit when document.reproducible).
//! \pre constraint_problems(document.sets, document.solver) is empty.
Recipe current_recipe(const Document& document);
//! current_recipe in the file's numbering: what Export recipe writes.
Recipe file_recipe(const Document& document);
//! Writes file_recipe as JSON, atomically. \throw WriteError
void export_recipe(const Document& document, const std::string& path);
//! \brief The sets and settings of a recipe file, checked against the document's mesh (the
//! file's indices named in messages) and renumbered into the document's numbering.
//! \throw InvalidInputError (RecipeError) naming the file and the key at fault.
ImportedRecipe import_recipe(const Document& document, const std::string& path);
//! The presets the solver panel offers: the names of assets/recipes/*.json, sorted.
std::vector<std::string> preset_names();
//! The preset's "description" (what it is for); empty when it has none or does not read.
std::string preset_description(const std::string& preset);
//! \brief The file of a preset: assets/recipes/NAME.json, or `preset` itself when it names
//! a file (a path with a '/' or ending in .json).
//! \throw InvalidInputError naming the presets there are when there is no such preset.
std::string preset_path(const std::string& preset);

//! \brief The autosave of a session and its recovery files (app/editor/recovery.h): when
//! the document changed (its versions) and enough time went by, its edit state is written
//! under the recovery root; a clean exit removes what this session wrote or recovered.
class Autosaver
{
public:
    explicit Autosaver(std::string root = recovery_root()) : root_(std::move(root)) {}
    //! Where recovery files go (empty: no autosave).
    void set_root(std::string root) { root_ = std::move(root); }
    //! \brief Writes the recovery files when the document changed since the last time and
    //! at least `interval_s` seconds went by (0: now). Returns an error message, or empty.
    std::string autosave(const Document& document, double interval_s);
    //! Recovery files of this mesh left by an editor that crashed, if any.
    std::optional<RecoveryInfo> offer(const Document& document) const;
    //! \brief Restores them into `document`. \throw InvalidInputError when they cannot be
    //! read (the document is then as it was).
    RecoveryInfo recover(Document& document);
    //! Removes this mesh's recovery files (the offer declined).
    void discard(const Document& document);
    //! At a clean exit: removes the recovery files this session wrote or recovered.
    void end_session();
    //! The document is a new one: what was autosaved is not of it.
    void forget() { autosaved_ = std::nullopt; }

private:
    std::string root_;
    std::optional<std::uint64_t> autosaved_; // the versions' total at the last autosave
    double last_ = 0;                        // seconds on the steady clock
    bool owns_ = false;                      // this session wrote or recovered the files...
    std::string path_;                       // ...of this mesh path
};

} // namespace meshfair::app
