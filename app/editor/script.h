// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/edit/command.h"
#include "app/editor/input_event.h"

namespace meshfair::app {

class EditorFrame;
class EditorSession;

//! \brief One step of a scripted session (docs/editor.md, "Scripted sessions"): editor
//! commands, as the key map and the panels give them, or raw input a person gives (mouse
//! moves, presses and releases, keys, typed text, clicks on a widget of the interface by
//! its label), fed through the window's input router. Points are framebuffer pixels,
//! (0, 0) the top-left corner, as a mouse gives them.
struct ScriptAction
{
    enum class Kind
    {
        Commands,    //!< `commands`, dispatched in turn
        Input,       //!< `events`, through the input router, frames run until they are taken
        ClickWidget, //!< `text`: a widget's label (EditorUi::widget); a press and a release on it
        Screenshot,  //!< `text`: a PNG path
        Play,        //!< `count` frames of live solving on the solver's thread, then pause
        Frames       //!< `count` frames of the interface with no input
    };
    Kind kind = Kind::Commands;
    std::string where; //!< "actions[3]", for messages
    std::vector<Command> commands;
    //! Commands: the list is dispatched this many times in turn ("undo": 500 is one Undo
    //! played 500 times, not 500 commands held).
    int repeat = 1;
    std::vector<InputEvent> events;
    std::string text;
    int count = 1;
    Modifiers mods;      //!< ClickWidget's
    bool writes = false; //!< a failure is an output that could not be written
    bool waits_for_heat = false;
    //! A solver action's keys: its command's settings give only these, merged into the
    //! settings of the moment when it is played.
    std::vector<std::string> keys;
    //! Commands: one interaction, so one undo step (a stroke's dabs); empty: each its own.
    std::string interaction;
};

struct Script
{
    std::string name; //!< the file, for messages
    std::vector<ScriptAction> actions;
};

//! \brief Reads a script: {"actions": [...]} or the list by itself. Every action is checked
//! before any is played.
//! \throw InvalidInputError naming the file and the action at fault (with line and column
//! for JSON that does not parse).
Script parse_script(const std::string& text, const std::string& name);
Script read_script(const std::string& path);

//! A script action's key and the options it takes beside it.
struct ScriptActionSyntax
{
    std::string_view name;
    std::vector<std::string_view> options;
};
//! \brief Every action a script may give, the commands' first (from their definitions,
//! app/edit/command.h), then raw input: the dictionary of the script reader, its fuzzer's
//! (tests/fuzz/dict/script.dict) and docs/editor.md's table.
std::vector<ScriptActionSyntax> script_actions();

//! Throws the InvalidInputError of a script's action: "'name': where: why".
[[noreturn]] void script_error(const std::string& name, const std::string& where,
                               const std::string& why);

//! \brief A stroke's dabs (one set, mode, radius, strength, curve and steps) as the script
//! action that replays them bit for bit: {"paint": {..., "dabs": [[x, y, z], ...]}} on one
//! line; the editor's trace prints it at the end of each Paint stroke.
std::string stroke_action(std::span<const cmd::PaintDab> dabs);

//! One input event of `type` at `p` (framebuffer pixels).
InputEvent input_event(InputEvent::Type type, ScreenPoint p, MouseButton button = MouseButton::Left,
                       Modifiers mods = {});
//! \brief A drag as a mouse gives it: a move to the first point, a press, moves through the
//! others, a release at the last (a click: two equal points).
std::vector<InputEvent> drag_events(const std::vector<ScreenPoint>& points, MouseButton button,
                                    Modifiers mods);

//! \brief A key chord as a keyboard gives it: the modifiers pressed, the key pressed (with
//! its character when it types one), the key released, the modifiers released.
std::vector<InputEvent> key_events(const KeyChord& chord);

//! What playing a script needs from the program around the session.
class ScriptHost
{
public:
    virtual ~ScriptHost() = default;
    //! Runs one frame of the interface and input (EditorFrame::run), without drawing.
    virtual void run_frame() = 0;
    //! The frame driver: its input router takes the script's raw input.
    virtual EditorFrame& frame_driver() = 0;
    //! Draws a frame and writes it as PNG.
    virtual void screenshot(const std::string& path) = 0;
};

//! \brief Plays the actions as a person's input and the key map's commands would.
//! \throw WriteError when a screenshot, a mesh or a recipe cannot be written (files
//! already there are kept whole); InvalidInputError naming the action when a command fails
//! (a set that does not exist, a recipe that cannot be read or does not fit, sets that
//! cannot run) or a widget it clicks is not on screen.
void play_script(const Script& script, EditorSession& session, ScriptHost& host);

} // namespace meshfair::app
