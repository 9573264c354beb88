// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <cctype>
#include <string>

#include <imgui.h>

#include "app/editor/key_map.h"
#include "app/editor/panels/panel_context.h"

namespace meshfair::app {

namespace {

// A menu item tracked as "Menu/Item" for scripts: the command's own label and the key
// bound to it (both from the command's definition and the key map), given when chosen.
// `label` (shown) and `name` (tracked) replace the command's own label where the menu
// says more; a chosen item that is already `selected` gives nothing when `reselect` is off.
struct ItemOptions
{
    bool selected = false;
    bool enabled = true;
    std::string label = {}, name = {};
    bool reselect = true;
};
void item(const PanelContext& ui, const char* menu, const Command& command,
          const ItemOptions& o = {})
{
    const std::string label = o.label.empty() ? menu_label(command) : o.label;
    const std::optional<KeyChord> chord = key_for(command);
    const std::string keys = chord ? chord_label(*chord) : std::string();
    const bool chosen =
        ImGui::MenuItem(label.c_str(), chord ? keys.c_str() : nullptr, o.selected, o.enabled);
    ui.track(std::string(menu) + "/" + (o.name.empty() ? label : o.name));
    if (chosen && (o.reselect || !o.selected))
        ui.give(command);
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
        item(ui, "File", ShowDialog{Dialog::OpenMesh});
        if (ImGui::BeginMenu("Open recent", !state.recent.empty()))
        {
            for (const std::string& path : state.recent)
                if (ImGui::MenuItem(path.c_str()))
                    ui.give(OpenMesh{path});
            ImGui::EndMenu();
        }
        item(ui, "File", SaveMesh{});
        item(ui, "File", ShowDialog{Dialog::SaveMeshAs});
        item(ui, "File", ShowDialog{Dialog::ExportRecipe});
        item(ui, "File", ShowDialog{Dialog::ImportRecipe});
        item(ui, "File", Screenshot{});
        ImGui::Separator();
        item(ui, "File", Quit{});
        ImGui::EndMenu();
    }
    if (menu(ui, "Edit"))
    {
        // The steps' names in the labels; "###" keeps the items' IDs as they change.
        const HistoryStatus& h = state.history;
        item(ui, "Edit", Undo{},
             {.enabled = h.undo_count > 0,
              .label = "Undo " + h.undo_label + "###undo",
              .name = "Undo"});
        item(ui, "Edit", Redo{},
             {.enabled = h.redo_count > 0,
              .label = "Redo " + h.redo_label + "###redo",
              .name = "Redo"});
        ImGui::EndMenu();
    }
    if (menu(ui, "Solve"))
    {
        item(ui, "Solve", TogglePlay{});
        item(ui, "Solve", Step{});
        item(ui, "Solve", Solve{}, {.selected = ui.document.solver.method == Method::Direct});
        item(ui, "Solve", CancelPreparation{}, {.enabled = ui.state.solver.preparing});
        ImGui::EndMenu();
    }
    if (menu(ui, "Select"))
    {
        for (const SelectionCommand c :
             {SelectionCommand::All, SelectionCommand::Clear, SelectionCommand::Invert,
              SelectionCommand::Grow, SelectionCommand::Shrink, SelectionCommand::Connected,
              SelectionCommand::Boundary})
            item(ui, "Select", RunSelection{c});
        ImGui::EndMenu();
    }
    if (menu(ui, "View"))
    {
        item(ui, "View", FrameAll{});
        item(ui, "View", FrameSelection{});
        for (StandardView v : {StandardView::Front, StandardView::Right, StandardView::Top,
                               StandardView::Back, StandardView::Left, StandardView::Bottom})
            item(ui, "View", SetView{v});
        item(ui, "View", ToggleProjection{},
             {.selected = ui.camera.projection == Projection::Orthographic});
        item(ui, "View", ToggleOrbit{}, {.selected = state.orbit == OrbitStyle::Trackball});
        for (const UpAxis up : kUpAxes)
            item(ui, "View", SetUpAxis{up}, {.selected = ui.camera.up_axis == up});
        item(ui, "View", Toggle{DisplayToggle::SidePanel}, {.selected = state.show_side_panel});
        item(ui, "View", Toggle{DisplayToggle::EnergyPlot}, {.selected = state.show_energy});
        ImGui::EndMenu();
    }
    if (menu(ui, "Display"))
    {
        const DisplayOptions& d = state.display;
        // Shading is one toggle shown as two choices: each gives it only when not chosen.
        const bool flat = d.shading == Shading::Flat;
        item(ui, "Display", Toggle{DisplayToggle::Shading},
             {.selected = flat, .label = "Flat shading", .reselect = false});
        item(ui, "Display", Toggle{DisplayToggle::Shading}, {.selected = !flat, .reselect = false});
        item(ui, "Display", Toggle{DisplayToggle::Wireframe}, {.selected = d.wireframe});
        item(ui, "Display", Toggle{DisplayToggle::BoundaryEdges}, {.selected = d.boundary_edges});
        item(ui, "Display", Toggle{DisplayToggle::VertexPoints}, {.selected = d.vertex_points});
        item(ui, "Display", Toggle{DisplayToggle::BackFaceTint}, {.selected = d.back_face_tint});
        ImGui::EndMenu();
    }
    if (menu(ui, "Help"))
    {
        item(ui, "Help", Toggle{DisplayToggle::Help}, {.selected = state.show_help});
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

} // namespace meshfair::app
