// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/panels/panel_context.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace meshfair::app {

namespace {

// The text a person reads on a widget: its label before any "##" or "###".
std::string visible_label(const char* label)
{
    const std::string text(label);
    return text.substr(0, text.find("##"));
}

} // namespace

float status_bar_height()
{
    return ImGui::GetFrameHeight() + 8;
}

void PanelContext::track(const std::string& label) const
{
    if (!ImGui::IsItemVisible())
        return; // scrolled out of its window: not where a click can reach it
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    // Half cut off by the window's edge: a click at its centre would miss it.
    const ImVec2 lo = ImGui::GetWindowDrawList()->GetClipRectMin();
    const ImVec2 hi = ImGui::GetWindowDrawList()->GetClipRectMax();
    const float cx = (a.x + b.x) / 2, cy = (a.y + b.y) / 2;
    if (cx < lo.x || cx >= hi.x || cy < lo.y || cy >= hi.y)
        return;
    const double sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0;
    const double sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0;
    widgets[label] = {a.x * sx, a.y * sy, b.x * sx, b.y * sy};
}

bool PanelContext::button(const char* label, const std::string& key) const
{
    const bool pressed = ImGui::Button(label);
    track(key.empty() ? visible_label(label) : key);
    return pressed;
}

bool PanelContext::small_button(const char* label, const std::string& key) const
{
    const bool pressed = ImGui::SmallButton(label);
    track(key.empty() ? visible_label(label) : key);
    return pressed;
}

bool PanelContext::checkbox(const char* label, bool* value, const std::string& key) const
{
    const bool changed = ImGui::Checkbox(label, value);
    track(key.empty() ? visible_label(label) : key);
    return changed;
}

bool PanelContext::radio(const char* label, bool active, const std::string& key) const
{
    const bool pressed = ImGui::RadioButton(label, active);
    track(key.empty() ? visible_label(label) : key);
    return pressed;
}

bool PanelContext::curve_combo(const char* label, FalloffCurve& curve) const
{
    bool chosen = false;
    ImGui::SetNextItemWidth(120);
    if (ImGui::BeginCombo(label, std::string(falloff_curve_name(curve)).c_str()))
    {
        for (int c = 0; c < 6; ++c)
        {
            const auto item = static_cast<FalloffCurve>(c);
            const std::string name(falloff_curve_name(item));
            if (ImGui::Selectable(name.c_str(), item == curve))
            {
                curve = item;
                chosen = true;
            }
            track(std::string(label) + "/" + name);
        }
        ImGui::EndCombo();
    }
    track(label);
    return chosen;
}

const char* kind_label(ConstraintKind kind)
{
    return kind_info(kind).label.data(); // (the table's literals end in a NUL)
}

std::string preparation_text(const SolverStatus& status, bool with_times)
{
    const PreparationProgress::Snapshot& p = status.preparation;
    std::string text;
    switch (p.phase)
    {
        case PreparationProgress::Phase::Assembling:
            text = "building the terms and the system";
            break;
        case PreparationProgress::Phase::Ordering:
            text = "ordering " + with_separators(p.unknowns) + " unknowns";
            break;
        case PreparationProgress::Phase::Factoring:
        {
            char flops[64];
            std::snprintf(flops, sizeof flops, "factoring (%.1f Gflop)", p.flops / 1e9);
            text = flops;
            break;
        }
        case PreparationProgress::Phase::Done:
            text = "solving";
            break;
    }
    if (p.cancelled)
        text += ", cancelled: stops when this phase ends";
    else if (with_times && p.expected_seconds > 0)
        text += ": " + std::to_string(std::lround(p.seconds)) + " s of about " +
                std::to_string(std::max(1L, std::lround(p.expected_seconds)));
    else if (with_times)
        text += ": " + std::to_string(std::lround(p.seconds)) + " s";
    return text;
}

} // namespace meshfair::app
