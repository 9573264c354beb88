// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/edit/command.h"
#include "app/editor/input_event.h"

namespace meshfair::app {

//! One chord of a binding and the command it gives.
struct KeyAction
{
    KeyChord chord;
    Command command;
};

//! \brief One row of the bindings table, as the help overlay and docs/editor.md list it:
//! the input, what it does, and the key chords that do it (none for mouse rows, which the
//! input router and the tools handle).
struct KeyBinding
{
    const char* input;
    const char* action;
    std::vector<KeyAction> keys;
};

//! Every binding of the editor, in the order of the help overlay.
std::span<const KeyBinding> key_bindings();

//! \brief The command a key chord gives (modifiers must match exactly), if any: what the
//! input router dispatches when a key reaches the view.
std::optional<Command> command_for_key(const KeyChord& chord);

//! The first key chord bound to `command` (an equal command), if any: the menus' shortcut.
std::optional<KeyChord> key_for(const Command& command);

//! A chord as a menu shows it: "Ctrl+Shift+Z", "F12", "Numpad 5", "Home", "Space".
std::string chord_label(const KeyChord& chord);

} // namespace meshfair::app
