// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/editor/panels/panel_context.h"

namespace meshfair::app {

void paint_panel(const PanelContext& ui)
{
    using namespace cmd;
    const EditorState& state = ui.state;
    // Opened when the Paint tool is chosen, so its settings are by the stroke (the user
    // may close it again).
    ToolKind& last_tool = ui.state.panels.tool;
    if (state.tool == ToolKind::Paint && last_tool != ToolKind::Paint)
        ImGui::SetNextItemOpen(true);
    last_tool = state.tool;
    if (!ImGui::CollapsingHeader("Paint"))
        return;
    PaintSettings p = state.tools.paint;
    bool changed = false;
    static constexpr std::pair<PaintMode, const char*> modes[] = {
        {PaintMode::Relax, "smooth brush"},
        {PaintMode::Add, "add weight"},
        {PaintMode::Subtract, "subtract weight"},
        {PaintMode::Smooth, "smooth weights"}};
    for (size_t k = 0; k < std::size(modes); ++k)
    {
        if (k % 2 == 1)
            ImGui::SameLine(150);
        if (ui.radio(modes[k].second, p.mode == modes[k].first))
        {
            p.mode = modes[k].first;
            changed = true;
        }
    }
    float strength = static_cast<float>(p.strength);
    if (ImGui::SliderFloat("strength", &strength, 0.0f, 1.0f, "%.2f"))
    {
        p.strength = std::clamp(double(strength), 0.0, 1.0);
        changed = true;
    }
    ui.track("strength");
    changed |= ui.curve_combo("brush curve", p.curve);
    if (p.mode == PaintMode::Relax)
    {
        int steps = p.steps;
        if (ImGui::SliderInt("stroke steps", &steps, 1, 100))
        {
            p.steps = std::clamp(steps, 1, 100);
            changed = true;
        }
        ui.track("stroke steps");
    }
    // The set painted: the brush's region, or a region or anchor set of vertices.
    std::vector<std::string> names{std::string(kPaintSet)};
    for (const ConstraintSet& s : ui.document.sets)
        if (takes_weight_map(s.kind) && s.faces.empty() && s.name != kPaintSet)
            names.push_back(s.name);
    const std::string current = p.set.empty() ? std::string(kPaintSet) : p.set;
    ImGui::SetNextItemWidth(160);
    if (ImGui::BeginCombo("paint set", current.c_str()))
    {
        for (const std::string& name : names)
        {
            if (ImGui::Selectable(name.c_str(), name == current))
            {
                p.set = name == kPaintSet ? std::string() : name;
                changed = true;
            }
            ui.track("paint set/" + name);
        }
        ImGui::EndCombo();
    }
    ui.track("paint set");
    ImGui::TextDisabled(
        "while painting (O), weights tint the\nsurface: blue low, green 1/2, red 1");
    if (changed && !(p == state.tools.paint))
        ui.give(SetPaintSettings{p});
}

} // namespace meshfair::app
