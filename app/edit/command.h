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

#include "app/edit/constraint_sets.h"
#include "app/edit/edit_parts.h"
#include "app/edit/operator.h"
#include "app/edit/selection_command.h"
#include "app/edit/tool_settings.h"
#include "app/render/camera.h"
#include "app/render/renderer.h"
#include "core/recipe/locality_run.h"
#include "core/select/mesh_select.h"

//! \file
//! \brief Every action of the editor, as one vocabulary: the key map, the menus, the
//! panels, the mouse tools and scripts all produce these commands, and
//! EditorSession::dispatch carries each out (undo state, the step's record, errors into the
//! status bar, what changed in the document). Sets are named by their (unique) names.

namespace meshfair::app {

//! What a command does to the document, for the undo step it makes.
struct CommandSpec
{
    std::string label;             //!< the undo step's name
    unsigned captures = 0;         //!< the parts its undo step keeps (0: not an undo step)
    unsigned bumps = 0;            //!< the parts whose versions it bumps when done
    bool stops_run = false;        //!< a run playing is paused (its segment recorded) first
    bool waits_for_gesture = true; //!< refused while a tool's gesture is under way
};

} // namespace meshfair::app

namespace meshfair::app::cmd {

// --- Selection and tools.
struct SetTool
{
    ToolKind tool = ToolKind::Navigate;
    static constexpr OperatorInfo info{.id = "tool", .script = "tool"};
    static constexpr auto fields = std::tuple{
        enum_field(&SetTool::tool, tool_named,
                   "navigate, click, brush, rectangle, lasso, move_pins, aim_normals or paint")};
    bool operator==(const SetTool&) const = default;
};
struct SetElements
{
    ElementKind elements = ElementKind::Vertices;
    static constexpr OperatorInfo info{.id = "elements", .script = "elements"};
    static constexpr auto fields =
        std::tuple{enum_field(&SetElements::elements, element_kind_named, "vertices or faces")};
    bool operator==(const SetElements&) const = default;
};
struct ToggleElements
{
    static constexpr OperatorInfo info{.id = "toggle elements"};
    bool operator==(const ToggleElements&) const = default;
};
struct SetThrough
{
    bool through = false;
    static constexpr OperatorInfo info{
        .id = "through",
        .script = "through",
    };
    static constexpr auto fields = std::tuple{value_field(&SetThrough::through)};
    bool operator==(const SetThrough&) const = default;
};
struct SetBrushRadius
{
    double pixels = 24;
    static constexpr OperatorInfo info{
        .id = "brush radius",
        .waits_for_gesture = false,
        .script = "brush_radius",
    };
    static constexpr auto fields = std::tuple{number_field(&SetBrushRadius::pixels, 1, 1000)};
    bool operator==(const SetBrushRadius&) const = default;
};
//! The brush radius times `factor`, within [2, 400] pixels ([ and ]).
struct ScaleBrushRadius
{
    double factor = 1;
    static constexpr OperatorInfo info{.id = "brush radius", .waits_for_gesture = false};
    bool operator==(const ScaleBrushRadius&) const = default;
};
//! A command of the Select menu on the current mode's selection.
struct RunSelection
{
    SelectionCommand command = SelectionCommand::All;
    static constexpr OperatorInfo info{
        .id = "select",
        .label = "select",
        .captures = kSelection,
        .bumps = kSelection,
        .script = "select",
    };
    static constexpr auto fields =
        std::tuple{enum_field(&RunSelection::command, selection_command_named,
                              "all, clear, invert, grow, shrink, connected or boundary")};
    static CommandSpec spec_for(const RunSelection& c);
    bool operator==(const RunSelection&) const = default;
    static std::string menu_label_for(const RunSelection& c);
};
//! What a selection gesture covered: Replace clears the mode's selection first.
struct ApplySelection
{
    ElementKind elements = ElementKind::Vertices;
    SelectOp op = SelectOp::Add;
    std::vector<Index> indices;
    ToolKind tool = ToolKind::Click; //!< the gesture's tool, for the undo step's name
    static constexpr OperatorInfo info{.id = "select",
                                       .label = "select",
                                       .captures = kSelection,
                                       .bumps = kSelection,
                                       .waits_for_gesture = false};
    static CommandSpec spec_for(const ApplySelection& c);
    bool operator==(const ApplySelection&) const = default;
};

// --- History.
struct Undo
{
    static constexpr OperatorInfo info{
        .id = "undo", .menu = "Undo", .stops_run = true, .script = "undo", .own_reader = true};
    bool operator==(const Undo&) const = default;
};
struct Redo
{
    static constexpr OperatorInfo info{
        .id = "redo", .menu = "Redo", .stops_run = true, .script = "redo", .own_reader = true};
    bool operator==(const Redo&) const = default;
};

// --- The view (not undo steps).
struct FrameAll
{
    static constexpr OperatorInfo info{
        .id = "frame all", .menu = "Frame all", .waits_for_gesture = false};
    bool operator==(const FrameAll&) const = default;
};
struct FrameSelection
{
    static constexpr OperatorInfo info{
        .id = "frame selection", .menu = "Frame selection", .waits_for_gesture = false};
    bool operator==(const FrameSelection&) const = default;
};
struct SetView
{
    StandardView view = StandardView::Front;
    static constexpr OperatorInfo info{
        .id = "view", .waits_for_gesture = false, .script = "view", .own_reader = true};
    bool operator==(const SetView&) const = default;
    static std::string menu_label_for(const SetView& c);
};
struct SetProjection
{
    Projection projection = Projection::Perspective;
    static constexpr OperatorInfo info{
        .id = "projection",
        .waits_for_gesture = false,
        .script = "projection",
    };
    static constexpr auto fields = std::tuple{
        enum_field(&SetProjection::projection, projection_named, "perspective or orthographic")};
    bool operator==(const SetProjection&) const = default;
};
struct ToggleProjection
{
    static constexpr OperatorInfo info{
        .id = "projection", .menu = "Orthographic", .waits_for_gesture = false};
    bool operator==(const ToggleProjection&) const = default;
};
struct SetOrbit
{
    OrbitStyle orbit = OrbitStyle::Turntable;
    static constexpr OperatorInfo info{.id = "orbit", .waits_for_gesture = false};
    bool operator==(const SetOrbit&) const = default;
};
struct ToggleOrbit
{
    static constexpr OperatorInfo info{
        .id = "orbit", .menu = "Trackball orbit", .waits_for_gesture = false};
    bool operator==(const ToggleOrbit&) const = default;
};
//! The world's up axis: the front view again, framed, remembered for the file.
struct SetUpAxis
{
    UpAxis up = UpAxis::Y;
    static constexpr OperatorInfo info{
        .id = "up axis",
        .waits_for_gesture = false,
        .script = "up_axis",
    };
    static constexpr auto fields = std::tuple{enum_field(
        &SetUpAxis::up, up_axis_named, "\"+x\", \"-x\", \"+y\", \"-y\", \"+z\" or \"-z\"")};
    bool operator==(const SetUpAxis&) const = default;
    static std::string menu_label_for(const SetUpAxis& c);
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
    static constexpr OperatorInfo info{.id = "toggle", .waits_for_gesture = false};
    bool operator==(const Toggle&) const = default;
    static std::string menu_label_for(const Toggle& c);
};
//! New display options (the Display panel's widgets).
struct SetDisplay
{
    DisplayOptions display;
    static constexpr OperatorInfo info{.id = "display", .waits_for_gesture = false};
    bool operator==(const SetDisplay&) const = default;
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
    static constexpr OperatorInfo info{
        .id = "create set",
        .label = "new set",
        .captures = kSets,
        .bumps = kSets | kSetMembers,
        .script = "create_set",
    };
    static constexpr auto fields = std::tuple{
        enum_field(&CreateSet::kind, kind_named,
                   "region, pin, anchor, centroid, normal, hard_normal or soft_normal"),
        option_field("name", &CreateSet::name, FieldPlace::Option, "its name (default: numbered)"),
        option_field("close_holes", &CreateSet::close_holes, FieldPlace::Option,
                     "a region takes in the holes it encloses (default: true)")};
    bool operator==(const CreateSet&) const = default;
};
struct DeleteSet
{
    std::string set;
    static constexpr OperatorInfo info{
        .id = "delete set",
        .label = "delete set",
        .captures = kSets,
        .bumps = kSets | kSetMembers,
        .script = "delete_set",
    };
    static constexpr auto fields = std::tuple{value_field(&DeleteSet::set)};
    bool operator==(const DeleteSet&) const = default;
};
struct RenameSet
{
    std::string set, name;
    static constexpr OperatorInfo info{
        .id = "rename set",
        .label = "rename set",
        .captures = kSets,
        .bumps = kSets | kSetMembers,
        .script = "rename_set",
    };
    static constexpr auto fields = std::tuple{
        value_field(&RenameSet::set),
        option_field("name", &RenameSet::name, FieldPlace::RequiredOption, "the new name")};
    bool operator==(const RenameSet&) const = default;
};
//! Shows or hides the set's glyphs (display only, not an undo step).
struct ShowSet
{
    std::string set;
    bool visible = true;
    static constexpr OperatorInfo info{.id = "show set",
                                       .bumps = kSets,
                                       .waits_for_gesture = false,
                                       .script = "show_set",
                                       .script_alias = "hide_set",
                                       .own_reader = true};
    bool operator==(const ShowSet&) const = default;
};
struct SetColor
{
    std::string set;
    std::array<float, 3> color{1, 1, 1};
    static constexpr OperatorInfo info{
        .id = "set colour", .label = "set colour", .captures = kSets, .bumps = kSets};
    bool operator==(const SetColor&) const = default;
};
//! Replaces the selection with the set's elements (and switches to its mode).
struct SelectSet
{
    std::string set;
    static constexpr OperatorInfo info{
        .id = "select set",
        .label = "select set",
        .captures = kSelection,
        .bumps = kSelection,
        .script = "select_set",
    };
    static constexpr auto fields = std::tuple{value_field(&SelectSet::set)};
    bool operator==(const SelectSet&) const = default;
};
//! Gives every face of a normal set the unit direction of `direction` (not zero).
struct SetNormalDirection
{
    std::string set;
    Vec3 direction{0, 0, 1};
    static constexpr OperatorInfo info{
        .id = "normal direction",
        .label = "normal direction",
        .captures = kSets,
        .bumps = kSets,
        .waits_for_gesture = false,
        .script = "normal_direction",
    };
    static constexpr auto fields =
        std::tuple{value_field(&SetNormalDirection::set),
                   nonzero_field("direction", &SetNormalDirection::direction)};
    bool operator==(const SetNormalDirection&) const = default;
};
//! Adds the selection to a set (as CreateSet takes it: vertex kinds take vertices).
struct AddToSet
{
    std::string set;
    static constexpr OperatorInfo info{
        .id = "add to set", .label = "add to set", .captures = kSets, .bumps = kSets | kSetMembers};
    bool operator==(const AddToSet&) const = default;
};
//! Takes the selection out of a set.
struct RemoveFromSet
{
    std::string set;
    static constexpr OperatorInfo info{.id = "remove from set",
                                       .label = "remove from set",
                                       .captures = kSets,
                                       .bumps = kSets | kSetMembers};
    bool operator==(const RemoveFromSet&) const = default;
};
//! Adds to a region set what it encloses but leaves out (region_holes).
struct CloseHoles
{
    std::string set;
    static constexpr OperatorInfo info{.id = "close holes",
                                       .label = "close holes",
                                       .captures = kSets,
                                       .bumps = kSets | kSetMembers};
    bool operator==(const CloseHoles&) const = default;
};
//! Takes a set into the solve or out of it (its glyphs stay as shown).
struct EnableSet
{
    std::string set;
    bool enabled = true;
    static constexpr OperatorInfo info{
        .id = "enable set", .label = "enable set", .captures = kSets, .bumps = kSets | kSetMembers};
    static CommandSpec spec_for(const EnableSet& c);
    bool operator==(const EnableSet&) const = default;
};
//! A set's own weight mu (anchor, centroid, normal and soft normal sets).
struct SetSetWeight
{
    std::string set;
    Scalar mu = 1;
    static constexpr OperatorInfo info{
        .id = "set weight", .label = "set weight", .captures = kSets, .bumps = kSets};
    bool operator==(const SetSetWeight&) const = default;
};
//! \brief Moves a pin set's targets by `offset`; with `dome`, first takes those solver
//! settings (the M tool's first move, when the settings raise no dome: dome_settings), in
//! the same undo step.
struct MovePins
{
    std::string set;
    Vec3 offset{0, 0, 0};
    std::optional<SolverSettings> dome{};
    static constexpr OperatorInfo info{
        .id = "move pins",
        .label = "move pins",
        .captures = kSets | kSettings,
        .bumps = kSets,
        .waits_for_gesture = false,
        .script = "move_pins",
    };
    static constexpr auto fields = std::tuple{
        value_field(&MovePins::set),
        option_field("offset", &MovePins::offset, FieldPlace::RequiredOption, "[x, y, z]")};
    static CommandSpec spec_for(const MovePins& c);
    bool operator==(const MovePins&) const = default;
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
    static constexpr OperatorInfo info{.id = "paint",
                                       .label = "smooth stroke",
                                       .captures = kSets | kPositions,
                                       .bumps = kSets | kSetMembers,
                                       .stops_run = true,
                                       .waits_for_gesture = false,
                                       .script = "paint",
                                       .own_reader = true};
    static CommandSpec spec_for(const PaintDab& c);
    bool operator==(const PaintDab&) const = default;
};
//! New settings of the Paint tool (not an undo step).
struct SetPaintSettings
{
    PaintSettings paint;
    static constexpr OperatorInfo info{.id = "paint settings",
                                       .waits_for_gesture = false,
                                       .script = "paint_settings",
                                       .own_reader = true};
    bool operator==(const SetPaintSettings&) const = default;
};

// --- Solving.
//! New solver settings (a slider dragged through many values is one undo step: the
//! dispatch's interaction merges them).
struct SetSolverSettings
{
    SolverSettings settings;
    static constexpr OperatorInfo info{.id = "solver settings",
                                       .label = "solver settings",
                                       .captures = kSettings,
                                       .bumps = kSettings,
                                       .script = "solver",
                                       .own_reader = true};
    bool operator==(const SetSolverSettings&) const = default;
};
//! Live solving on the solver's thread; `frames` > 0: pause by itself after them.
struct Play
{
    int frames = 0;
    static constexpr OperatorInfo info{.id = "play", .script = "play", .own_reader = true};
    bool operator==(const Play&) const = default;
};
struct Pause
{
    static constexpr OperatorInfo info{.id = "pause"};
    bool operator==(const Pause&) const = default;
};
struct TogglePlay
{
    static constexpr OperatorInfo info{.id = "play/pause", .menu = "Play / pause"};
    bool operator==(const TogglePlay&) const = default;
};
//! `steps` steps now (0: the settings' steps per frame).
struct Step
{
    int steps = 0;
    static constexpr OperatorInfo info{
        .id = "step",
        .menu = "Step",
        .label = "step",
        .captures = kPositions,
        .stops_run = true,
        .script = "step",
    };
    static constexpr auto fields = std::tuple{number_field(&Step::steps, 1, 1000000)};
    bool operator==(const Step&) const = default;
};
//! \brief Shows the minimizer of the sets: the direct method from now on (a settings
//! change, undone as one), so the shape is solved again whenever the sets change and a
//! dragged pin's shape is the minimizer at every move.
struct Solve
{
    static constexpr OperatorInfo info{
        .id = "solve",
        .menu = "Solve: the minimizer",
        .label = "solve",
        .captures = kSettings,
        .bumps = kSettings,
        .script = "solve",
    };
    static constexpr std::tuple<> fields{};
    bool operator==(const Solve&) const = default;
};
//! \brief Stops the solver's preparation pending or under way (the direct method's
//! ordering and factorization, seconds on a large mesh): the shape stays as it is, and
//! nothing is prepared again until Play, Step or Solve asks or the sets change. Not an
//! undo step: it changes nothing of the document.
struct CancelPreparation
{
    static constexpr OperatorInfo info{
        .id = "cancel preparation",
        .menu = "Cancel preparation",
        .waits_for_gesture = false,
        .script = "cancel_preparation",
    };
    static constexpr std::tuple<> fields{};
    bool operator==(const CancelPreparation&) const = default;
};
struct ResetShape
{
    static constexpr OperatorInfo info{
        .id = "reset",
        .label = "reset shape",
        .captures = kPositions,
        .bumps = kPositions,
        .stops_run = true,
        .script = "reset",
    };
    static constexpr std::tuple<> fields{};
    bool operator==(const ResetShape&) const = default;
};
struct ApplyShape
{
    static constexpr OperatorInfo info{
        .id = "apply",
        .label = "apply shape",
        .captures = kPositions | kBasePositions,
        .bumps = kBasePositions,
        .stops_run = true,
        .script = "apply",
    };
    static constexpr std::tuple<> fields{};
    bool operator==(const ApplyShape&) const = default;
};
//! Gaussian noise of `sigma` mean edge lengths (as meshfair-cli noise); the noisy shape
//! becomes the base.
struct AddNoise
{
    Scalar sigma = 0.3;
    std::uint64_t seed = 1;
    static constexpr OperatorInfo info{
        .id = "noise",
        .label = "noise",
        .captures = kPositions | kBasePositions,
        .bumps = kPositions | kBasePositions,
        .stops_run = true,
        .script = "noise",
    };
    static constexpr auto fields =
        std::tuple{number_field(&AddNoise::sigma, 0, 10),
                   number_field(&AddNoise::seed, 0, 2147483647, FieldPlace::Option, "seed")};
    bool operator==(const AddNoise&) const = default;
};
//! The heat map of a term's energy shares (nullopt: off). Display only.
struct SetHeatMap
{
    std::optional<EnergyTerm> term;
    static constexpr OperatorInfo info{
        .id = "heat map", .waits_for_gesture = false, .script = "heat_map", .own_reader = true};
    bool operator==(const SetHeatMap&) const = default;
};

// --- Files and the program.
struct OpenMesh
{
    std::string path;
    static constexpr OperatorInfo info{.id = "open", .stops_run = true};
    bool operator==(const OpenMesh&) const = default;
};
//! Saves the mesh (format from the extension, atomic); empty path: the file it came from.
struct SaveMesh
{
    std::string path;
    static constexpr OperatorInfo info{
        .id = "save", .menu = "Save", .script = "save_mesh", .writes = true};
    static constexpr auto fields = std::tuple{value_field(&SaveMesh::path, "a file name")};
    bool operator==(const SaveMesh&) const = default;
};
struct ExportRecipe
{
    std::string path;
    static constexpr OperatorInfo info{
        .id = "export recipe", .script = "export_recipe", .writes = true};
    static constexpr auto fields = std::tuple{value_field(&ExportRecipe::path, "a file name")};
    bool operator==(const ExportRecipe&) const = default;
};
struct ImportRecipe
{
    std::string path;
    static constexpr OperatorInfo info{
        .id = "import recipe",
        .label = "import recipe",
        .captures = kSets | kSettings,
        .bumps = kSets | kSettings | kSetMembers,
        .stops_run = true,
        .script = "import_recipe",
    };
    static constexpr auto fields = std::tuple{value_field(&ImportRecipe::path, "a file name")};
    bool operator==(const ImportRecipe&) const = default;
};
//! \brief A preset recipe (assets/recipes/NAME.json, or a path) over the user's sets: its
//! settings, and its sets of the kinds it has, replace the editor's; the user's sets of the
//! kinds it does not have stay, and so do the user's regions and pins (what to smooth and
//! what holds is the artist's; a preset's own regions or pins come in only where the user
//! has none of that kind).
struct ApplyPreset
{
    std::string preset;
    static constexpr OperatorInfo info{
        .id = "preset",
        .label = "preset",
        .captures = kSets | kSettings,
        .bumps = kSets | kSettings | kSetMembers,
        .stops_run = true,
        .script = "preset",
    };
    static constexpr auto fields = std::tuple{value_field(&ApplyPreset::preset)};
    bool operator==(const ApplyPreset&) const = default;
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
    static constexpr OperatorInfo info{.id = "dialog"};
    bool operator==(const ShowDialog&) const = default;
    static std::string menu_label_for(const ShowDialog& c);
};
//! The view as PNG (empty path: meshfair-screenshot-N.png, or the --screenshot path).
struct Screenshot
{
    std::string path;
    static constexpr OperatorInfo info{
        .id = "screenshot", .menu = "Screenshot", .waits_for_gesture = false};
    bool operator==(const Screenshot&) const = default;
};
//! Quits, asking first when there are unsaved changes.
struct Quit
{
    static constexpr OperatorInfo info{.id = "quit", .menu = "Quit"};
    bool operator==(const Quit&) const = default;
};
//! Quits without asking (the prompt's "Discard and quit").
struct QuitDiscarding
{
    static constexpr OperatorInfo info{.id = "quit"};
    bool operator==(const QuitDiscarding&) const = default;
};
struct Recover
{
    static constexpr OperatorInfo info{
        .id = "recover",
        .stops_run = true,
        .script = "recover",
    };
    static constexpr std::tuple<> fields{};
    bool operator==(const Recover&) const = default;
};
struct DiscardRecovery
{
    static constexpr OperatorInfo info{.id = "discard recovery"};
    bool operator==(const DiscardRecovery&) const = default;
};
//! Writes the recovery files now.
struct Autosave
{
    static constexpr OperatorInfo info{
        .id = "autosave",
        .script = "autosave",
    };
    static constexpr std::tuple<> fields{};
    bool operator==(const Autosave&) const = default;
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

CommandSpec spec_of(const Command& command);

//! The command's entry in a menu ("Frame all", "Open...", "Wireframe"): its definition's
//! `menu`, or what its values make of it; its id when it has none.
std::string menu_label(const Command& command);

} // namespace meshfair::app
