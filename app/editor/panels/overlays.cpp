// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// What is drawn over the view: the tool's overlay, the status bar and the help overlay.
#include <algorithm>

#include <imgui.h>

#include <string>

#include "app/editor/key_map.h"
#include "app/editor/panels/panel_context.h"
#include "app/render/palette.h"

namespace meshfair::app {

// The active tool's ring, rectangle or lasso line, under the panels.
void grab_highlight(const PanelContext& ui)
{
    const std::vector<ScreenPoint>& h = ui.state.grab_hover;
    if (h.empty())
        return;
    const ImGuiIO& io = ImGui::GetIO();
    const float sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
    const float sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0f;
    const auto at = [&](const ScreenPoint& p) { return ImVec2(float(p.x) / sx, float(p.y) / sy); };
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const palette::Rgb& c = palette::kToolOverlay;
    const ImU32 color = ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 0.95f));
    const ImU32 outline = IM_COL32(0, 0, 0, 200);
    // The arrow retraced from base to tip, its tip ringed; a pin ringed.
    if (h.size() == 2)
    {
        draw->AddLine(at(h[0]), at(h[1]), outline, 5.0f);
        draw->AddLine(at(h[0]), at(h[1]), color, 2.5f);
    }
    draw->AddCircle(at(h.back()), 7.0f, outline, 24, 3.5f);
    draw->AddCircle(at(h.back()), 7.0f, color, 24, 1.5f);
    // Where the handle is, by name, as the panels' widgets are (framebuffer pixels).
    const auto mark = [&](const char* name, const ScreenPoint& p) {
        ui.widgets[name] = {p.x - 2, p.y - 2, p.x + 2, p.y + 2};
    };
    mark("grab/base", h.front());
    if (h.size() == 2)
        mark("grab/tip", h[1]);
}

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
    // White on a dark outline: seen over any surface, selection or set colour.
    const palette::Rgb& c = palette::kToolOverlay;
    const ImU32 color = ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 0.95f));
    const ImU32 outline = IM_COL32(0, 0, 0, 200);
    switch (o.shape)
    {
        case ToolOverlay::Shape::Circle:
            draw->AddCircle(at(o.points[0]), float(o.radius) / sx, outline, 48, 3.5f);
            draw->AddCircle(at(o.points[0]), float(o.radius) / sx, color, 48, 1.5f);
            break;
        case ToolOverlay::Shape::Rectangle:
            if (o.points.size() == 2)
            {
                const ImVec2 a = at(o.points[0]), b = at(o.points[1]);
                draw->AddRectFilled(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                                    ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)),
                                    IM_COL32(255, 255, 255, 30));
                draw->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                              ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)), outline, 0, 0, 3.5f);
                draw->AddRect(ImVec2(std::min(a.x, b.x), std::min(a.y, b.y)),
                              ImVec2(std::max(a.x, b.x), std::max(a.y, b.y)), color, 0, 0, 1.5f);
            }
            break;
        case ToolOverlay::Shape::Polyline:
        {
            std::vector<ImVec2> line;
            for (const ScreenPoint& p : o.points)
                line.push_back(at(p));
            draw->AddPolyline(line.data(), static_cast<int>(line.size()), outline, 0, 3.5f);
            draw->AddPolyline(line.data(), static_cast<int>(line.size()), color, 0, 1.5f);
            break;
        }
        case ToolOverlay::Shape::None:
            break;
    }
}

void status_bar(const PanelContext& ui)
{
    const Document& document = ui.document;
    const EditorState& state = ui.state;
    const ImGuiIO& io = ImGui::GetIO();
    const float height = status_bar_height();
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
        "V %s  F %s  E %s  |  boundary %s  singular %s  |  %s  |  %s",
        with_separators(document.mesh.vertex_count()).c_str(),
        with_separators(document.mesh.face_count()).c_str(),
        with_separators(t.edge_count()).c_str(), with_separators(t.boundary_edge_count).c_str(),
        with_separators(t.singular_edge_count).c_str(), frame.c_str(), state.renderer_name.c_str());
    if (!state.message.empty())
    {
        ImGui::SameLine();
        ImGui::TextColored(
            state.message_is_error ? ImVec4(1, 0.45f, 0.35f, 1) : ImVec4(0.85f, 0.85f, 0.85f, 1),
            "|  %s", state.message.c_str());
        // A long message runs past the window's edge: the whole of it, wrapped, on hover.
        if (ImGui::IsItemHovered())
        {
            ImGui::BeginTooltip();
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40);
            ImGui::TextUnformatted(state.message.c_str());
            ImGui::PopTextWrapPos();
            ImGui::EndTooltip();
        }
    }
    else
        // No newer message: what the run does besides the settings' letter (an open scan's
        // volume kept with its boundary loops capped, ...) stays in view while it plays.
        for (const std::string& note : state.run_notes)
        {
            ImGui::SameLine();
            ImGui::TextColored(ImVec4(0.85f, 0.85f, 0.85f, 1), "|  %s", note.c_str());
        }
    ImGui::End();
}

void preparation_toast(const PanelContext& ui)
{
    const EditorState& state = ui.state;
    const SolverStatus& st = state.solver;
    if (!st.preparing)
        return;
    const ImGuiIO& io = ImGui::GetIO();
    const float view_width = io.DisplaySize.x - (state.show_side_panel ? kSidePanelWidth : 0.0f);
    const float width = std::min(420.0f, view_width - 20);
    const float top = ImGui::GetFrameHeight() + 12; // below the menu bar
    ImGui::SetNextWindowPos(ImVec2(view_width * 0.5f, top), ImGuiCond_Always, ImVec2(0.5f, 0));
    ImGui::SetNextWindowSize(ImVec2(width, 0));
    ImGui::Begin("##preparing", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::TextWrapped("Preparing the solver: %s", preparation_text(st, !state.offscreen).c_str());
    const double fraction = state.offscreen ? -1 : st.preparation.fraction();
    ImGui::ProgressBar(fraction >= 0 ? static_cast<float>(fraction) : 0.0f, ImVec2(-110, 0),
                       fraction >= 0 ? nullptr : "");
    ImGui::SameLine();
    if (ui.button("Cancel (Esc)###cancel preparation", "cancel preparation"))
        ui.give(cmd::CancelPreparation{});
    ImGui::End();
}

void error_toast(const PanelContext& ui, std::string& dismissed, bool& expanded)
{
    const EditorState& state = ui.state;
    if (!state.message_is_error || state.message.empty() || state.message == dismissed)
        return;
    const ImGuiIO& io = ImGui::GetIO();
    const float view_width = io.DisplaySize.x - (state.show_side_panel ? kSidePanelWidth : 0.0f);
    const float width = std::min(480.0f, view_width - 20);
    // Below the menu bar, beside the preparation's box when it shows.
    const float top = ImGui::GetFrameHeight() + 12 + (state.solver.preparing ? 90.0f : 0.0f);
    ImGui::SetNextWindowPos(ImVec2(view_width * 0.5f, top), ImGuiCond_Always, ImVec2(0.5f, 0));
    ImGui::SetNextWindowBgAlpha(0.92f);
    // Fitted to its text at once (the whole text shown grows it in the same frame).
    ImGui::Begin("##refused", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoScrollbar |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::Dummy(ImVec2(width - 2 * ImGui::GetStyle().WindowPadding.x, 0));
    ImGui::TextColored(ImVec4(1, 0.45f, 0.35f, 1), "Not done");
    ImGui::SameLine(width - 34);
    if (ui.small_button("x##toast", "toast/close"))
        dismissed = state.message;
    // The first lines, wrapped; the whole text a click away.
    constexpr size_t kShort = 220;
    const bool long_text = state.message.size() > kShort;
    const std::string text =
        long_text && !expanded ? state.message.substr(0, kShort) + " ..." : state.message;
    ImGui::PushTextWrapPos(width - ImGui::GetStyle().WindowPadding.x);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ui.track("toast/text");
    if (long_text && ui.small_button(expanded ? "less" : "the whole text", "toast/whole text"))
        expanded = !expanded;
    ImGui::End();
}

void help_overlay(const PanelContext& ui)
{
    const EditorState& state = ui.state;
    if (!state.show_help)
        return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    bool open = true;
    ImGui::Begin("Keys and mouse", &open,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    if (ImGui::BeginTable("bindings", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV))
    {
        for (const KeyBinding& b : key_bindings())
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
    if (!open)
        ui.give(cmd::Toggle{cmd::DisplayToggle::Help});
}

} // namespace meshfair::app
