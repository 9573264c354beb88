// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/tools/selection_commands.h"

#include <algorithm>
#include <array>
#include <utility>

namespace meshfair::app {

void run_selection_command(SelectionCommand command, ElementKind kind, const Mesh& mesh,
                           const Topology& topology, SelectionMask& vertices, SelectionMask& faces)
{
    const bool on_faces = kind == ElementKind::Faces;
    SelectionMask& mask = on_faces ? faces : vertices;
    switch (command)
    {
        case SelectionCommand::All:
            std::fill(mask.begin(), mask.end(), 1);
            break;
        case SelectionCommand::Clear:
            std::fill(mask.begin(), mask.end(), 0);
            break;
        case SelectionCommand::Invert:
            invert_selection(mask);
            break;
        case SelectionCommand::Grow:
            mask = on_faces ? grow_faces(mesh, topology, mask) : grow_vertices(topology, mask);
            break;
        case SelectionCommand::Shrink:
            mask = on_faces ? shrink_faces(mesh, topology, mask) : shrink_vertices(topology, mask);
            break;
        case SelectionCommand::Connected:
        {
            const std::vector<Index> seeds = selected_indices(mask);
            mask = on_faces ? connected_faces(mesh, topology, seeds)
                            : connected_vertices(topology, seeds);
            break;
        }
        case SelectionCommand::Boundary:
            mask = on_faces ? boundary_faces(mesh, topology) : boundary_vertices(topology);
            break;
    }
}

} // namespace meshfair::app
