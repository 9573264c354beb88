// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <string>
#include <vector>

#include "app/editor/editor_session.h"

namespace meshfair::app {

//! \brief One step of a scripted session (docs/editor.md, "Scripted sessions"). Points are
//! in framebuffer pixels, (0, 0) the top-left corner, as a mouse gives them.
struct ScriptAction
{
    enum class Kind
    {
        Tool,            //!< text: a tool name ("brush")
        Elements,        //!< text: "vertices" or "faces"
        Through,         //!< value: 1 selects through the surface
        BrushRadius,     //!< value: pixels
        Drag,            //!< points: press at the first, move through the rest, release at the last
        Click,           //!< points[0]: press and release there
        Scroll,          //!< value: wheel notches, points[0] the cursor
        Select,          //!< text: a selection command ("grow")
        Undo,            //!< count times
        Redo,            //!< count times
        View,            //!< text: a standard view ("front") or "all" / "selection" to frame
        Projection,      //!< text: "perspective" or "orthographic"
        Screenshot,      //!< text: a PNG path
        SaveMesh,        //!< text: a mesh path (format from the extension)
        CreateSet,       //!< text: a kind ("pin"); name: the set's name (empty: numbered)
        DeleteSet,       //!< name
        ShowSet,         //!< name; value: 1 show, 0 hide
        SelectSet,       //!< name
        MovePins,        //!< name; vector: the offset
        NormalDirection, //!< name; vector: the direction
        Solver,          //!< settings: the solver panel's values
        Step,            //!< count steps now
        Play,            //!< count frames of live solving on the solver's thread, then pause
        Reset,           //!< back to the base shape
        Apply,           //!< the current shape becomes the base
        ExportRecipe,    //!< text: a JSON path
        ImportRecipe,    //!< text: a JSON path
        Noise,           //!< value: sigma in mean edge lengths; count: the seed
        HeatMap,         //!< text: a term ("total") or "off"
        Autosave,        //!< write the recovery files now
        Recover          //!< restore the recovery files a crashed session left
    };
    Kind kind = Kind::Tool;
    std::string where; //!< "actions[3]", for messages
    std::string text;
    double value = 0;
    int count = 1;
    std::vector<ScreenPoint> points;
    MouseButton button = MouseButton::Left;
    Modifiers mods;
    std::string name; //!< a set's name
    Vec3 vector{0, 0, 0};
    SolverSettings settings;       //!< Solver: the values given, the others as they were...
    std::vector<std::string> keys; //!< ...these keys given
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

//! What playing a script needs from the program around the session.
class ScriptHost
{
public:
    virtual ~ScriptHost() = default;
    //! Lays out a frame of the interface, so that the view's rectangle is current.
    virtual void layout() = 0;
    //! Draws a frame and writes it as PNG.
    virtual void screenshot(const std::string& path) = 0;
};

//! \brief Plays the actions through the calls the window's mouse and keys make.
//! \throw WriteError when a screenshot, a mesh or a recipe cannot be written (files
//! already there are kept whole); InvalidInputError naming the action when it names a set
//! that does not exist, imports a recipe that cannot be read or does not fit, or runs the
//! solver on sets that cannot run (constraint_problems).
void play_script(const Script& script, EditorSession& session, ScriptHost& host);

} // namespace meshfair::app
