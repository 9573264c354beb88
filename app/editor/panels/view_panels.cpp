// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// The side panel's Mesh, Display and Camera sections.
#include <filesystem>

#include <cctype>
#include <string>

#include <imgui.h>

#include "app/editor/panels/panel_context.h"
#include "app/render/palette.h"
#include "core/io/attributes.h"

namespace meshfair::app {

void legend_panel(const PanelContext&)
{
    if (!ImGui::CollapsingHeader("Legend", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    struct Entry
    {
        const palette::Rgb& color;
        const char* meaning;
    };
    static const Entry entries[] = {{palette::kSelection, "selection"},
                                    {palette::kBoundary, "mesh boundary"},
                                    {palette::kSingular, "singular edges"},
                                    {palette::kToolOverlay, "brush, rectangle, lasso"},
                                    {palette::kRegion, "region, border ring"},
                                    {palette::kPin, "pins"},
                                    {palette::kAnchor, "anchors"},
                                    {palette::kCentroid, "centroids"},
                                    {palette::kNormal, "normals"},
                                    {palette::kHardNormal, "hard normals"},
                                    {palette::kSoftNormal, "soft normals"},
                                    {palette::kBackFace, "back faces"}};
    int k = 0;
    for (const Entry& e : entries)
    {
        if (k++ % 2 == 1)
            ImGui::SameLine(165);
        const palette::Rgb& c = e.color;
        ImGui::ColorButton(e.meaning, ImVec4(c[0], c[1], c[2], 1),
                           ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker,
                           ImVec2(12, 12));
        ImGui::SameLine();
        ImGui::TextUnformatted(e.meaning);
    }
    ImGui::TextDisabled("a set's colour is its own (click its swatch)");
}

void mesh_panel(const PanelContext& ui)
{
    if (!ImGui::CollapsingHeader("Mesh"))
        return;
    const Document& document = ui.document;
    const Topology& t = document.topology;
    ImGui::TextUnformatted(std::filesystem::path(document.path).filename().string().c_str());
    ImGui::Text("vertices  %s", with_separators(document.mesh.vertex_count()).c_str());
    ImGui::Text("faces     %s", with_separators(document.mesh.face_count()).c_str());
    ImGui::Text("edges     %s", with_separators(t.edge_count()).c_str());
    ImGui::Text("boundary  %s   singular  %s", with_separators(t.boundary_edge_count).c_str(),
                with_separators(t.singular_edge_count).c_str());
    // What the file holds beside the shape, which a save writes back.
    for (const std::string& attribute : io::describe_attributes(document.attributes))
        ImGui::TextWrapped("kept: %s", attribute.c_str());
    for (const std::string& note : document.report.notes)
        ImGui::TextWrapped("note: %s", note.c_str());
}

void display_panel(const PanelContext& ui)
{
    if (!ImGui::CollapsingHeader("Display"))
        return;
    DisplayOptions d = ui.state.display;
    if (ui.radio("flat", d.shading == Shading::Flat))
        d.shading = Shading::Flat;
    ImGui::SameLine();
    if (ui.radio("smooth", d.shading == Shading::Smooth))
        d.shading = Shading::Smooth;
    ui.checkbox("wireframe (polygon edges)", &d.wireframe);
    ui.checkbox("boundary and singular edges", &d.boundary_edges);
    ui.checkbox("vertex points", &d.vertex_points);
    ui.checkbox("tint back faces", &d.back_face_tint);
    ImGui::SliderFloat("edge width", &d.edge_width_px, 1.0f, 4.0f, "%.1f px");
    ImGui::SliderFloat("point size", &d.point_size_px, 1.0f, 12.0f, "%.0f px");
    ImGui::ColorEdit3("surface", d.surface_color.data(), ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    ImGui::ColorEdit3("background", d.background.data(), ImGuiColorEditFlags_NoInputs);
    const DisplayOptions& now = ui.state.display;
    if (d.shading != now.shading || d.wireframe != now.wireframe ||
        d.boundary_edges != now.boundary_edges || d.vertex_points != now.vertex_points ||
        d.back_face_tint != now.back_face_tint || d.edge_width_px != now.edge_width_px ||
        d.point_size_px != now.point_size_px || d.surface_color != now.surface_color ||
        d.background != now.background)
        ui.give(cmd::SetDisplay{d});
}

void camera_panel(const PanelContext& ui)
{
    using namespace cmd;
    if (!ImGui::CollapsingHeader("Camera"))
        return;
    if (ui.radio("perspective", ui.camera.projection == Projection::Perspective))
        ui.give(SetProjection{Projection::Perspective});
    ImGui::SameLine();
    if (ui.radio("orthographic", ui.camera.projection == Projection::Orthographic))
        ui.give(SetProjection{Projection::Orthographic});
    // The up axis, three a row: +X -X +Y, then -Y +Z -Z.
    int up_column = 0;
    for (const UpAxis up : kUpAxes)
    {
        std::string name(up_axis_name(up));
        name[1] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[1])));
        if (up_column++ % 3 != 0)
            ImGui::SameLine();
        if (ui.radio((name + " up").c_str(), ui.camera.up_axis == up))
            ui.give(SetUpAxis{up});
    }
    if (ui.radio("turntable", ui.state.orbit == OrbitStyle::Turntable))
        ui.give(SetOrbit{OrbitStyle::Turntable});
    ImGui::SameLine();
    if (ui.radio("trackball", ui.state.orbit == OrbitStyle::Trackball))
        ui.give(SetOrbit{OrbitStyle::Trackball});
    int column = 0;
    for (StandardView v : {StandardView::Front, StandardView::Right, StandardView::Top,
                           StandardView::Back, StandardView::Left, StandardView::Bottom})
    {
        if (column++ % 3 != 0)
            ImGui::SameLine();
        const std::string name = menu_label(cmd::SetView{v});
        if (ImGui::Button(name.c_str(), ImVec2(86, 0)))
            ui.give(SetView{v});
        ui.track("view " + name);
    }
    if (ImGui::Button("Frame all", ImVec2(-1, 0)))
        ui.give(FrameAll{});
    ui.track("Frame all");
}

} // namespace meshfair::app
