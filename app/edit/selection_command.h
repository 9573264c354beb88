// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <string_view>

namespace meshfair::app {

//! The selection commands that need no gesture (the Select menu and its keys).
enum class SelectionCommand
{
    All,       //!< every element
    Clear,     //!< none
    Invert,    //!< every flag flipped
    Grow,      //!< one ring more
    Shrink,    //!< one ring less
    Connected, //!< the connected components of the selection
    Boundary   //!< the boundary's vertices, or the faces with a boundary edge
};

//! The command's name in scripts and menus ("all", "clear", "invert", "grow", ...).
std::string_view command_name(SelectionCommand command);
//! The command named `name`, if any.
std::optional<SelectionCommand> selection_command_named(std::string_view name);

} // namespace meshfair::app
