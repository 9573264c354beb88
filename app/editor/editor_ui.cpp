// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_ui.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <imgui.h>

#include "app/editor/interface_context.h"
#include "app/editor/panels/panel_context.h"
#include "core/io/io.h"

namespace meshfair::app {

namespace {

void side_panel(const PanelContext& ui, std::string& rename_buffer, std::string& renaming)
{
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    const float bottom = status_bar_height();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kSidePanelWidth, top));
    ImGui::SetNextWindowSize(ImVec2(kSidePanelWidth, io.DisplaySize.y - top - bottom));
    ImGui::Begin("##side", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoCollapse);
    select_panel(ui);
    paint_panel(ui);
    sets_panel(ui, rename_buffer, renaming);
    solver_panel(ui);
    legend_panel(ui);
    mesh_panel(ui);
    display_panel(ui);
    camera_panel(ui);
    ImGui::End();
}

// The file dialog's title and what it lists, for each purpose.
struct DialogKind
{
    const char* title;
    FileBrowser::Mode mode;
    FileBrowser::Files files;
};

DialogKind dialog_kind(cmd::Dialog dialog)
{
    switch (dialog)
    {
        case cmd::Dialog::OpenMesh:
            return {"Open mesh", FileBrowser::Mode::Open, FileBrowser::Files::Meshes};
        case cmd::Dialog::SaveMeshAs:
            return {"Save mesh as", FileBrowser::Mode::Save, FileBrowser::Files::Meshes};
        case cmd::Dialog::ExportRecipe:
            return {"Export recipe", FileBrowser::Mode::Save, FileBrowser::Files::Recipes};
        case cmd::Dialog::ImportRecipe:
            return {"Import recipe", FileBrowser::Mode::Open, FileBrowser::Files::Recipes};
    }
    return {"Open mesh", FileBrowser::Mode::Open, FileBrowser::Files::Meshes};
}

std::string file_name_for(cmd::Dialog dialog, const Document& document)
{
    const std::filesystem::path mesh(document.path);
    switch (dialog)
    {
        case cmd::Dialog::SaveMeshAs:
            return mesh.filename().string();
        case cmd::Dialog::ExportRecipe:
            return mesh.stem().string() + "-recipe.json";
        default:
            return {};
    }
}

} // namespace

UiOutput EditorUi::build(const Document& document, EditorState& state, const Camera& camera)
{
    UiOutput out;
    drawing_.clear();
    const PanelContext ui{document, state, camera, out, drawing_};
    menu_bar(ui);
    if (state.show_side_panel)
        side_panel(ui, rename_buffer_, renaming_);
    status_bar(ui);
    energy_window(ui);
    preparation_toast(ui); // (over the energy window)
    error_toast(ui, toast_dismissed_, toast_expanded_);
    tool_overlay(state);
    grab_highlight(ui);
    help_overlay(ui);

    if (state.dialog)
    {
        const DialogKind kind = dialog_kind(*state.dialog);
        browser_.open(kind.mode, document.path, file_name_for(*state.dialog, document), kind.files,
                      kind.title);
        browser_purpose_ = *state.dialog;
        state.dialog.reset();
    }
    if (const std::optional<std::string> chosen = browser_.draw(&drawing_))
    {
        switch (browser_purpose_)
        {
            case cmd::Dialog::OpenMesh:
                ui.give(cmd::OpenMesh{*chosen});
                break;
            case cmd::Dialog::SaveMeshAs:
                ui.give(cmd::SaveMesh{*chosen});
                break;
            case cmd::Dialog::ExportRecipe:
                ui.give(cmd::ExportRecipe{*chosen});
                break;
            case cmd::Dialog::ImportRecipe:
                ui.give(cmd::ImportRecipe{*chosen});
                break;
        }
    }

    if (state.recovery_saved_at && !ImGui::IsPopupOpen("Recover unsaved work"))
        ImGui::OpenPopup("Recover unsaved work");
    if (ImGui::BeginPopupModal("Recover unsaved work", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("A session of %s ended without saving; its work was autosaved at %s.",
                    std::filesystem::path(document.path).filename().string().c_str(),
                    state.recovery_saved_at ? state.recovery_saved_at->c_str() : "");
        if (ui.button("Recover"))
        {
            ui.give(cmd::Recover{});
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ui.button("Discard"))
        {
            ui.give(cmd::DiscardRecovery{});
            ImGui::CloseCurrentPopup();
        }
        if (!state.recovery_saved_at)
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    if (state.quit_prompt)
    {
        ImGui::OpenPopup("Unsaved changes");
        state.quit_prompt = false;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("%s has unsaved changes.",
                    std::filesystem::path(document.path).filename().string().c_str());
        if (ui.button("Save as..."))
        {
            ImGui::CloseCurrentPopup();
            ui.give(cmd::ShowDialog{cmd::Dialog::SaveMeshAs});
        }
        ImGui::SameLine();
        if (ui.button("Discard and quit"))
        {
            ImGui::CloseCurrentPopup();
            ui.give(cmd::QuitDiscarding{});
        }
        ImGui::SameLine();
        if (ui.button("Cancel"))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    // A slider or a field let go ends its series of edits: the next one is a new undo step.
    out.end_interaction = !ImGui::IsAnyItemActive() && was_editing_;
    was_editing_ = ImGui::IsAnyItemActive();
    widgets_.swap(drawing_);
    return out;
}

std::optional<WidgetRect> EditorUi::widget(std::string_view label) const
{
    const auto it = widgets_.find(label);
    if (it == widgets_.end())
        return std::nullopt;
    return it->second;
}

std::vector<std::string> EditorUi::widget_names() const
{
    std::vector<std::string> names;
    for (const auto& [name, rect] : widgets_)
        names.push_back(name);
    return names;
}

ViewRect EditorUi::view_rect(int width, int height, const EditorState& state)
{
    const ImGuiIO& io = ImGui::GetIO();
    // ImGui lays out in window units; the framebuffer may have more pixels (HiDPI).
    const float scale = io.DisplaySize.x > 0 ? float(width) / io.DisplaySize.x : 1.0f;
    const int top = static_cast<int>(ImGui::GetFrameHeight() * scale);
    const int bottom = static_cast<int>(status_bar_height() * scale);
    const int right = state.show_side_panel ? static_cast<int>(kSidePanelWidth * scale) : 0;
    const int plot = state.show_energy ? static_cast<int>(kEnergyPanelHeight * scale) : 0;
    return {width,
            height,
            0,
            top,
            std::max(width - right, 16),
            std::max(height - top - bottom - plot, 16)};
}

void EditorUi::prepare_offscreen(InterfaceContext& layer, const Document& document,
                                 EditorState& state, const Camera& camera, int width, int height)
{
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = 1.0f / 60.0f;
    // Two frames: windows that size themselves to their contents settle in the first.
    for (int frame = 0; frame < 2; ++frame)
    {
        layer.new_frame();
        build(document, state, camera);
        layer.end_frame();
    }
}

} // namespace meshfair::app
