// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <cctype>
#include <string>

#include <imgui.h>

#include "app/editor/panels/panel_context.h"

namespace meshfair::app {

namespace {

// A menu item tracked as "Menu/Item" for scripts.
bool item(const PanelContext& ui, const char* menu, const char* label, const char* keys = nullptr,
          bool selected = false, bool enabled = true)
{
    const bool chosen = ImGui::MenuItem(label, keys, selected, enabled);
    ui.track(std::string(menu) + "/" + label);
    return chosen;
}

bool menu(const PanelContext& ui, const char* label, bool enabled = true)
{
    const bool open = ImGui::BeginMenu(label, enabled);
    ui.track(label);
    // Escape closes an open menu, as every other program's does.
    if (open && ImGui::IsKeyPressed(ImGui::GetIO().KeyMap[ImGuiKey_Escape]))
        ImGui::CloseCurrentPopup();
    return open;
}

} // namespace

void menu_bar(const PanelContext& ui)
{
    using namespace cmd;
    if (!ImGui::BeginMainMenuBar())
        return;
    const EditorState& state = ui.state;
    if (menu(ui, "File"))
    {
        if (item(ui, "File", "Open...", "Ctrl+O"))
            ui.give(ShowDialog{Dialog::OpenMesh});
        if (ImGui::BeginMenu("Open recent", !state.recent.empty()))
        {
            for (const std::string& path : state.recent)
                if (ImGui::MenuItem(path.c_str()))
                    ui.give(OpenMesh{path});
            ImGui::EndMenu();
        }
        if (item(ui, "File", "Save", "Ctrl+S"))
            ui.give(SaveMesh{});
        if (item(ui, "File", "Save as...", "Ctrl+Shift+S"))
            ui.give(ShowDialog{Dialog::SaveMeshAs});
        if (item(ui, "File", "Export recipe..."))
            ui.give(ShowDialog{Dialog::ExportRecipe});
        if (item(ui, "File", "Import recipe..."))
            ui.give(ShowDialog{Dialog::ImportRecipe});
        if (item(ui, "File", "Screenshot", "F12"))
            ui.give(Screenshot{});
        ImGui::Separator();
        if (item(ui, "File", "Quit", "Ctrl+Q"))
            ui.give(Quit{});
        ImGui::EndMenu();
    }
    if (menu(ui, "Edit"))
    {
        const HistoryStatus& h = state.history;
        const std::string undo = "Undo " + h.undo_label + "###undo",
                          redo = "Redo " + h.redo_label + "###redo";
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, h.undo_count > 0))
            ui.give(Undo{});
        ui.track("Edit/Undo");
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, h.redo_count > 0))
            ui.give(Redo{});
        ui.track("Edit/Redo");
        ImGui::EndMenu();
    }
    if (menu(ui, "Solve"))
    {
        if (item(ui, "Solve", "Play / pause", "Space"))
            ui.give(TogglePlay{});
        if (item(ui, "Solve", "Step"))
            ui.give(Step{});
        if (item(ui, "Solve", "Solve: the minimizer", "Enter",
                 ui.document.solver.method == Method::Direct))
            ui.give(Solve{});
        if (item(ui, "Solve", "Cancel preparation", "Esc", false, ui.state.solver.preparing))
            ui.give(CancelPreparation{});
        ImGui::EndMenu();
    }
    if (menu(ui, "Select"))
    {
        static constexpr std::pair<SelectionCommand, const char*> items[] = {
            {SelectionCommand::All, "Ctrl+A"},     {SelectionCommand::Clear, "Alt+A"},
            {SelectionCommand::Invert, "Ctrl+I"},  {SelectionCommand::Grow, "Ctrl+="},
            {SelectionCommand::Shrink, "Ctrl+-"},  {SelectionCommand::Connected, "Ctrl+L"},
            {SelectionCommand::Boundary, "Ctrl+B"}};
        for (const auto& [command, keys] : items)
            if (item(ui, "Select", std::string(command_name(command)).c_str(), keys))
                ui.give(RunSelection{command});
        ImGui::EndMenu();
    }
    if (menu(ui, "View"))
    {
        if (item(ui, "View", "Frame all", "Home"))
            ui.give(FrameAll{});
        if (item(ui, "View", "Frame selection", "F"))
            ui.give(FrameSelection{});
        for (StandardView v : {StandardView::Front, StandardView::Right, StandardView::Top,
                               StandardView::Back, StandardView::Left, StandardView::Bottom})
            if (item(ui, "View", view_name(v)))
                ui.give(SetView{v});
        if (item(ui, "View", "Orthographic", "Numpad 5",
                 ui.camera.projection == Projection::Orthographic))
            ui.give(ToggleProjection{});
        if (item(ui, "View", "Trackball orbit", "T", state.orbit == OrbitStyle::Trackball))
            ui.give(ToggleOrbit{});
        for (const UpAxis up : kUpAxes)
        {
            std::string name(up_axis_name(up));
            name[1] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[1])));
            if (item(ui, "View", ("Up axis " + name).c_str(), nullptr, ui.camera.up_axis == up))
                ui.give(SetUpAxis{up});
        }
        if (item(ui, "View", "Side panel", "Tab", state.show_side_panel))
            ui.give(Toggle{DisplayToggle::SidePanel});
        if (item(ui, "View", "Energy plot", "E", state.show_energy))
            ui.give(Toggle{DisplayToggle::EnergyPlot});
        ImGui::EndMenu();
    }
    if (menu(ui, "Display"))
    {
        const DisplayOptions& d = state.display;
        if (item(ui, "Display", "Flat shading", nullptr, d.shading == Shading::Flat) &&
            d.shading != Shading::Flat)
            ui.give(Toggle{DisplayToggle::Shading});
        if (item(ui, "Display", "Smooth shading", "S", d.shading == Shading::Smooth) &&
            d.shading != Shading::Smooth)
            ui.give(Toggle{DisplayToggle::Shading});
        if (item(ui, "Display", "Wireframe", "W", d.wireframe))
            ui.give(Toggle{DisplayToggle::Wireframe});
        if (item(ui, "Display", "Boundary and singular edges", "B", d.boundary_edges))
            ui.give(Toggle{DisplayToggle::BoundaryEdges});
        if (item(ui, "Display", "Vertex points", "P", d.vertex_points))
            ui.give(Toggle{DisplayToggle::VertexPoints});
        if (item(ui, "Display", "Tint back faces", nullptr, d.back_face_tint))
            ui.give(Toggle{DisplayToggle::BackFaceTint});
        ImGui::EndMenu();
    }
    if (menu(ui, "Help"))
    {
        if (item(ui, "Help", "Keys and mouse", "F1", state.show_help))
            ui.give(Toggle{DisplayToggle::Help});
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

} // namespace meshfair::app
