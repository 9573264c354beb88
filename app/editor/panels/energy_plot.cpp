// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "app/editor/panels/panel_context.h"
#include "core/recipe/energy_terms.h"

namespace meshfair::app {

namespace {

// The relative gradient's curve: cyan.
constexpr ImU32 kGradientColor = IM_COL32(80, 220, 240, 255);

// Each term's colour in the plot (the total is white).
ImU32 curve_color(EnergyTerm term)
{
    switch (term)
    {
        case EnergyTerm::Edge:
            return IM_COL32(120, 200, 120, 255);
        case EnergyTerm::Soft:
            return IM_COL32(240, 190, 40, 255);
        case EnergyTerm::Centroid:
            return IM_COL32(70, 140, 240, 255);
        case EnergyTerm::Normal:
            return IM_COL32(180, 90, 230, 255);
        case EnergyTerm::Bending:
            return IM_COL32(240, 110, 90, 255);
        case EnergyTerm::Total:
            break;
    }
    return IM_COL32(255, 255, 255, 255);
}

// The energy curve of the current run: the total and each active term, of what moves
// (each term's parts with a free vertex: a region's curve is not flattened by the energy of
// the fixed rest) or of the whole mesh, with the relative gradient; log scale or not.
void energy_plot(const PanelContext& ui)
{
    const EditorState& state = ui.state;
    const std::vector<EnergySample>& e = state.energies;
    bool log_scale = state.energy_log_scale;
    if (ui.checkbox("log scale", &log_scale))
        ui.give(cmd::Toggle{cmd::DisplayToggle::EnergyLogScale});
    ImGui::SameLine();
    bool whole = state.energy_whole_mesh;
    if (ui.checkbox("whole mesh", &whole))
        ui.give(cmd::Toggle{cmd::DisplayToggle::EnergyWholeMesh});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Off: the energy of what moves, the terms' parts that hold a free vertex.\n"
            "On: the whole mesh's, fixed vertices included.");
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
    // What a curve plots of a sample: a term, the total, or the gradient.
    using Of = double (*)(const EnergySample&, Scalar TermEnergies::*, bool);
    struct Curve
    {
        Scalar TermEnergies::*term; // null: the total
        std::string_view name;
        ImU32 color;
        Of of;
        float width;
    };
    const Of term_of = [](const EnergySample& s, Scalar TermEnergies::*term, bool all) {
        const double v = term ? s.energy.*term : s.energy.total();
        const double held = term ? s.held.*term : s.held.total();
        return all ? v : std::max(v - held, 0.0);
    };
    const Of gradient_of = [](const EnergySample& s, Scalar TermEnergies::*, bool) {
        return double(s.gradient);
    };
    // The terms of the positions (those with per-vertex shares), by energy_terms(), the
    // total over them, and the gradient where the run knows it.
    std::vector<Curve> curves;
    for (const EnergyTermInfo& t : energy_terms())
        if (t.shares)
            curves.push_back({t.energy, t.label, curve_color(*t.shares), term_of, 1.5f});
    curves.push_back({nullptr, "total", IM_COL32(255, 255, 255, 255), term_of, 2.0f});
    const bool has_gradient = std::count_if(e.begin(), e.end(), [](const EnergySample& s) {
                                  return s.gradient >= 0;
                              }) >= 2;
    if (has_gradient)
        curves.push_back({nullptr, "gradient", kGradientColor, gradient_of, 1.5f});
    // Each curve relative to its own largest value over the run, so that terms of very
    // different sizes all show how they converge (a term that starts at 0, as a soft
    // constraint on the input does, rises and settles).
    std::vector<double> top(curves.size(), 0.0);
    for (const EnergySample& s : e)
        for (size_t c = 0; c < curves.size(); ++c)
            top[c] = std::max(top[c], curves[c].of(s, curves[c].term, whole));
    const double floor_value = 1e-6; // the log scale's bottom: a millionth of the largest
    const auto value = [&](double v, double largest) {
        const double r = largest > 0 ? v / largest : 0;
        return state.energy_log_scale ? std::log10(std::max(r, floor_value)) : r;
    };
    const auto known = [&](const Curve& c, const EnergySample& s) {
        return c.of != gradient_of || s.gradient >= 0;
    };
    double lo = 1e300;
    for (const EnergySample& s : e)
        for (size_t c = 0; c < curves.size(); ++c)
            if (top[c] > 0 && known(curves[c], s))
                lo = std::min(lo, value(curves[c].of(s, curves[c].term, whole), top[c]));
    const double hi = state.energy_log_scale ? 0.0 : 1.0;
    lo = std::min(lo, hi - (state.energy_log_scale ? 0.5 : 0.1));
    const double last = std::max(e.back().step, 1);
    std::vector<ImVec2> line;
    for (size_t c = 0; c < curves.size(); ++c)
    {
        if (!(top[c] > 0))
            continue;
        line.clear();
        for (const EnergySample& s : e)
            if (known(curves[c], s))
                line.emplace_back(
                    origin.x + float(s.step / last) * (size.x - 1),
                    origin.y + float((hi - value(curves[c].of(s, curves[c].term, whole), top[c])) /
                                     (hi - lo)) *
                                   (size.y - 1));
        draw->AddPolyline(line.data(), static_cast<int>(line.size()), curves[c].color, 0,
                          curves[c].width);
    }
    // The vertical range, at the plot's corners.
    char label[64];
    std::snprintf(label, sizeof label, state.energy_log_scale ? "1e%.1f" : "%.2g", lo);
    draw->AddText(ImVec2(origin.x + 4, origin.y + size.y - ImGui::GetFontSize() - 2),
                  IM_COL32(170, 170, 170, 255), label);
    draw->AddText(ImVec2(origin.x + 4, origin.y + 2), IM_COL32(170, 170, 170, 255),
                  "1 = each curve's largest value");
    const EnergySample& now = e.back();
    const double moving = term_of(now, nullptr, false);
    if (whole)
        ImGui::Text("step %d   whole mesh %.6g   (what moves %.6g)", now.step, now.energy.total(),
                    moving);
    else
        ImGui::Text("step %d   what moves %.6g   (whole mesh %.6g)", now.step, moving,
                    now.energy.total());
    // Relative to the first point that has one (the plot may have been opened mid-run).
    const auto start =
        std::find_if(e.begin(), e.end(), [](const EnergySample& s) { return s.gradient > 0; });
    bool first = true;
    if (start != e.end() && now.gradient >= 0)
    {
        first = false;
        ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(kGradientColor), "gradient %.2g ",
                           now.gradient / start->gradient);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "The gradient's size |r| over the free vertices, relative to the\n"
                "run's start: 0 at the minimizer.");
    }
    for (const Curve& c : curves)
        if (c.term != nullptr && term_of(now, c.term, whole) > 0)
        {
            if (!first)
                ImGui::SameLine();
            first = false;
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(c.color), "%s %.4g ",
                               std::string(c.name).c_str(), term_of(now, c.term, whole));
        }
}

} // namespace

// The energy plot in a strip of its own under the view, across its width: the view
// shrinks to make room (EditorUi::view_rect), so the plot never covers the mesh.
void energy_window(const PanelContext& ui)
{
    EditorState& state = ui.state;
    if (!state.show_energy)
        return;
    const ImGuiIO& io = ImGui::GetIO();
    const float bottom = status_bar_height();
    const float width = io.DisplaySize.x - (state.show_side_panel ? kSidePanelWidth : 0.0f);
    ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - bottom - kEnergyPanelHeight));
    ImGui::SetNextWindowSize(ImVec2(width, kEnergyPanelHeight));
    bool open = true;
    ImGui::Begin("Energy", &open,
                 ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
    energy_plot(ui);
    ImGui::End();
    if (!open)
        ui.give(cmd::Toggle{cmd::DisplayToggle::EnergyPlot});
}

} // namespace meshfair::app
