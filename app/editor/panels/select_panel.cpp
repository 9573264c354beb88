// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <cstdio>

#include <imgui.h>

#include "app/editor/panels/panel_context.h"

namespace meshfair::app {

namespace {

std::string megabytes(std::size_t bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1 << 20));
    return text;
}

} // namespace

void select_panel(const PanelContext& ui)
{
    using namespace cmd;
    if (!ImGui::CollapsingHeader("Select", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    const EditorState& state = ui.state;
    static constexpr std::pair<ToolKind, const char*> tools[] = {
        {ToolKind::Navigate, "navigate (N)"},
        {ToolKind::Click, "click (K)"},
        {ToolKind::Brush, "brush (C)"},
        {ToolKind::Rectangle, "rectangle (R)"},
        {ToolKind::Lasso, "lasso (L)"},
        {ToolKind::MovePins, "move pins (M)"},
        {ToolKind::AimNormals, "aim normals (D)"},
        {ToolKind::Paint, "paint (O)"}};
    for (size_t k = 0; k < std::size(tools); ++k)
    {
        if (k % 2 == 1)
            ImGui::SameLine(150);
        if (ui.radio(tools[k].second, state.tool == tools[k].first))
            ui.give(SetTool{tools[k].first});
    }
    if (ui.radio("vertices", state.tools.elements == ElementKind::Vertices))
        ui.give(SetElements{ElementKind::Vertices});
    ImGui::SameLine(150);
    if (ui.radio("faces (V)", state.tools.elements == ElementKind::Faces))
        ui.give(SetElements{ElementKind::Faces});
    bool through = state.tools.through;
    if (ui.checkbox("through the surface", &through))
        ui.give(SetThrough{through});
    float radius = static_cast<float>(state.tools.brush_radius_px);
    if (ImGui::SliderFloat("radius", &radius, 2.0f, 200.0f, "%.0f px"))
        ui.give(SetBrushRadius{radius});
    ui.track("radius");
    ImGui::Text("selected: %s vertices, %s faces",
                with_separators(static_cast<std::int64_t>(state.selected_vertices)).c_str(),
                with_separators(static_cast<std::int64_t>(state.selected_faces)).c_str());
    static constexpr std::pair<SelectionCommand, const char*> commands[] = {
        {SelectionCommand::All, "All"},          {SelectionCommand::Clear, "None"},
        {SelectionCommand::Invert, "Invert"},    {SelectionCommand::Grow, "Grow"},
        {SelectionCommand::Shrink, "Shrink"},    {SelectionCommand::Connected, "Connected"},
        {SelectionCommand::Boundary, "Boundary"}};
    int column = 0;
    for (const auto& [command, label] : commands)
    {
        if (column++ % 4 != 0)
            ImGui::SameLine();
        if (ui.button(label))
            ui.give(RunSelection{command});
    }
    const HistoryStatus& h = state.history;
    ImGui::Text("history: %zu step%s, %s of %s", h.undo_count, h.undo_count == 1 ? "" : "s",
                megabytes(h.bytes).c_str(), megabytes(h.limit).c_str());
    if (h.dropped > 0)
        ImGui::Text("(%zu oldest steps dropped to stay within it)", h.dropped);
}

} // namespace meshfair::app
