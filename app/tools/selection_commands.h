// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <string_view>

#include "app/edit/selection_command.h"
#include "app/tools/selection_tool.h"
#include "core/select/mesh_select.h"
#include "core/topology/topology.h"

namespace meshfair::app {

//! \brief Runs `command` on the selection of `kind` (the vertex mask or the face mask;
//! the other one is left alone).
//! \pre topology has the Neighbors, Corners and Edges parts; each mask has one flag per
//! element.
void run_selection_command(SelectionCommand command, ElementKind kind, const Mesh& mesh,
                           const Topology& topology, SelectionMask& vertices, SelectionMask& faces);

} // namespace meshfair::app
