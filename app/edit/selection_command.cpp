// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/edit/selection_command.h"

#include <array>
#include <utility>

namespace meshfair::app {

namespace {

constexpr std::array<std::pair<SelectionCommand, std::string_view>, 7> kNames = {{
    {SelectionCommand::All, "all"},
    {SelectionCommand::Clear, "clear"},
    {SelectionCommand::Invert, "invert"},
    {SelectionCommand::Grow, "grow"},
    {SelectionCommand::Shrink, "shrink"},
    {SelectionCommand::Connected, "connected"},
    {SelectionCommand::Boundary, "boundary"},
}};

} // namespace

std::string_view command_name(SelectionCommand command)
{
    for (const auto& [c, name] : kNames)
        if (c == command)
            return name;
    return {};
}

std::optional<SelectionCommand> selection_command_named(std::string_view name)
{
    for (const auto& [c, n] : kNames)
        if (n == name)
            return c;
    return std::nullopt;
}

} // namespace meshfair::app
