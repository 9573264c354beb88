// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/editor/heat_map.h"
#include "app/editor/panels/panel_context.h"
#include "app/editor/persistence.h"

namespace meshfair::app {

namespace {

// A weight's slider: logarithmic over [1e-3, 1e3] (a pixel is a fixed ratio, never a
// jump from 1 to 0.04), with Ctrl+click to type a value.
bool weight_slider(const PanelContext& ui, const char* label, Scalar& value)
{
    float v = float(value);
    const bool changed =
        ImGui::SliderFloat(label, &v, 1e-3f, 1e3f, "%.4g", ImGuiSliderFlags_Logarithmic);
    ui.track(label);
    if (changed)
        value = std::clamp(Scalar(v), Scalar(1e-3), Scalar(1e3));
    return changed;
}

} // namespace

void solver_panel(const PanelContext& ui)
{
    using namespace cmd;
    if (!ImGui::CollapsingHeader("Solver", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    const Document& document = ui.document;
    const EditorState& state = ui.state;
    // The presets: each sets the recipe's settings over the artist's regions and pins.
    static const std::vector<std::string> presets = preset_names();
    static const std::vector<std::string> descriptions = [] {
        std::vector<std::string> out;
        for (const std::string& name : presets)
            out.push_back(preset_description(name));
        return out;
    }();
    ImGui::SetNextItemWidth(160);
    const bool applied =
        ui.state.preset_applied && ui.state.preset_applied->second == document.solver;
    if (ImGui::BeginCombo("preset", applied ? ui.state.preset_applied->first.c_str() : "choose...",
                          ImGuiComboFlags_None))
    {
        for (size_t k = 0; k < presets.size(); ++k)
        {
            const std::string& name = presets[k];
            if (ImGui::Selectable(name.c_str(), false))
                ui.give(ApplyPreset{name});
            // What each preset is for, where the artist chooses it.
            if (!descriptions[k].empty() && ImGui::IsItemHovered())
            {
                ImGui::BeginTooltip();
                ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28);
                ImGui::TextUnformatted(descriptions[k].c_str());
                ImGui::PopTextWrapPos();
                ImGui::EndTooltip();
            }
            ui.track("preset/" + name);
        }
        ImGui::EndCombo();
    }
    ui.track("preset");
    SolverSettings s = document.solver;
    bool toggled = false, dragged = false;
    toggled |= ui.checkbox("optimal step (line search, safe)", &s.optimal_step, "optimal step");
    if (!s.optimal_step)
    {
        // Within (0, 1): the step never overshoots a vertex's own minimizer.
        float lambda = float(s.lambda);
        if (ImGui::SliderFloat("lambda", &lambda, 0.01f, 0.99f, "%.3f"))
        {
            s.lambda = std::clamp(lambda, 0.01f, 0.99f);
            dragged = true;
        }
        ui.track("lambda");
    }
    if (ImGui::SliderInt("steps/frame", &s.iterations_per_frame, 1, 200))
    {
        s.iterations_per_frame = std::clamp(s.iterations_per_frame, 1, 200);
        dragged = true;
    }
    ui.track("steps/frame");
    if (!s.until_converged)
    {
        if (ImGui::SliderInt("steps per run", &s.steps_per_run, 1, 2000, "%d",
                             ImGuiSliderFlags_Logarithmic))
        {
            s.steps_per_run = std::clamp(s.steps_per_run, 1, 100000);
            dragged = true;
        }
        ui.track("steps per run");
    }
    // Where nothing holds a free part, its energy has no unique minimizer: steps only shrink
    // it toward a point, and "until converged" would melt it; Taubin's steps converge to
    // no minimizer. Not offered; the reason shown.
    const std::string& no_minimizer = state.solver.no_minimizer;
    if (!no_minimizer.empty() && !s.until_converged)
        ImGui::BeginDisabled();
    toggled |= ui.checkbox("until converged", &s.until_converged);
    if (!no_minimizer.empty() && !s.until_converged)
        ImGui::EndDisabled();
    if (!no_minimizer.empty() && s.method == Method::Taubin)
    {
        // A tooltip: the line the reason would take would move the panel's widgets when
        // the method's restart ends.
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip(
                "until converged is off for Taubin's steps: they keep the "
                "shape's low frequencies instead of converging to a minimum; "
                "a run plays the steps per run");
    }
    else if (!no_minimizer.empty())
    {
        ImGui::PushTextWrapPos(0);
        ImGui::TextDisabled(
            "until converged is off here: nothing holds the free part, so "
            "its energy has no minimum to settle at (it would shrink to a "
            "point); a run plays the steps per run. Pin, anchor or make a "
            "region to hold it.");
        ImGui::PopTextWrapPos();
    }
    float tolerance = float(s.tolerance);
    if (ImGui::InputFloat("tolerance", &tolerance, 0, 0, "%.2e"))
    {
        s.tolerance = std::max(tolerance, 0.0f);
        dragged = true;
    }
    ui.track("tolerance");
    // The weights of the sets that have none of their own (a set's row sets its own).
    ImGui::TextDisabled("weights of sets without their own:");
    dragged |= weight_slider(ui, "anchor mu", s.anchor_mu);
    dragged |= weight_slider(ui, "centroid mu", s.centroid_mu);
    dragged |= weight_slider(ui, "normal mu", s.normal_mu);
    bool exact = s.denominator == CentroidDenominator::Exact;
    if (ui.checkbox("exact centroid denominator", &exact))
    {
        s.denominator = exact ? CentroidDenominator::Exact : CentroidDenominator::Paper;
        toggled = true;
    }
    bool smoothed = s.normal_source == NormalSource::Smoothed;
    if (ui.checkbox("smoothed normals", &smoothed))
    {
        s.normal_source = smoothed ? NormalSource::Smoothed : NormalSource::Initial;
        toggled = true;
    }
    toggled |= ui.checkbox("joint mode", &s.joint);
    if (s.joint)
        dragged |= weight_slider(ui, "gamma", s.gamma);
    if (s.normal_source == NormalSource::Smoothed)
    {
        // The normal smoothing's iterations from the noise found in the mesh, scaled by one
        // strength (docs/recipe.md, "iterations": "auto"); the run's note says what it found.
        bool from_noise = s.adaptive_smoothing.has_value();
        if (ui.checkbox("iterations from the noise", &from_noise))
        {
            s.adaptive_smoothing =
                from_noise ? std::optional<AdaptiveIterations>(AdaptiveIterations{}) : std::nullopt;
            toggled = true;
        }
        if (s.adaptive_smoothing)
        {
            float strength = float(s.adaptive_smoothing->strength);
            if (ImGui::SliderFloat("strength", &strength, 0.0f, 3.0f, "%.2f"))
            {
                // Hundredths, as shown: an exported recipe says 1.25, not 1.2500000476837158.
                s.adaptive_smoothing->strength =
                    std::round(std::clamp(Scalar(strength), Scalar(0), Scalar(3)) * 100) / 100;
                dragged = true;
            }
            ui.track("strength");
        }
        else
        {
            if (ImGui::SliderInt("normal iterations", &s.normal_smoothing_iterations, 0, 200))
            {
                s.normal_smoothing_iterations = std::clamp(s.normal_smoothing_iterations, 0, 200);
                dragged = true;
            }
            ui.track("normal iterations");
        }
    }
    if (s.normal_source == NormalSource::Smoothed || s.joint)
    {
        // Normals kept apart across creases (bilateral weights, docs/recipe.md).
        // Turned off then on again, the weights come back as they were (a preset's too).
        BilateralWeights& last_bilateral = ui.state.panels.bilateral;
        if (s.bilateral)
            last_bilateral = *s.bilateral;
        bool bilateral = s.bilateral.has_value();
        if (ui.checkbox("keep creases (bilateral)", &bilateral))
        {
            s.bilateral =
                bilateral ? std::optional<BilateralWeights>(last_bilateral) : std::nullopt;
            toggled = true;
        }
        if (s.bilateral)
        {
            float sigma_r = float(s.bilateral->sigma_r);
            if (ImGui::SliderFloat("crease sigma_r", &sigma_r, 0.05f, 1.0f, "%.2f"))
            {
                s.bilateral->sigma_r = std::clamp(Scalar(sigma_r), Scalar(0.05), Scalar(1));
                dragged = true;
            }
            ui.track("crease sigma_r");
            bool vertex = s.bilateral->neighbors == FaceNeighborhood::Vertex;
            if (ui.checkbox("faces sharing a vertex", &vertex))
            {
                s.bilateral->neighbors = vertex ? FaceNeighborhood::Vertex : FaceNeighborhood::Edge;
                toggled = true;
            }
        }
    }
    // The methods the editor runs, each an item of the combo that a script can click
    // ("method/Jacobi steps").
    constexpr std::pair<Method, const char*> methods[] = {
        {Method::Jacobi, "Jacobi steps"},
        {Method::Taubin, "Taubin lambda|mu"},
        {Method::Direct, "direct: the minimizer"},
        {Method::ConjugateGradient, "CG: the minimizer"},
        {Method::Implicit, "implicit (backward Euler)"}};
    const char* shown = methods[0].second;
    for (const auto& [m, name] : methods)
        if (m == s.method)
            shown = name;
    ImGui::SetNextItemWidth(170);
    if (ImGui::BeginCombo("method", shown))
    {
        for (const auto& [m, name] : methods)
        {
            if (ImGui::Selectable(name, m == s.method) && m != s.method)
            {
                s.method = m;
                toggled = true;
            }
            ui.track(std::string("method/") + name);
        }
        ImGui::EndCombo();
    }
    ui.track("method");
    if (s.method == Method::Implicit)
    {
        // The time of each step, logarithmic: 0.01 (a few Jacobi steps) to 100 (near the
        // minimizer where the sets hold the mesh).
        float time = float(s.time);
        if (ImGui::SliderFloat("time", &time, 0.01f, 100.0f, "%.3g", ImGuiSliderFlags_Logarithmic))
        {
            s.time = std::clamp(Scalar(time), Scalar(0.01), Scalar(100));
            dragged = true;
        }
        ui.track("time");
    }
    Bending& last_bending = ui.state.panels.bending; // turned off then on: as it was
    if (s.bending)
        last_bending = *s.bending;
    bool bending = s.bending.has_value();
    if (ui.checkbox("thin plate (a dome under pins)", &bending))
    {
        s.bending = bending ? std::optional<Bending>(last_bending) : std::nullopt;
        toggled = true;
    }
    if (s.bending)
    {
        dragged |= weight_slider(ui, "bending mu", s.bending->mu);
        float membrane = float(s.bending->membrane);
        if (ImGui::SliderFloat("membrane", &membrane, 0.0f, 1.0f, "%.3f"))
        {
            s.bending->membrane = std::clamp(Scalar(membrane), Scalar(0), Scalar(1));
            dragged = true;
        }
        ui.track("membrane");
    }
    toggled |= ui.checkbox("keep volume", &s.keep_volume);
    ImGui::SameLine();
    toggled |= ui.checkbox("no faces turned over", &s.prevent_flips);
    Falloff& last_falloff = ui.state.panels.falloff; // likewise
    if (s.falloff)
        last_falloff = *s.falloff;
    bool falloff = s.falloff.has_value();
    if (ui.checkbox("falloff from border and pins", &falloff))
    {
        s.falloff = falloff ? std::optional<Falloff>(last_falloff) : std::nullopt;
        toggled = true;
    }
    if (s.falloff)
    {
        float radius = float(s.falloff->radius);
        if (ImGui::SliderFloat("falloff radius (edges)", &radius, 0.0f, 100.0f, "%.1f",
                               ImGuiSliderFlags_Logarithmic))
        {
            s.falloff->radius = std::clamp(Scalar(radius), Scalar(0), Scalar(100));
            s.falloff->radius_in_edge_lengths = true;
            dragged = true;
        }
        ui.track("falloff radius");
        toggled |= ui.curve_combo("falloff curve", s.falloff->curve);
    }
    if ((toggled || dragged) && !(s == document.solver))
        // A slider held is one interaction: its values make one undo step.
        ui.give(SetSolverSettings{s}, dragged ? Interaction{"solver panel"} : Interaction{});

    if (ui.button(state.playing ? "Pause###play" : "Play###play", "Play"))
        ui.give(TogglePlay{});
    ImGui::SameLine();
    if (ui.button("Step"))
        ui.give(Step{});
    ImGui::SameLine();
    if (ui.button("Solve", "solver/Solve")) // ("Solve" is the menu's)
        ui.give(Solve{});
    ImGui::SameLine();
    if (ui.button("Reset"))
        ui.give(ResetShape{});
    ImGui::SameLine();
    if (ui.button("Apply"))
        ui.give(ApplyShape{});
    const SolverStatus& st = state.solver;
    // (A preparation under way shows over the view, preparation_toast: a line here would
    // come and go, moving what is below it under a pointer about to click.)
    if (st.cancelled && !st.preparing)
        ImGui::TextWrapped("preparation cancelled: Solve, Play or Step prepares again");
    if (state.playing && st.goal > 0)
        ImGui::Text("running: step %d of %d", st.played, st.goal);
    else if (state.playing && st.relative_gradient >= 0)
        ImGui::TextWrapped(
            "running: step %d, until the gradient falls to %.0e of the "
            "start's (now %.1e)",
            st.played, st.stop_tolerance, st.relative_gradient);
    else if (state.playing)
        ImGui::Text("running: step %d, until it converges", st.played);
    ImGui::TextWrapped("%d steps from the base%s", document.steps_from_base,
                       document.reproducible ? "" : " (recipe changed during the run)");
    if (!state.offscreen) // a time would make offscreen frames differ from run to run
    {
        ImGui::Text("last frame %.1f ms on the solver's thread", st.step_ms);
        if (st.factor_ms > 0 && st.analysis_kept)
            ImGui::TextWrapped(
                "prepared in %.0f ms: the analysis kept (a weight changed), "
                "factored %.0f ms",
                st.precompute_ms, st.factor_ms);
        else if (st.factor_ms > 0)
            ImGui::TextWrapped("prepared in %.0f ms: analysed %.0f ms, factored %.0f ms",
                               st.precompute_ms, st.analyse_ms, st.factor_ms);
    }
    // "off", then the heat map's terms in their order, each item named for the widget map.
    const std::span<const EnergyTerm> terms = heat_terms();
    ImGui::SetNextItemWidth(120);
    // (The label apart: a click at the widget's centre lands on the box, not the label.)
    if (ImGui::BeginCombo("##heat map", state.heat_map
                                            ? std::string(heat_term_name(*state.heat_map)).c_str()
                                            : "off"))
    {
        if (ImGui::Selectable("off", !state.heat_map) && state.heat_map)
            ui.give(SetHeatMap{std::nullopt});
        ui.track("heat map/off");
        for (const EnergyTerm t : terms)
        {
            const std::string name(heat_term_name(t));
            if (ImGui::Selectable(name.c_str(), state.heat_map == t) && state.heat_map != t)
                ui.give(SetHeatMap{t});
            ui.track("heat map/" + name);
        }
        ImGui::EndCombo();
    }
    ui.track("heat map");
    ImGui::SameLine();
    ImGui::TextUnformatted("heat map: energy share");
    ImGui::SetNextItemWidth(100);
    ImGui::SliderFloat("##sigma", &ui.state.noise_sigma, 0.0f, 1.0f, "sigma %.2f");
    ui.track("noise sigma");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    ImGui::InputInt("##seed", &ui.state.noise_seed, 0);
    ui.track("noise seed");
    ImGui::SameLine();
    if (ui.button("Add noise"))
        ui.give(
            AddNoise{state.noise_sigma, static_cast<std::uint64_t>(std::max(state.noise_seed, 0))});
    if (!st.error.empty())
    {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.35f, 1));
        ImGui::TextWrapped("%s", st.error.c_str());
        ImGui::PopStyleColor();
    }
    for (const std::string& note : ui.state.run_notes)
        ImGui::TextWrapped("note: %s", note.c_str());
    if (st.converged)
        ImGui::TextUnformatted("converged (tolerance)");
}

} // namespace meshfair::app
