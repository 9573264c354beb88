// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_ui.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <imgui.h>

#include "app/editor/heat_map.h"
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
    {"M", "tool: drag pins to new targets in the view plane"},
    {"D", "tool: drag a normal set's arrows to turn its direction"},
    {"V", "select vertices / faces"},
    {"[ / ]", "brush radius smaller / larger"},
    {"Ctrl + A, Alt + A", "select all, select none"},
    {"Ctrl + I", "invert the selection"},
    {"Ctrl + = / Ctrl + -", "grow / shrink the selection by a ring"},
    {"Ctrl + L", "select the connected components of the selection"},
    {"Ctrl + B", "select the boundary"},
    {"Shift + R / P / A / C / N",
     "new region / pin / anchor / centroid / normal set from the selection"},
    {"Space", "play / pause live solving"},
    {"E", "energy plot"},
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
    {"Ctrl + S", "save (the file it came from, in its format)"},
    {"Ctrl + Shift + S", "save as"},
    {"Ctrl + Q, closing the window", "quit (asks first when there are unsaved changes)"},
};

constexpr float kSidePanelWidth = 340;

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
constexpr ToolItem kToolItems[] = {
    {ToolKind::Navigate, "navigate (N)"},     {ToolKind::Click, "click (K)"},
    {ToolKind::Brush, "brush (C)"},           {ToolKind::Rectangle, "rectangle (R)"},
    {ToolKind::Lasso, "lasso (L)"},           {ToolKind::MovePins, "move pins (M)"},
    {ToolKind::AimNormals, "aim normals (D)"}};

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
    if (ImGui::SliderFloat("radius", &radius, 2.0f, 200.0f, "%.0f px"))
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
        if (ImGui::MenuItem("Save", "Ctrl+S"))
            r.save_path = document.path;
        if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S"))
            ui.save_file_dialog(document);
        if (ImGui::MenuItem("Export recipe..."))
            ui.export_recipe_dialog(document);
        if (ImGui::MenuItem("Import recipe..."))
            ui.import_recipe_dialog(document);
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
        ImGui::MenuItem("Energy plot", "E", &state.show_energy);
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

const char* kind_label(ConstraintKind kind)
{
    switch (kind)
    {
        case ConstraintKind::Region:
            return "region";
        case ConstraintKind::Pin:
            return "pin";
        case ConstraintKind::Anchor:
            return "anchor";
        case ConstraintKind::Centroid:
            return "centroid";
        case ConstraintKind::Normal:
            return "normal";
        case ConstraintKind::HardNormal:
            return "hard normal";
        case ConstraintKind::SoftNormal:
            return "soft normal";
    }
    return "";
}

UiRequests::SetEdit set_edit(UiRequests::SetEdit::What what, size_t index)
{
    UiRequests::SetEdit e;
    e.what = what;
    e.index = index;
    return e;
}

void sets_section(const Document& document, const EditorState& state, UiRequests& r,
                  char* rename_buffer, size_t rename_size, size_t& renaming)
{
    if (!ImGui::CollapsingHeader("Constraint sets", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    ImGui::TextUnformatted("new from the selection:");
    for (int k = 0; k < kConstraintKinds; ++k)
    {
        const auto kind = static_cast<ConstraintKind>(k);
        if (k % 4 != 0)
            ImGui::SameLine();
        if (ImGui::SmallButton(kind_label(kind)))
            r.create_set = kind;
    }
    for (size_t i = 0; i < document.sets.size(); ++i)
    {
        const ConstraintSet& set = document.sets[i];
        ImGui::PushID(static_cast<int>(i));
        bool visible = set.visible;
        if (ImGui::Checkbox("##visible", &visible))
        {
            r.set_edit = set_edit(UiRequests::SetEdit::What::Show, i);
            r.set_edit->visible = visible;
        }
        ImGui::SameLine();
        std::array<float, 3> color = set.color;
        if (ImGui::ColorEdit3("##color", color.data(), ImGuiColorEditFlags_NoInputs))
        {
            r.set_edit = set_edit(UiRequests::SetEdit::What::Color, i);
            r.set_edit->color = color;
        }
        ImGui::SameLine();
        const size_t count = set.vertices.size() + set.faces.size();
        ImGui::Text("%s  (%s, %s %s)", set.name.c_str(), kind_label(set.kind),
                    with_separators(static_cast<std::int64_t>(count)).c_str(),
                    set.vertices.empty() ? "faces" : "vertices");
        if (ImGui::SmallButton("select"))
            r.set_edit = set_edit(UiRequests::SetEdit::What::Select, i);
        ImGui::SameLine();
        if (ImGui::SmallButton("rename"))
        {
            renaming = i;
            std::snprintf(rename_buffer, rename_size, "%s", set.name.c_str());
            ImGui::OpenPopup("rename");
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("delete"))
            r.set_edit = set_edit(UiRequests::SetEdit::What::Delete, i);
        if (set.kind == ConstraintKind::Normal || set.kind == ConstraintKind::HardNormal ||
            set.kind == ConstraintKind::SoftNormal)
        {
            Vec3 d = set.normals.empty() ? Vec3{0, 0, 1} : set.normals.front();
            float direction[3] = {float(d[0]), float(d[1]), float(d[2])};
            ImGui::SetNextItemWidth(180);
            if (ImGui::DragFloat3("direction", direction, 0.01f, -1.0f, 1.0f, "%.2f"))
            {
                r.set_edit = set_edit(UiRequests::SetEdit::What::Direction, i);
                r.set_edit->direction = {direction[0], direction[1], direction[2]};
            }
        }
        if (ImGui::BeginPopup("rename"))
        {
            ImGui::InputText("name", rename_buffer, rename_size);
            if (ImGui::Button("OK") && rename_buffer[0] != 0)
            {
                r.set_edit = set_edit(UiRequests::SetEdit::What::Rename, renaming);
                r.set_edit->name = rename_buffer;
                ImGui::CloseCurrentPopup();
            }
            ImGui::EndPopup();
        }
        ImGui::PopID();
    }
    for (const std::string& problem : state.problems)
        ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", problem.c_str());
    ImGui::TextWrapped(
        "Vertices outside the regions are fixed; the border ring (orange) is "
        "where they meet the moving ones.");
}

// The energy curve of the current run: the total and each active term, log scale or not.
void energy_plot(EditorState& state)
{
    const std::vector<EnergySample>& e = state.energies;
    ImGui::Checkbox("log scale", &state.energy_log_scale);
    const ImVec2 size(ImGui::GetContentRegionAvail().x, 120);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                        IM_COL32(25, 27, 31, 255));
    ImGui::Dummy(size);
    if (e.size() < 2)
    {
        draw->AddText(ImVec2(origin.x + 8, origin.y + 8), IM_COL32(170, 170, 170, 255),
                      "Play or Step to draw the energy of the run");
        return;
    }
    struct Curve
    {
        Scalar TermEnergies::*term;
        const char* name;
        ImU32 color;
    };
    const Curve curves[] = {{&TermEnergies::edge, "edge", IM_COL32(120, 200, 120, 255)},
                            {&TermEnergies::soft, "anchor", IM_COL32(240, 190, 40, 255)},
                            {&TermEnergies::centroid, "centroid", IM_COL32(70, 140, 240, 255)},
                            {&TermEnergies::normal, "normal", IM_COL32(180, 90, 230, 255)}};
    // Each curve relative to its own largest value over the run, so that terms of very
    // different sizes all show how they converge (a term that starts at 0, as a soft
    // constraint on the input does, rises and settles).
    std::vector<double> top(std::size(curves) + 1, 0.0);
    for (const EnergySample& s : e)
    {
        for (size_t c = 0; c < std::size(curves); ++c)
            top[c] = std::max(top[c], s.energy.*curves[c].term);
        top.back() = std::max(top.back(), s.energy.total());
    }
    const double floor_value = 1e-6; // the log scale's bottom: a millionth of the largest
    const auto value = [&](double v, double largest) {
        const double r = largest > 0 ? v / largest : 0;
        return state.energy_log_scale ? std::log10(std::max(r, floor_value)) : r;
    };
    double lo = 1e300;
    for (const EnergySample& s : e)
    {
        lo = std::min(lo, value(s.energy.total(), top.back()));
        for (size_t c = 0; c < std::size(curves); ++c)
            if (top[c] > 0)
                lo = std::min(lo, value(s.energy.*curves[c].term, top[c]));
    }
    const double hi = state.energy_log_scale ? 0.0 : 1.0;
    lo = std::min(lo, hi - (state.energy_log_scale ? 0.5 : 0.1));
    const double last = std::max(e.back().step, 1);
    const auto at = [&](const EnergySample& s, double v, double largest) {
        return ImVec2(origin.x + float(s.step / last) * (size.x - 1),
                      origin.y + float((hi - value(v, largest)) / (hi - lo)) * (size.y - 1));
    };
    std::vector<ImVec2> line;
    for (size_t c = 0; c < std::size(curves); ++c)
    {
        if (!(top[c] > 0))
            continue;
        line.clear();
        for (const EnergySample& s : e)
            line.push_back(at(s, s.energy.*curves[c].term, top[c]));
        draw->AddPolyline(line.data(), static_cast<int>(line.size()), curves[c].color, 0, 1.5f);
    }
    line.clear();
    for (const EnergySample& s : e)
        line.push_back(at(s, s.energy.total(), top.back()));
    draw->AddPolyline(line.data(), static_cast<int>(line.size()), IM_COL32(255, 255, 255, 255), 0,
                      2.0f);
    // The vertical range, at the plot's corners.
    char label[64];
    std::snprintf(label, sizeof label, state.energy_log_scale ? "1e%.1f" : "%.2g", lo);
    draw->AddText(ImVec2(origin.x + 4, origin.y + size.y - ImGui::GetFontSize() - 2),
                  IM_COL32(170, 170, 170, 255), label);
    draw->AddText(ImVec2(origin.x + 4, origin.y + 2), IM_COL32(170, 170, 170, 255),
                  "1 = each curve's largest value");
    const TermEnergies& now = e.back().energy;
    ImGui::Text("step %d   total %.6g", e.back().step, now.total());
    bool first = true;
    for (const Curve& c : curves)
        if (now.*c.term > 0)
        {
            if (!first)
                ImGui::SameLine();
            first = false;
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(c.color), "%s %.4g ", c.name,
                               now.*c.term);
        }
}

void solver_section(const Document& document, EditorState& state, UiRequests& r)
{
    if (!ImGui::CollapsingHeader("Solver", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    SolverSettings s = document.solver;
    bool changed = false, release = false;
    const auto track = [&](bool edited) {
        changed = changed || edited;
        release = release || ImGui::IsItemDeactivatedAfterEdit();
    };
    track(ImGui::Checkbox("optimal step (line search)", &s.optimal_step));
    if (!s.optimal_step)
    {
        float lambda = float(s.lambda);
        track(ImGui::SliderFloat("lambda", &lambda, 0.01f, 1.0f, "%.3f"));
        s.lambda = lambda;
    }
    track(ImGui::SliderInt("steps/frame", &s.iterations_per_frame, 1, 200));
    float tolerance = float(s.tolerance);
    track(ImGui::InputFloat("tolerance", &tolerance, 0, 0, "%.2e"));
    s.tolerance = std::max(tolerance, 0.0f);
    const auto mu = [&](const char* label, Scalar& value) {
        float v = float(value);
        track(ImGui::SliderFloat(label, &v, 0.0f, 100.0f, "%.3g", ImGuiSliderFlags_Logarithmic));
        value = v;
    };
    mu("anchor mu", s.anchor_mu);
    mu("centroid mu", s.centroid_mu);
    mu("normal mu", s.normal_mu);
    bool exact = s.denominator == CentroidDenominator::Exact;
    track(ImGui::Checkbox("exact centroid denominator", &exact));
    s.denominator = exact ? CentroidDenominator::Exact : CentroidDenominator::Paper;
    bool smoothed = s.normal_source == NormalSource::Smoothed;
    track(ImGui::Checkbox("smoothed normals", &smoothed));
    s.normal_source = smoothed ? NormalSource::Smoothed : NormalSource::Initial;
    track(ImGui::Checkbox("joint mode", &s.joint));
    if (s.joint)
    {
        float gamma = float(s.gamma);
        track(ImGui::SliderFloat("gamma", &gamma, 0.0f, 100.0f, "%.3g",
                                 ImGuiSliderFlags_Logarithmic));
        s.gamma = gamma;
    }
    if (changed && !(s == document.solver))
    {
        r.solver = s;
        r.solver_merge = !release;
    }
    if (ImGui::Button(state.playing ? "Pause" : "Play", ImVec2(60, 0)))
        (state.playing ? r.pause : r.play) = true;
    ImGui::SameLine();
    if (ImGui::Button("Step"))
        r.step = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset"))
        r.reset_shape = true;
    ImGui::SameLine();
    if (ImGui::Button("Apply"))
        r.apply_shape = true;
    const SolverStatus& st = state.solver;
    ImGui::Text("%d steps from the base%s", document.steps_from_base,
                document.reproducible ? "" : " (recipe changed during the run)");
    if (!state.offscreen) // a time would make offscreen frames differ from run to run
        ImGui::Text("last frame %.1f ms on the solver's thread", st.step_ms);
    const char* heat_items[] = {"off", "total", "edge", "anchor", "centroid", "normal"};
    int heat = state.heat_map ? 1 + static_cast<int>(*state.heat_map) : 0;
    ImGui::SetNextItemWidth(120);
    if (ImGui::Combo("heat map: energy share", &heat, heat_items, 6))
        r.heat_map =
            heat == 0 ? std::nullopt : std::optional<EnergyTerm>(static_cast<EnergyTerm>(heat - 1));
    ImGui::SetNextItemWidth(100);
    ImGui::SliderFloat("##sigma", &state.noise_sigma, 0.0f, 1.0f, "sigma %.2f");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    ImGui::InputInt("##seed", &state.noise_seed, 0);
    ImGui::SameLine();
    if (ImGui::Button("Add noise"))
        r.noise = std::pair<Scalar, std::uint64_t>(state.noise_sigma,
                                                   static_cast<std::uint64_t>(state.noise_seed));
    if (!st.error.empty())
        ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "%s", st.error.c_str());
    if (st.converged)
        ImGui::TextUnformatted("converged (tolerance)");
}

// The energy plot in its own window at the bottom left of the view, always in sight.
void energy_window(EditorState& state)
{
    if (!state.show_energy)
        return;
    const ImGuiIO& io = ImGui::GetIO();
    const float bottom = ImGui::GetFrameHeight() + 8;
    ImGui::SetNextWindowPos(ImVec2(8, io.DisplaySize.y - bottom - 8), ImGuiCond_Always,
                            ImVec2(0, 1));
    ImGui::SetNextWindowSize(ImVec2(420, 0));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Energy", &state.show_energy,
                 ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
    energy_plot(state);
    ImGui::End();
}

void side_panel(const Document& document, EditorState& state, const Camera& camera, UiRequests& r,
                char* rename_buffer, size_t rename_size, size_t& renaming)
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
    sets_section(document, state, r, rename_buffer, rename_size, renaming);
    solver_section(document, state, r);
    if (ImGui::CollapsingHeader("Mesh"))
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
    if (ImGui::CollapsingHeader("Display"))
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
    if (ImGui::CollapsingHeader("Camera"))
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

void EditorUi::export_recipe_dialog(const Document& document)
{
    const std::filesystem::path mesh(document.path);
    browser_.open(FileBrowser::Mode::Save, document.path, mesh.stem().string() + "-recipe.json",
                  FileBrowser::Files::Recipes);
    browser_mode_ = FileBrowser::Mode::Save;
}

void EditorUi::import_recipe_dialog(const Document& document)
{
    browser_.open(FileBrowser::Mode::Open, document.path, {}, FileBrowser::Files::Recipes);
    browser_mode_ = FileBrowser::Mode::Open;
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
        side_panel(document, state, camera, r, rename_buffer_, sizeof rename_buffer_, renaming_);
    status_bar(document, state);
    energy_window(state);
    tool_overlay(state);
    help_overlay(state);
    if (const std::optional<std::string> chosen = browser_.draw())
    {
        const bool recipe = browser_.files() == FileBrowser::Files::Recipes;
        if (browser_mode_ == FileBrowser::Mode::Open)
            (recipe ? r.import_recipe_path : r.open_path) = chosen;
        else
            (recipe ? r.export_recipe_path : r.save_path) = chosen;
    }
    if (state.recovery_saved_at && !ImGui::IsPopupOpen("Recover unsaved work"))
        ImGui::OpenPopup("Recover unsaved work");
    if (ImGui::BeginPopupModal("Recover unsaved work", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    {
        ImGui::Text("A session of %s ended without saving; its work was autosaved at %s.",
                    std::filesystem::path(document.path).filename().string().c_str(),
                    state.recovery_saved_at ? state.recovery_saved_at->c_str() : "");
        if (ImGui::Button("Recover"))
        {
            r.recover = true;
            state.recovery_saved_at.reset();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard"))
        {
            r.discard_recovery = true;
            state.recovery_saved_at.reset();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    // A slider or a field let go ends its series of edits: the next one is a new undo step.
    r.seal_history = ImGui::IsAnyItemActive() == false && was_editing_;
    was_editing_ = ImGui::IsAnyItemActive();
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
