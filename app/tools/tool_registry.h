// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <memory>

#include "app/tools/interactive_tool.h"

namespace meshfair::app {

inline constexpr int kToolKinds = 8;

//! \brief Every tool of the left mouse button, one per ToolKind but Navigate (which only
//! orbits): the selection tools, MovePins, AimNormals and Paint.
class ToolRegistry
{
public:
    ToolRegistry();
    //! The tool of `kind`; nullptr for Navigate.
    InteractiveTool* find(ToolKind kind) const;

private:
    std::array<std::unique_ptr<InteractiveTool>, kToolKinds> tools_;
};

} // namespace meshfair::app
