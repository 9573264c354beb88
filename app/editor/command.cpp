// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/command.h"

#include <iterator>
#include <type_traits>

#include "app/editor/history.h"

namespace meshfair::app {

CommandSpec spec_of(const Command& command)
{
    return std::visit(
        [](const auto& c) -> CommandSpec {
            using T = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<T, cmd::RunSelection>)
                return {"select " + std::string(command_name(c.command)), kSelection, kSelection};
            else if constexpr (std::is_same_v<T, cmd::ApplySelection>)
            {
                const char* names[] = {"navigate",         "click select", "brush stroke",
                                       "rectangle select", "lasso select", "select",
                                       "select",           "select"};
                return {names[static_cast<int>(c.tool)], kSelection, kSelection, false, false};
            }
            else if constexpr (std::is_same_v<T, cmd::SelectSet>)
                return {"select set", kSelection, kSelection};
            else if constexpr (std::is_same_v<T, cmd::AddToSet>)
                return {"add to set", kSets, kSets | kSetMembers};
            else if constexpr (std::is_same_v<T, cmd::RemoveFromSet>)
                return {"remove from set", kSets, kSets | kSetMembers};
            else if constexpr (std::is_same_v<T, cmd::CloseHoles>)
                return {"close holes", kSets, kSets | kSetMembers};
            else if constexpr (std::is_same_v<T, cmd::EnableSet>)
                return {c.enabled ? "enable set" : "disable set", kSets, kSets | kSetMembers};
            else if constexpr (std::is_same_v<T, cmd::SetSetWeight>)
                return {"set weight", kSets, kSets};
            else if constexpr (std::is_same_v<T, cmd::CreateSet>)
                return {"new set", kSets, kSets | kSetMembers};
            else if constexpr (std::is_same_v<T, cmd::DeleteSet>)
                return {"delete set", kSets, kSets | kSetMembers};
            else if constexpr (std::is_same_v<T, cmd::RenameSet>)
                return {"rename set", kSets, kSets | kSetMembers};
            else if constexpr (std::is_same_v<T, cmd::SetColor>)
                return {"set colour", kSets, kSets};
            else if constexpr (std::is_same_v<T, cmd::ShowSet>)
                return {"", 0, kSets, false, false}; // display only: not an undo step
            else if constexpr (std::is_same_v<T, cmd::SetNormalDirection>)
                return {"normal direction", kSets, kSets, false, false};
            else if constexpr (std::is_same_v<T, cmd::MovePins>)
                return {"move pins", kSets | kSettings, c.dome ? kSets | kSettings : kSets, false,
                        false};
            else if constexpr (std::is_same_v<T, cmd::PaintDab>)
            {
                // Relax steps the solver from the stroke's start: a run playing is paused
                // at the first dab (dispatch keeps the stroke's step open after it).
                if (c.mode == PaintMode::Relax)
                    return {"smooth stroke", kSets | kPositions, kSets | kSetMembers, true, false};
                return {"paint weights", kSets, kSets | kSetMembers, false, false};
            }
            else if constexpr (std::is_same_v<T, cmd::SetSolverSettings>)
                return {"solver settings", kSettings, kSettings};
            else if constexpr (std::is_same_v<T, cmd::Solve>)
                return {"solve", kSettings, kSettings};
            else if constexpr (std::is_same_v<T, cmd::ImportRecipe>)
                return {"import recipe", kSets | kSettings, kSets | kSettings | kSetMembers, true};
            else if constexpr (std::is_same_v<T, cmd::ApplyPreset>)
                return {"preset", kSets | kSettings, kSets | kSettings | kSetMembers, true};
            else if constexpr (std::is_same_v<T, cmd::Step>)
                // The solver bumps the positions it publishes.
                return {"step", kPositions, 0, true};
            else if constexpr (std::is_same_v<T, cmd::ResetShape>)
                return {"reset shape", kPositions, kPositions, true};
            else if constexpr (std::is_same_v<T, cmd::ApplyShape>)
                return {"apply shape", kPositions | kBasePositions, kBasePositions, true};
            else if constexpr (std::is_same_v<T, cmd::AddNoise>)
                return {"noise", kPositions | kBasePositions, kPositions | kBasePositions, true};
            else if constexpr (std::is_same_v<T, cmd::Undo> || std::is_same_v<T, cmd::Redo> ||
                               std::is_same_v<T, cmd::OpenMesh> || std::is_same_v<T, cmd::Recover>)
                return {"", 0, 0, true};
            else if constexpr (std::is_same_v<T, cmd::FrameAll> ||
                               std::is_same_v<T, cmd::FrameSelection> ||
                               std::is_same_v<T, cmd::SetView> ||
                               std::is_same_v<T, cmd::SetProjection> ||
                               std::is_same_v<T, cmd::ToggleProjection> ||
                               std::is_same_v<T, cmd::SetOrbit> ||
                               std::is_same_v<T, cmd::ToggleOrbit> ||
                               std::is_same_v<T, cmd::SetUpAxis> ||
                               std::is_same_v<T, cmd::Toggle> ||
                               std::is_same_v<T, cmd::SetDisplay> ||
                               std::is_same_v<T, cmd::SetHeatMap> ||
                               std::is_same_v<T, cmd::ScaleBrushRadius> ||
                               std::is_same_v<T, cmd::SetBrushRadius> ||
                               std::is_same_v<T, cmd::SetPaintSettings> ||
                               std::is_same_v<T, cmd::CancelPreparation> ||
                               std::is_same_v<T, cmd::Screenshot>)
                return {"", 0, 0, false, false};
            else
                return {};
        },
        command);
}

std::string_view command_name(const Command& command)
{
    static constexpr const char* names[] = {"tool",
                                            "elements",
                                            "toggle elements",
                                            "through",
                                            "brush radius",
                                            "brush radius",
                                            "select",
                                            "select",
                                            "undo",
                                            "redo",
                                            "frame all",
                                            "frame selection",
                                            "view",
                                            "projection",
                                            "projection",
                                            "orbit",
                                            "orbit",
                                            "up axis",
                                            "toggle",
                                            "display",
                                            "create set",
                                            "delete set",
                                            "rename set",
                                            "show set",
                                            "set colour",
                                            "select set",
                                            "add to set",
                                            "remove from set",
                                            "close holes",
                                            "enable set",
                                            "set weight",
                                            "normal direction",
                                            "move pins",
                                            "paint",
                                            "paint settings",
                                            "solver settings",
                                            "play",
                                            "pause",
                                            "play/pause",
                                            "step",
                                            "solve",
                                            "cancel preparation",
                                            "reset",
                                            "apply",
                                            "noise",
                                            "heat map",
                                            "open",
                                            "save",
                                            "export recipe",
                                            "import recipe",
                                            "preset",
                                            "dialog",
                                            "screenshot",
                                            "quit",
                                            "quit",
                                            "recover",
                                            "discard recovery",
                                            "autosave"};
    static_assert(std::size(names) == std::variant_size_v<Command>);
    return names[command.index()];
}

} // namespace meshfair::app
