// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "core/io/io.h"
#include "core/recipe/recipe.h"

namespace meshfair::cli {

//! Output encoding: what the user asked ("ascii", "binary", "binary-be"; empty for the
//! default), else the input's own encoding when the format stays the same (so binary STL
//! stays binary and ASCII stays exact), else binary.
io::WriteOptions output_options(const std::string& requested, io::Format out_format,
                                const io::ReadReport& input, bool keep_normals);

//! Writes the mesh with its attributes atomically and returns the writer's notes: what the
//! target format cannot hold, so nothing is lost silently.
std::vector<std::string> write_output(const Mesh& mesh, const io::MeshAttributes& attributes,
                                      const std::string& path, io::Format format,
                                      const io::WriteOptions& options);

//! `meshfair-cli smooth` and each file of `batch`: reads `mesh_path`, smooths it with
//! `recipe` (checked first, in the file's numbering; `recipe_name` names the recipe file in
//! errors) in the locality numbering, writes `out_path` atomically in the file's numbering
//! and returns the report with its timings. The editor's tests call it to compare the
//! editor with the CLI in process. Throws what the readers, the recipe check and the
//! writer throw.
nlohmann::json smooth_file(const std::string& mesh_path, const std::string& out_path,
                           const Recipe& recipe, const std::string& recipe_name,
                           const std::string& encoding, bool keep_normals);

} // namespace meshfair::cli
