// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <string>

#include "app/editor/document.h"

namespace meshfair::app {

//! \brief Where recovery files live: $XDG_STATE_HOME/meshfair/recovery, else
//! ~/.local/state/meshfair/recovery; empty when neither variable is set (no autosave).
std::string recovery_root();

//! A session's recovery files, found for a mesh.
struct RecoveryInfo
{
    std::string dir;       //!< the folder holding them
    std::string mesh_path; //!< the mesh they belong to (absolute)
    long pid = 0;          //!< the editor that wrote them
    std::string saved_at;  //!< local time, for the offer ("2026-12-01 20:15:03")
};

//! \brief Writes the session's edit state (positions, base shape, selection, sets, solver
//! settings) for `document` into root/<id of its mesh path>/. Each file is written
//! atomically and the state file last, so a crash mid-way leaves the previous autosave whole.
//! \throw WriteError when it cannot be written.
void write_recovery(const Document& document, const std::string& root);

//! \brief The recovery files of `mesh_path` under `root` left by an editor that is no
//! longer running (a crash, a kill), if any.
std::optional<RecoveryInfo> find_recovery(const std::string& mesh_path, const std::string& root);

//! \brief Restores the edit state saved in `info` into `document` (the same mesh): reads
//! its files and restores them (restore_recovery_files).
//! \throw InvalidInputError naming the file when it cannot be read, is damaged or is for
//! another mesh (other vertex or face counts); the document is then left as it was.
void restore_recovery(const RecoveryInfo& info, Document& document);

//! The contents of a session's recovery files, as write_recovery writes them.
struct RecoveryFiles
{
    std::string dir;       //!< the folder they came from, for messages
    std::string state;     //!< state.json
    std::string positions; //!< positions.bin: 3 #V doubles
    std::string base;      //!< base.bin: 3 #V doubles
    std::string selection; //!< selection.bin: #V then #F flags
};

//! \brief Restores recovery files already read into `document`. Everything is checked
//! before the document changes: counts and sizes that fit its mesh, finite coordinates,
//! set elements within the mesh, targets and normals one per element, weights and solver
//! settings within what the editor can hold (weights >= 0, counts >= 1, ...).
//! \throw InvalidInputError naming the file and what is wrong; the document is then left
//! as it was.
void restore_recovery_files(const RecoveryFiles& files, Document& document);

//! Removes the recovery files of `mesh_path` (a clean exit, or the offer declined).
void remove_recovery(const std::string& mesh_path, const std::string& root);

} // namespace meshfair::app
