// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <map>
#include <string>

#include "app/editor/editor_ui.h"

namespace meshfair::app {

//! \brief What every panel of the interface reads and writes: the document and state it
//! shows, the commands it gives, and where its widgets were drawn (for scripts).
struct PanelContext
{
    const Document& document;
    EditorState& state;
    const Camera& camera;
    UiOutput& out;
    WidgetMap& widgets;

    void give(Command command, Interaction from = {}) const
    {
        out.commands.push_back({std::move(command), std::move(from)});
    }
    //! Records where the last widget was drawn under `label`.
    void track(const std::string& label) const;
    //! ImGui::Button, tracked under `label` (or `key`).
    bool button(const char* label, const std::string& key = {}) const;
    bool small_button(const char* label, const std::string& key = {}) const;
    bool checkbox(const char* label, bool* value, const std::string& key = {}) const;
    bool radio(const char* label, bool active, const std::string& key = {}) const;
    //! \brief A menu of the falloff curves under `label`, each item tracked as
    //! "label/name" (the brush's curve, the falloff's); true when one was chosen.
    bool curve_combo(const char* label, FalloffCurve& curve) const;
};

// The sections of the interface, one file each in app/editor/panels/.
void menu_bar(const PanelContext& ui);
//! \brief The handle a press of M or D would grab at the cursor, highlighted, and where it
//! is tracked as "grab/base" and "grab/tip".
void grab_highlight(const PanelContext& ui);
void select_panel(const PanelContext& ui);
//! The rename field's text and the set being renamed live in the EditorUi.
void sets_panel(const PanelContext& ui, std::string& rename_buffer, std::string& renaming);
void solver_panel(const PanelContext& ui);
//! The Paint tool's mode, strength, curve, steps and the set it paints.
void paint_panel(const PanelContext& ui);
void energy_window(const PanelContext& ui);
void legend_panel(const PanelContext& ui);
void mesh_panel(const PanelContext& ui);
void display_panel(const PanelContext& ui);
void camera_panel(const PanelContext& ui);
void status_bar(const PanelContext& ui);
//! \brief While the solver prepares (a long factorization): its phase, a bar of its
//! expected length and Cancel, over the top of the view, where the artist looks.
void preparation_toast(const PanelContext& ui);
void help_overlay(const PanelContext& ui);
//! \brief The newest error (a refused command, preset or run: why), wrapped in a box over
//! the top of the view where the artist looks, its first lines and the whole text a click
//! away, until closed (`dismissed` keeps the message closed) or another message comes.
void error_toast(const PanelContext& ui, std::string& dismissed, bool& expanded);
//! The active tool's ring, rectangle or lasso line, over the view.
void tool_overlay(const EditorState& state);

//! The side panel's width, in window units.
inline constexpr float kSidePanelWidth = 340;
//! The status bar's height at the window's bottom, in window units (the side panel, the
//! energy plot's strip and the view end above it).
float status_bar_height();
//! The energy plot's strip under the view, in window units (its contents fit).
inline constexpr float kEnergyPanelHeight = 224;

//! \brief What the solver's preparation is doing, for the box over the view:
//! "ordering 1,078,592 unknowns", "factoring (22.1 Gflop)", with "3 s of about 8" when
//! `with_times` (not offscreen: frames must not depend on the clock).
std::string preparation_text(const SolverStatus& status, bool with_times);
const char* kind_label(ConstraintKind kind);

} // namespace meshfair::app
