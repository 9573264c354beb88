// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "app/editor/constraint_sets.h"
#include "app/render/camera.h"
#include "app/render/renderer.h"
#include "app/tools/selection_commands.h"
#include "app/tools/selection_tool.h"
#include "core/recipe/locality_run.h"
#include "core/select/mesh_select.h"

//! \file
//! \brief Every action of the editor, as one vocabulary: the key map, the menus, the
//! panels, the mouse tools and scripts all produce these commands, and
//! EditorSession::dispatch carries each out (undo state, the step's record, errors into the
//! status bar, what changed in the document). Sets are named by their (unique) names.

namespace meshfair::app::cmd {

// --- Selection and tools.
struct SetTool
{
    ToolKind tool = ToolKind::Navigate;
};
struct SetElements
{
    ElementKind elements = ElementKind::Vertices;
};
struct ToggleElements
{
};
struct SetThrough
{
    bool through = false;
};
struct SetBrushRadius
{
    double pixels = 24;
};
//! The brush radius times `factor`, within [2, 400] pixels ([ and ]).
struct ScaleBrushRadius
{
    double factor = 1;
};
//! A command of the Select menu on the current mode's selection.
struct RunSelection
{
    SelectionCommand command = SelectionCommand::All;
};
//! What a selection gesture covered: Replace clears the mode's selection first.
struct ApplySelection
{
    ElementKind elements = ElementKind::Vertices;
    SelectOp op = SelectOp::Add;
    std::vector<Index> indices;
    ToolKind tool = ToolKind::Click; //!< the gesture's tool, for the undo step's name
};

// --- History.
struct Undo
{
};
struct Redo
{
};

// --- The view (not undo steps).
struct FrameAll
{
};
struct FrameSelection
{
};
struct SetView
{
    StandardView view = StandardView::Front;
};
struct SetProjection
{
    Projection projection = Projection::Perspective;
};
struct ToggleProjection
{
};
struct SetOrbit
{
    OrbitStyle orbit = OrbitStyle::Turntable;
};
struct ToggleOrbit
{
};
//! The world's up axis: the front view again, framed, remembered for the file.
struct SetUpAxis
{
    UpAxis up = UpAxis::Y;
};
//! What the display toggles flip (keys and menus).
enum class DisplayToggle
{
    Shading,
    Wireframe,
    BoundaryEdges,
    VertexPoints,
    BackFaceTint,
    SidePanel,
    Help,
    EnergyPlot,
    EnergyLogScale,
    EnergyWholeMesh //!< the plot's energy of the whole mesh, or of what moves
};
struct Toggle
{
    DisplayToggle what = DisplayToggle::Wireframe;
};
//! New display options (the Display panel's widgets).
struct SetDisplay
{
    DisplayOptions display;
};

// --- Constraint sets (each an undo step).
//! \brief A set of `kind` from the selection; empty name: numbered ("pin 2"). A region
//! also takes in, with `close_holes`, what it encloses but leaves out (region_holes: the
//! pits a front-facing selection cannot see), in the same undo step, and says how many.
struct CreateSet
{
    ConstraintKind kind = ConstraintKind::Region;
    std::string name;
    bool close_holes = true;
};
struct DeleteSet
{
    std::string set;
};
struct RenameSet
{
    std::string set, name;
};
//! Shows or hides the set's glyphs (display only, not an undo step).
struct ShowSet
{
    std::string set;
    bool visible = true;
};
struct SetColor
{
    std::string set;
    std::array<float, 3> color{1, 1, 1};
};
//! Replaces the selection with the set's elements (and switches to its mode).
struct SelectSet
{
    std::string set;
};
//! Gives every face of a normal set the unit direction of `direction` (not zero).
struct SetNormalDirection
{
    std::string set;
    Vec3 direction{0, 0, 1};
};
//! Adds the selection to a set (as CreateSet takes it: vertex kinds take vertices).
struct AddToSet
{
    std::string set;
};
//! Takes the selection out of a set.
struct RemoveFromSet
{
    std::string set;
};
//! Adds to a region set what it encloses but leaves out (region_holes).
struct CloseHoles
{
    std::string set;
};
//! Takes a set into the solve or out of it (its glyphs stay as shown).
struct EnableSet
{
    std::string set;
    bool enabled = true;
};
//! A set's own weight mu (anchor, centroid, normal and soft normal sets).
struct SetSetWeight
{
    std::string set;
    Scalar mu = 1;
};
//! \brief Moves a pin set's targets by `offset`; with `dome`, first takes those solver
//! settings (the M tool's first move, when the settings raise no dome: dome_settings), in
//! the same undo step.
struct MovePins
{
    std::string set;
    Vec3 offset{0, 0, 0};
    std::optional<SolverSettings> dome{};
};
//! \brief One dab of the Paint tool, in the world, so that a script replays a stroke
//! bit for bit: the vertices within `radius` of `center` (at the current positions) change
//! the weight map of `set` by strength * curve(distance / radius) (PaintMode). A set that
//! is not there is made by Relax and Add (a region). Relax then puts the shape back to
//! where the stroke began and runs `steps` solver steps of the whole recipe with the map
//! as it is now: a stroke is one undo step, and the recipe exported after it (from the
//! base shape) reproduces its shape. A stroke's dabs share one Interaction.
struct PaintDab
{
    std::string set{kPaintSet};
    PaintMode mode = PaintMode::Relax;
    Vec3 center{0, 0, 0};
    Scalar radius = 1;
    Scalar strength = 0.5;
    FalloffCurve curve = FalloffCurve::Smooth;
    int steps = 10;
};
//! New settings of the Paint tool (not an undo step).
struct SetPaintSettings
{
    PaintSettings paint;
};

// --- Solving.
//! New solver settings (a slider dragged through many values is one undo step: the
//! dispatch's interaction merges them).
struct SetSolverSettings
{
    SolverSettings settings;
};
//! Live solving on the solver's thread; `frames` > 0: pause by itself after them.
struct Play
{
    int frames = 0;
};
struct Pause
{
};
struct TogglePlay
{
};
//! `steps` steps now (0: the settings' steps per frame).
struct Step
{
    int steps = 0;
};
//! \brief Shows the minimizer of the sets: the direct method from now on (a settings
//! change, undone as one), so the shape is solved again whenever the sets change and a
//! dragged pin's shape is the minimizer at every move.
struct Solve
{
};
//! \brief Stops the solver's preparation pending or under way (the direct method's
//! ordering and factorization, seconds on a large mesh): the shape stays as it is, and
//! nothing is prepared again until Play, Step or Solve asks or the sets change. Not an
//! undo step: it changes nothing of the document.
struct CancelPreparation
{
};
struct ResetShape
{
};
struct ApplyShape
{
};
//! Gaussian noise of `sigma` mean edge lengths (as meshfair-cli noise); the noisy shape
//! becomes the base.
struct AddNoise
{
    Scalar sigma = 0.3;
    std::uint64_t seed = 1;
};
//! The heat map of a term's energy shares (nullopt: off). Display only.
struct SetHeatMap
{
    std::optional<EnergyTerm> term;
};

// --- Files and the program.
struct OpenMesh
{
    std::string path;
};
//! Saves the mesh (format from the extension, atomic); empty path: the file it came from.
struct SaveMesh
{
    std::string path;
};
struct ExportRecipe
{
    std::string path;
};
struct ImportRecipe
{
    std::string path;
};
//! \brief A preset recipe (assets/recipes/NAME.json, or a path) over the user's sets: its
//! settings, and its sets of the kinds it has, replace the editor's; the user's sets of the
//! kinds it does not have stay, and so do the user's regions and pins (what to smooth and
//! what holds is the artist's; a preset's own regions or pins come in only where the user
//! has none of that kind).
struct ApplyPreset
{
    std::string preset;
};
//! The file dialogs and prompts of the interface.
enum class Dialog
{
    OpenMesh,
    SaveMeshAs,
    ExportRecipe,
    ImportRecipe
};
struct ShowDialog
{
    Dialog dialog = Dialog::OpenMesh;
};
//! The view as PNG (empty path: meshfair-screenshot-N.png, or the --screenshot path).
struct Screenshot
{
    std::string path;
};
//! Quits, asking first when there are unsaved changes.
struct Quit
{
};
//! Quits without asking (the prompt's "Discard and quit").
struct QuitDiscarding
{
};
struct Recover
{
};
struct DiscardRecovery
{
};
//! Writes the recovery files now.
struct Autosave
{
};

} // namespace meshfair::app::cmd

namespace meshfair::app {

using Command = std::variant<
    cmd::SetTool, cmd::SetElements, cmd::ToggleElements, cmd::SetThrough, cmd::SetBrushRadius,
    cmd::ScaleBrushRadius, cmd::RunSelection, cmd::ApplySelection, cmd::Undo, cmd::Redo,
    cmd::FrameAll, cmd::FrameSelection, cmd::SetView, cmd::SetProjection, cmd::ToggleProjection,
    cmd::SetOrbit, cmd::ToggleOrbit, cmd::SetUpAxis, cmd::Toggle, cmd::SetDisplay, cmd::CreateSet,
    cmd::DeleteSet, cmd::RenameSet, cmd::ShowSet, cmd::SetColor, cmd::SelectSet, cmd::AddToSet,
    cmd::RemoveFromSet, cmd::CloseHoles, cmd::EnableSet, cmd::SetSetWeight, cmd::SetNormalDirection,
    cmd::MovePins, cmd::PaintDab, cmd::SetPaintSettings, cmd::SetSolverSettings, cmd::Play,
    cmd::Pause, cmd::TogglePlay, cmd::Step, cmd::Solve, cmd::CancelPreparation, cmd::ResetShape,
    cmd::ApplyShape, cmd::AddNoise, cmd::SetHeatMap, cmd::OpenMesh, cmd::SaveMesh,
    cmd::ExportRecipe, cmd::ImportRecipe, cmd::ApplyPreset, cmd::ShowDialog, cmd::Screenshot,
    cmd::Quit, cmd::QuitDiscarding, cmd::Recover, cmd::DiscardRecovery, cmd::Autosave>;

//! \brief Where a command comes from, for the undo step it makes: commands of one
//! interaction (a drag of a tool, a slider held) with the same key merge into one step,
//! which ends when the interaction does (EditorSession::end_interaction). Empty: the
//! command is a step of its own.
struct Interaction
{
    std::string key;
};

//! A short name of the command, for messages ("create set", "undo").
std::string_view command_name(const Command& command);

//! What a command does to the document, for the undo step it makes.
struct CommandSpec
{
    std::string label;             //!< the undo step's name
    unsigned captures = 0;         //!< the parts its undo step keeps (0: not an undo step)
    unsigned bumps = 0;            //!< the parts whose versions it bumps when done
    bool stops_run = false;        //!< a run playing is paused (its segment recorded) first
    bool waits_for_gesture = true; //!< refused while a tool's gesture is under way
};
CommandSpec spec_of(const Command& command);

} // namespace meshfair::app
