// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/render/camera.h"

//! \file
//! \brief What the editor remembers between sessions, in the user's configuration folder:
//! the recent files and each mesh's up axis. Files of lines written atomically; one that
//! cannot be read or written is never a reason to fail.

namespace meshfair::app {

//! \brief `path` made absolute and normal ("a/../b.obj" -> "/cwd/b.obj"): one name per
//! file, for the recent files, the up axes and the recovery folders; as given when the
//! working directory cannot be read.
std::string absolute_path(const std::string& path);

//! Adds `path` (made absolute) in front of the recent files (once, at most 10 kept).
void remember_recent(std::vector<std::string>& recent, const std::string& path);

//! \brief Where the recent files are kept between runs:
//! $XDG_CONFIG_HOME/meshfair/recent.txt, else ~/.config/meshfair/recent.txt; empty when
//! neither variable is set.
std::string recent_files_path();
//! The recent files listed in `file`, one per line (none when it cannot be read).
std::vector<std::string> load_recent(const std::string& file);
//! \brief Writes the list atomically, creating the folder; false (and nothing changed)
//! when it cannot: the recent list is a convenience, never a reason to fail.
bool save_recent(const std::string& file, const std::vector<std::string>& recent);

//! \brief Where each mesh's up axis is kept, beside the recent files: up-axes.txt in the
//! same folder, one axis ("+z", "-y", ...: up_axis_name), a tab and an absolute path per
//! line; empty when unknown.
std::string up_axes_path();
//! The up axis remembered for `mesh_path` in `file`, if any.
std::optional<UpAxis> load_up_axis(const std::string& file, const std::string& mesh_path);
//! \brief Remembers `axis` for `mesh_path` (atomically; at most 1000 files kept); false
//! when it cannot, never a reason to fail.
bool save_up_axis(const std::string& file, const std::string& mesh_path, UpAxis axis);

} // namespace meshfair::app
