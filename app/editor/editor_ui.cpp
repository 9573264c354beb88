// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_ui.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <imgui.h>

#include "app/editor/interface_context.h"
#include "core/io/io.h"

namespace meshfair::app {

namespace {

constexpr KeyBinding kBindings[] = {
    {"Left drag", "the active tool; with Navigate, orbit (turntable or trackball, see T)"},
    {"Alt + left drag", "orbit, whatever the tool"},
    {"Shift + tool", "add to the selection"},
    {"Ctrl + tool", "take away from the selection"},
    {"N / K / C / R / L", "tool: navigate / click / brush / rectangle / lasso"},
    {"V", "select vertices / faces"},
    {"[ / ]", "brush radius smaller / larger"},
    {"Ctrl + A, Alt + A", "select all, select none"},
    {"Ctrl + I", "invert the selection"},
    {"Ctrl + = / Ctrl + -", "grow / shrink the selection by a ring"},
    {"Ctrl + L", "select the connected components of the selection"},
    {"Ctrl + B", "select the boundary"},
    {"Ctrl + Z", "undo"},
    {"Ctrl + Shift + Z, Ctrl + Y", "redo"},
    {"Middle drag", "orbit"},
    {"Right drag, Shift + middle drag", "pan"},
    {"Wheel", "zoom to the cursor"},
    {"Ctrl + middle drag", "zoom (drag up: closer)"},
    {"Home, numpad .", "frame all"},
    {"F", "frame the selection (all when nothing is selected)"},
    {"Numpad 1 / 3 / 7 (or 1 / 3 / 7)", "front / right / top view"},
    {"Ctrl + numpad 1 / 3 / 7", "back / left / bottom view"},
    {"Numpad 5 (or 5)", "perspective / orthographic"},
    {"T", "turntable / trackball orbit"},
    {"S", "smooth / flat shading"},
    {"W", "polygon wireframe"},
    {"B", "boundary and singular edges"},
    {"P", "vertex points"},
    {"Tab", "side panel"},
    {"F1, H", "this help"},
    {"F12", "screenshot (PNG)"},
    {"Ctrl + O", "open a mesh (or drop a file on the window)"},
    {"Ctrl + Shift + S", "save as"},
    {"Ctrl + Q, closing the window", "quit (asks first when there are unsaved changes)"},
};

constexpr float kSidePanelWidth = 300;

struct CommandItem
{
    SelectionCommand command;
    const char* label;
    const char* keys;
};
constexpr CommandItem kCommandItems[] = {
    {SelectionCommand::All, "All", "Ctrl+A"},
    {SelectionCommand::Clear, "None", "Alt+A"},
    {SelectionCommand::Invert, "Invert", "Ctrl+I"},
    {SelectionCommand::Grow, "Grow", "Ctrl+="},
    {SelectionCommand::Shrink, "Shrink", "Ctrl+-"},
    {SelectionCommand::Connected, "Connected", "Ctrl+L"},
    {SelectionCommand::Boundary, "Boundary", "Ctrl+B"},
};

struct ToolItem
{
    ToolKind tool;
    const char* label;
};
constexpr ToolItem kToolItems[] = {{ToolKind::Navigate, "navigate (N)"},
                                   {ToolKind::Click, "click (K)"},
                                   {ToolKind::Brush, "brush (C)"},
                                   {ToolKind::Rectangle, "rectangle (R)"},
                                   {ToolKind::Lasso, "lasso (L)"}};

std::string megabytes(std::size_t bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1 << 20));
    return text;
}

void select_section(EditorState& state, UiRequests& r)
{
    if (!ImGui::CollapsingHeader("Select", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    int tool = static_cast<int>(state.tool);
    for (size_t k = 0; k < std::size(kToolItems); ++k)
    {
        if (k % 2 == 1)
            ImGui::SameLine(150);
        if (ImGui::RadioButton(kToolItems[k].label, &tool, static_cast<int>(kToolItems[k].tool)))
            r.tool = kToolItems[k].tool;
    }
    int elements = state.tools.elements == ElementKind::Vertices ? 0 : 1;
    if (ImGui::RadioButton("vertices", &elements, 0))
        r.elements = ElementKind::Vertices;
    ImGui::SameLine(150);
    if (ImGui::RadioButton("faces (V)", &elements, 1))
        r.elements = ElementKind::Faces;
    ImGui::Checkbox("through the surface", &state.tools.through);
    float radius = static_cast<float>(state.tools.brush_radius_px);
    if (ImGui::SliderFloat("brush radius", &radius, 2.0f, 200.0f, "%.0f px"))
        state.tools.brush_radius_px = radius;
    ImGui::Text("selected: %s vertices, %s faces",
                with_separators(static_cast<std::int64_t>(state.selected_vertices)).c_str(),
                with_separators(static_cast<std::int64_t>(state.selected_faces)).c_str());
    int column = 0;
    for (const auto& [command, label, keys] : kCommandItems)
    {
        if (column++ % 4 != 0)
            ImGui::SameLine();
        if (ImGui::Button(label))
            r.command = command;
    }
    const HistoryStatus& h = state.history;
    ImGui::Text("history: %zu step%s, %s of %s", h.undo_count, h.undo_count == 1 ? "" : "s",
                megabytes(h.bytes).c_str(), megabytes(h.limit).c_str());
    if (h.dropped > 0)
        ImGui::Text("(%zu oldest steps dropped to stay within it)", h.dropped);
}

// The active tool's ring, rectangle or lasso line, under the panels.
void tool_overlay(const EditorState& state)
{
    const ToolOverlay& o = state.overlay;
    if (o.shape == ToolOverlay::Shape::None || o.points.empty())
        return;
    const ImGuiIO& io = ImGui::GetIO();
    const float sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
    const float sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0f;
    auto at = [&](const ScreenPoint& p) { return ImVec2(float(p.x) / sx, float(p.y) / sy); };
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImU32 color = IM_COL32(255, 160, 40, 230);
    switch (o.shape)
    {
        case ToolOverlay::Shape::Circle:
            draw->AddCircle(at(o.points[0]), float(o.radius) / sx, color, 48, 1.5f);
            break;
        case ToolOverlay::Shape::Rectangle:
            if (o.points.size() == 2)
            {
                const ImVec2 a = at(o.points[0]), b = at(o.points[1]);
                draw->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                                    ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                                    IM_COL32(255, 160, 40, 40));
                draw->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                              ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)), color, 0, 0, 1.5f);
            }
            break;
        case ToolOverlay::Shape::Polyline:
        {
            std::vector<ImVec2> line;
            for (const ScreenPoint& p : o.points)
                line.push_back(at(p));
            draw->AddPolyline(line.data(), static_cast<int>(line.size()), color, 0, 1.5f);
            break;
        }
        case ToolOverlay::Shape::None:
            break;
    }
}

const char* view_name(StandardView v)
{
    switch (v)
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
    return "";
}

void menu_bar(const Document& document, EditorState& state, const Camera& camera, EditorUi& ui,
              UiRequests& r)
{
    if (!ImGui::BeginMainMenuBar())
        return;
    if (ImGui::BeginMenu("File"))
    {
        if (ImGui::MenuItem("Open...", "Ctrl+O"))
            ui.open_file_dialog(document);
        if (ImGui::BeginMenu("Open recent", !state.recent.empty()))
        {
            for (const std::string& path : state.recent)
                if (ImGui::MenuItem(path.c_str()))
                    r.open_path = path;
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S"))
            ui.save_file_dialog(document);
        if (ImGui::MenuItem("Screenshot", "F12"))
            r.screenshot = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q"))
            ui.ask_to_quit(document, r);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit"))
    {
        const HistoryStatus& h = state.history;
        const std::string undo = "Undo " + h.undo_label, redo = "Redo " + h.redo_label;
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, h.undo_count > 0))
            r.undo = true;
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, h.redo_count > 0))
            r.redo = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Select"))
    {
        for (const auto& [command, label, keys] : kCommandItems)
            if (ImGui::MenuItem(label, keys))
                r.command = command;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View"))
    {
        if (ImGui::MenuItem("Frame all", "Home"))
            r.frame_all = true;
        if (ImGui::MenuItem("Frame selection", "F"))
            r.frame_selection = true;
        for (StandardView v : {StandardView::Front, StandardView::Right, StandardView::Top,
                               StandardView::Back, StandardView::Left, StandardView::Bottom})
            if (ImGui::MenuItem(view_name(v)))
                r.view = v;
        if (ImGui::MenuItem("Orthographic", "Numpad 5",
                            camera.projection == Projection::Orthographic))
            r.toggle_projection = true;
        bool trackball = state.orbit == OrbitStyle::Trackball;
        if (ImGui::MenuItem("Trackball orbit", "T", &trackball))
            state.orbit = trackball ? OrbitStyle::Trackball : OrbitStyle::Turntable;
        ImGui::MenuItem("Side panel", "Tab", &state.show_side_panel);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Display"))
    {
        DisplayOptions& d = state.display;
        if (ImGui::MenuItem("Flat shading", nullptr, d.shading == Shading::Flat))
            d.shading = Shading::Flat;
        if (ImGui::MenuItem("Smooth shading", "S", d.shading == Shading::Smooth))
            d.shading = Shading::Smooth;
        ImGui::MenuItem("Wireframe", "W", &d.wireframe);
        ImGui::MenuItem("Boundary and singular edges", "B", &d.boundary_edges);
        ImGui::MenuItem("Vertex points", "P", &d.vertex_points);
        ImGui::MenuItem("Tint back faces", nullptr, &d.back_face_tint);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help"))
    {
        ImGui::MenuItem("Keys and mouse", "F1", &state.show_help);
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

void side_panel(const Document& document, EditorState& state, const Camera& camera, UiRequests& r)
{
    const ImGuiIO& io = ImGui::GetIO();
    const float top = ImGui::GetFrameHeight();
    const float bottom = ImGui::GetFrameHeight() + 8;
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kSidePanelWidth, top));
    ImGui::SetNextWindowSize(ImVec2(kSidePanelWidth, io.DisplaySize.y - top - bottom));
    ImGui::Begin("##side", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoCollapse);
    select_section(state, r);
    if (ImGui::CollapsingHeader("Mesh", ImGuiTreeNodeFlags_DefaultOpen))
    {
        const Topology& t = document.topology;
        ImGui::TextUnformatted(std::filesystem::path(document.path).filename().string().c_str());
        ImGui::Text("vertices  %s", with_separators(document.mesh.vertex_count()).c_str());
        ImGui::Text("faces     %s", with_separators(document.mesh.face_count()).c_str());
        ImGui::Text("edges     %s", with_separators(t.edge_count()).c_str());
        ImGui::Text("boundary  %s   singular  %s", with_separators(t.boundary_edge_count).c_str(),
                    with_separators(t.singular_edge_count).c_str());
        for (const std::string& note : document.report.notes)
            ImGui::TextWrapped("note: %s", note.c_str());
    }
    if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen))
    {
        DisplayOptions& d = state.display;
        int shading = d.shading == Shading::Flat ? 0 : 1;
        ImGui::RadioButton("flat", &shading, 0);
        ImGui::SameLine();
        ImGui::RadioButton("smooth", &shading, 1);
        d.shading = shading == 0 ? Shading::Flat : Shading::Smooth;
        ImGui::Checkbox("wireframe (polygon edges)", &d.wireframe);
        ImGui::Checkbox("boundary and singular edges", &d.boundary_edges);
        ImGui::Checkbox("vertex points", &d.vertex_points);
        ImGui::Checkbox("tint back faces", &d.back_face_tint);
        ImGui::SliderFloat("edge width", &d.edge_width_px, 1.0f, 4.0f, "%.1f px");
        ImGui::SliderFloat("point size", &d.point_size_px, 1.0f, 12.0f, "%.0f px");
        ImGui::ColorEdit3("surface", d.surface_color.data(), ImGuiColorEditFlags_NoInputs);
        ImGui::SameLine();
        ImGui::ColorEdit3("background", d.background.data(), ImGuiColorEditFlags_NoInputs);
    }
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen))
    {
        int projection = camera.projection == Projection::Perspective ? 0 : 1;
        const int before = projection;
        ImGui::RadioButton("perspective", &projection, 0);
        ImGui::SameLine();
        ImGui::RadioButton("orthographic", &projection, 1);
        r.toggle_projection = r.toggle_projection || projection != before;
        int orbit = state.orbit == OrbitStyle::Turntable ? 0 : 1;
        ImGui::RadioButton("turntable", &orbit, 0);
        ImGui::SameLine();
        ImGui::RadioButton("trackball", &orbit, 1);
        state.orbit = orbit == 0 ? OrbitStyle::Turntable : OrbitStyle::Trackball;
        int column = 0;
        for (StandardView v : {StandardView::Front, StandardView::Right, StandardView::Top,
                               StandardView::Back, StandardView::Left, StandardView::Bottom})
        {
            if (column++ % 3 != 0)
                ImGui::SameLine();
            if (ImGui::Button(view_name(v), ImVec2(86, 0)))
                r.view = v;
        }
        if (ImGui::Button("Frame all", ImVec2(-1, 0)))
            r.frame_all = true;
    }
    ImGui::End();
}

void status_bar(const Document& document, const EditorState& state)
{
    const ImGuiIO& io = ImGui::GetIO();
    const float height = ImGui::GetFrameHeight() + 8;
    ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoSavedSettings);
    const Topology& t = document.topology;
    const std::string frame = state.frame_ms > 0
                                  ? std::to_string(static_cast<int>(state.frame_ms + 0.5)) + " ms"
                                  : "offscreen";
    ImGui::Text(
        "V %s  F %s  E %s  |  boundary %s  singular %s  |  %s  |  %s%s%s",
        with_separators(document.mesh.vertex_count()).c_str(),
        with_separators(document.mesh.face_count()).c_str(),
        with_separators(t.edge_count()).c_str(), with_separators(t.boundary_edge_count).c_str(),
        with_separators(t.singular_edge_count).c_str(), frame.c_str(), state.renderer_name.c_str(),
        state.message.empty() ? "" : "  |  ", state.message.c_str());
    ImGui::End();
}

void help_overlay(EditorState& state)
{
    if (!state.show_help)
        return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Keys and mouse", &state.show_help,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    if (ImGui::BeginTable("bindings", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV))
    {
        for (const KeyBinding& b : kBindings)
        {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(b.input);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(b.action);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

} // namespace

std::span<const KeyBinding> key_bindings()
{
    return kBindings;
}

void remember_recent(std::vector<std::string>& recent, const std::string& path)
{
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    const std::string p = ec ? path : absolute.lexically_normal().string();
    recent.erase(std::remove(recent.begin(), recent.end(), p), recent.end());
    recent.insert(recent.begin(), p);
    if (recent.size() > 10)
        recent.resize(10);
}

std::string recent_files_path()
{
    const char* config = std::getenv("XDG_CONFIG_HOME");
    if (config != nullptr && config[0] == '/')
        return std::string(config) + "/meshfair/recent.txt";
    const char* home = std::getenv("HOME");
    if (home != nullptr && home[0] == '/')
        return std::string(home) + "/.config/meshfair/recent.txt";
    return {};
}

std::vector<std::string> load_recent(const std::string& file)
{
    std::vector<std::string> recent;
    std::ifstream in(file);
    for (std::string line; recent.size() < 10 && std::getline(in, line);)
        if (!line.empty() && line[0] == '/')
            recent.push_back(line);
    return recent;
}

bool save_recent(const std::string& file, const std::vector<std::string>& recent)
{
    if (file.empty())
        return false;
    std::string text;
    for (const std::string& p : recent)
        if (p.find('\n') == std::string::npos)
            text += p + "\n";
    try
    {
        std::filesystem::create_directories(std::filesystem::path(file).parent_path());
        io::write_file_atomically(file, text);
        return true;
    }
    catch (const std::exception&)
    {
        return false;
    }
}

void EditorUi::open_file_dialog(const Document& document)
{
    browser_.open(FileBrowser::Mode::Open, document.path);
    browser_mode_ = FileBrowser::Mode::Open;
}

void EditorUi::save_file_dialog(const Document& document)
{
    browser_.open(FileBrowser::Mode::Save, document.path,
                  std::filesystem::path(document.path).filename().string());
    browser_mode_ = FileBrowser::Mode::Save;
}

void EditorUi::ask_to_quit(const Document& document, UiRequests& requests)
{
    if (document.modified)
        quit_prompt_ = true;
    else
        requests.quit = true;
}

UiRequests EditorUi::build(const Document& document, EditorState& state, const Camera& camera)
{
    UiRequests r;
    menu_bar(document, state, camera, *this, r);
    if (state.show_side_panel)
        side_panel(document, state, camera, r);
    status_bar(document, state);
    tool_overlay(state);
    help_overlay(state);
    if (const std::optional<std::string> chosen = browser_.draw())
    {
        if (browser_mode_ == FileBrowser::Mode::Open)
            r.open_path = chosen;
        else
            r.save_path = chosen;
    }
    if (quit_prompt_)
    {
        ImGui::OpenPopup("Unsaved changes");
        quit_prompt_ = false;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("%s has unsaved changes.",
                    std::filesystem::path(document.path).filename().string().c_str());
        if (ImGui::Button("Save as..."))
        {
            ImGui::CloseCurrentPopup();
            save_file_dialog(document);
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard and quit"))
        {
            ImGui::CloseCurrentPopup();
            r.quit = true;
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel"))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    return r;
}

ViewRect EditorUi::view_rect(int width, int height, const EditorState& state)
{
    const ImGuiIO& io = ImGui::GetIO();
    // ImGui lays out in window units; the framebuffer may have more pixels (HiDPI).
    const float scale = io.DisplaySize.x > 0 ? float(width) / io.DisplaySize.x : 1.0f;
    const int top = static_cast<int>(ImGui::GetFrameHeight() * scale);
    const int bottom = static_cast<int>((ImGui::GetFrameHeight() + 8) * scale);
    const int right = state.show_side_panel ? static_cast<int>(kSidePanelWidth * scale) : 0;
    return {
        width, height, 0, top, std::max(width - right, 16), std::max(height - top - bottom, 16)};
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
