// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/edit/command.h"

#include <cctype>
#include <type_traits>

namespace meshfair::app {

namespace {

// The undo step a command's definition gives.
CommandSpec spec_from(const OperatorInfo& op)
{
    return {std::string(op.label), op.captures, op.bumps, op.stops_run, op.waits_for_gesture};
}

} // namespace

namespace cmd {

CommandSpec RunSelection::spec_for(const RunSelection& c)
{
    CommandSpec spec = spec_from(info);
    spec.label += " " + std::string(command_name(c.command));
    return spec;
}

CommandSpec ApplySelection::spec_for(const ApplySelection& c)
{
    // The gesture's tool names the step.
    CommandSpec spec = spec_from(info);
    switch (c.tool)
    {
        case ToolKind::Navigate:
            spec.label = "navigate";
            break;
        case ToolKind::Click:
            spec.label = "click select";
            break;
        case ToolKind::Brush:
            spec.label = "brush stroke";
            break;
        case ToolKind::Rectangle:
            spec.label = "rectangle select";
            break;
        case ToolKind::Lasso:
            spec.label = "lasso select";
            break;
        case ToolKind::MovePins:
        case ToolKind::AimNormals:
        case ToolKind::Paint:
            break;
    }
    return spec;
}

CommandSpec EnableSet::spec_for(const EnableSet& c)
{
    CommandSpec spec = spec_from(info);
    if (!c.enabled)
        spec.label = "disable set";
    return spec;
}

CommandSpec MovePins::spec_for(const MovePins& c)
{
    // The first move of a drag may take the dome's settings too.
    CommandSpec spec = spec_from(info);
    if (c.dome)
        spec.bumps |= kSettings;
    return spec;
}

CommandSpec PaintDab::spec_for(const PaintDab& c)
{
    // The smoothing brush steps the solver from the stroke's start: a run playing is
    // paused at the first dab (dispatch keeps the stroke's step open after it). Painting
    // a weight map changes the sets alone.
    CommandSpec spec = spec_from(info);
    if (c.mode != PaintMode::Relax)
        spec = {"paint weights", kSets, kSets | kSetMembers, false, false};
    return spec;
}

std::string ShowDialog::menu_label_for(const ShowDialog& c)
{
    switch (c.dialog)
    {
        case Dialog::OpenMesh:
            return "Open...";
        case Dialog::SaveMeshAs:
            return "Save as...";
        case Dialog::ExportRecipe:
            return "Export recipe...";
        case Dialog::ImportRecipe:
            return "Import recipe...";
    }
    return std::string(info.id);
}

std::string RunSelection::menu_label_for(const RunSelection& c)
{
    return std::string(command_name(c.command));
}

std::string SetView::menu_label_for(const SetView& c)
{
    switch (c.view)
    {
        case StandardView::Front:
            return "Front";
        case StandardView::Back:
            return "Back";
        case StandardView::Right:
            return "Right";
        case StandardView::Left:
            return "Left";
        case StandardView::Top:
            return "Top";
        case StandardView::Bottom:
            return "Bottom";
    }
    return std::string(info.id);
}

std::string SetUpAxis::menu_label_for(const SetUpAxis& c)
{
    // "Up axis +X".
    std::string name(up_axis_name(c.up));
    for (char& ch : name)
        ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return "Up axis " + name;
}

std::string Toggle::menu_label_for(const Toggle& c)
{
    switch (c.what)
    {
        case DisplayToggle::Shading:
            return "Smooth shading";
        case DisplayToggle::Wireframe:
            return "Wireframe";
        case DisplayToggle::BoundaryEdges:
            return "Boundary and singular edges";
        case DisplayToggle::VertexPoints:
            return "Vertex points";
        case DisplayToggle::BackFaceTint:
            return "Tint back faces";
        case DisplayToggle::SidePanel:
            return "Side panel";
        case DisplayToggle::Help:
            return "Keys and mouse";
        case DisplayToggle::EnergyPlot:
            return "Energy plot";
        case DisplayToggle::EnergyLogScale:
            return "Log scale";
        case DisplayToggle::EnergyWholeMesh:
            return "Whole mesh";
    }
    return std::string(info.id);
}

} // namespace cmd

CommandSpec spec_of(const Command& command)
{
    return std::visit(
        [](const auto& c) -> CommandSpec {
            using T = std::decay_t<decltype(c)>;
            if constexpr (HasOwnSpec<T>)
                return T::spec_for(c);
            else
                return spec_from(T::info);
        },
        command);
}

std::string menu_label(const Command& command)
{
    return std::visit(
        [](const auto& c) -> std::string {
            using T = std::decay_t<decltype(c)>;
            if constexpr (HasOwnMenuLabel<T>)
                return T::menu_label_for(c);
            else
                return std::string(T::info.menu.empty() ? T::info.id : T::info.menu);
        },
        command);
}

std::string_view command_name(const Command& command)
{
    return std::visit([](const auto& c) { return std::decay_t<decltype(c)>::info.id; }, command);
}

} // namespace meshfair::app
