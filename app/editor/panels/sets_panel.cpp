// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <algorithm>

#include <imgui.h>

#include "app/editor/constraint_glyphs.h"
#include "app/editor/panels/panel_context.h"

namespace meshfair::app {

void sets_panel(const PanelContext& ui, std::string& rename_buffer, std::string& renaming)
{
    using namespace cmd;
    if (!ImGui::CollapsingHeader("Constraint sets", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    ImGui::TextUnformatted("new from the selection:");
    for (int k = 0; k < kConstraintKinds; ++k)
    {
        const auto kind = static_cast<ConstraintKind>(k);
        if (k % 4 != 0)
            ImGui::SameLine();
        if (ui.small_button(kind_label(kind), std::string("new ") + kind_label(kind)))
            ui.give(CreateSet{kind, {}});
    }
    for (size_t i = 0; i < ui.document.sets.size(); ++i)
    {
        const ConstraintSet& set = ui.document.sets[i];
        const std::string key = "sets/" + set.name + "/";
        ImGui::PushID(static_cast<int>(i));
        bool enabled = set.enabled;
        if (ui.checkbox("##enabled", &enabled, key + "enabled"))
            ui.give(EnableSet{set.name, enabled});
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("takes part in the solve");
        ImGui::SameLine();
        bool visible = set.visible;
        if (ui.checkbox("##visible", &visible, key + "show"))
            ui.give(ShowSet{set.name, visible});
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("shows its glyphs");
        ImGui::SameLine();
        std::array<float, 3> color = set.color;
        if (ImGui::ColorEdit3("##color", color.data(), ImGuiColorEditFlags_NoInputs))
            ui.give(SetColor{set.name, color}, {key + "color"});
        ui.track(key + "color");
        ImGui::SameLine();
        const size_t count = set.vertices.size() + set.faces.size();
        if (!set.enabled)
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s  (%s, %s %s)%s", set.name.c_str(), kind_label(set.kind),
                           with_separators(static_cast<std::int64_t>(count)).c_str(),
                           set.vertices.empty() ? "faces" : "vertices",
                           set.enabled ? "" : ", not solved");
        if (!set.enabled)
            ImGui::PopStyleColor();
        if (ui.small_button("select", key + "select"))
            ui.give(SelectSet{set.name});
        ImGui::SameLine();
        if (ui.small_button("+sel", key + "add"))
            ui.give(AddToSet{set.name});
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("add the selection to the set");
        ImGui::SameLine();
        if (ui.small_button("-sel", key + "remove"))
            ui.give(RemoveFromSet{set.name});
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("take the selection out of the set");
        ImGui::SameLine();
        if (ui.small_button("rename", key + "rename"))
        {
            renaming = set.name;
            rename_buffer = set.name;
            ImGui::OpenPopup("rename");
        }
        ImGui::SameLine();
        if (ui.small_button("delete", key + "delete"))
            ui.give(DeleteSet{set.name});
        for (const auto& [region, holes] : ui.state.region_holes)
            if (region == set.name)
            {
                const std::string label = "close " + std::to_string(holes) + " holes";
                if (ui.button(label.c_str(), key + "close holes"))
                    ui.give(CloseHoles{set.name});
            }
        if (takes_weight(set.kind))
        {
            // The set's own weight, logarithmic over [1e-3, 1e3]; Ctrl+click types one.
            float mu = float(weight_of(set, ui.document.solver));
            ImGui::SetNextItemWidth(180);
            if (ImGui::SliderFloat("mu", &mu, 1e-3f, 1e3f, "%.4g", ImGuiSliderFlags_Logarithmic))
                ui.give(SetSetWeight{set.name, std::clamp(Scalar(mu), Scalar(1e-3), Scalar(1e3))},
                        {key + "mu"});
            ui.track(key + "mu");
        }
        if (kind_info(set.kind).normals)
        {
            // The set's mean normal: what its arrows average, and where a drag starts.
            const Vec3 d =
                i < ui.state.set_directions.size() ? ui.state.set_directions[i] : Vec3{0, 0, 1};
            float direction[3] = {float(d[0]), float(d[1]), float(d[2])};
            ImGui::SetNextItemWidth(180);
            if (ImGui::DragFloat3("direction", direction, 0.01f, -1.0f, 1.0f, "%.2f"))
                ui.give(SetNormalDirection{set.name, {direction[0], direction[1], direction[2]}},
                        {key + "direction"});
            ui.track(key + "direction");
        }
        if (ImGui::BeginPopup("rename"))
        {
            char buffer[128] = {};
            rename_buffer.copy(buffer, sizeof buffer - 1);
            if (ImGui::IsWindowAppearing())
                ImGui::SetKeyboardFocusHere();
            const bool enter = ImGui::InputText(
                "name", buffer, sizeof buffer,
                ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
            ui.track("rename/name");
            rename_buffer = buffer;
            if ((ui.button("OK", "rename/OK") || enter) && !rename_buffer.empty())
            {
                ui.give(RenameSet{renaming, rename_buffer});
                ImGui::CloseCurrentPopup();
            }
            ImGui::EndPopup();
        }
        ImGui::PopID();
    }
    for (const std::string& note : ui.state.notes)
    {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.95f, 0.85f, 0.45f, 1));
        ImGui::TextWrapped("note: %s", note.c_str());
        ImGui::PopStyleColor();
    }
    for (const std::string& problem : ui.state.problems)
    {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.35f, 1));
        ImGui::TextWrapped("%s", problem.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::TextWrapped(
        "Vertices outside the regions are fixed; the border ring is where they meet the "
        "moving ones.");
}

} // namespace meshfair::app
