// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/edit/command.h"
#include "app/editor/live_solver.h"
#include "app/render/camera.h"
#include "app/render/renderer.h"
#include "app/tools/selection_tool.h"

namespace meshfair::app {

//! What the interface shows of the history (the Edit menu, the side panel).
struct HistoryStatus
{
    std::size_t undo_count = 0, redo_count = 0;
    std::string undo_label, redo_label;
    std::size_t bytes = 0, limit = 0, dropped = 0;
};

//! \brief What the panels remember between frames of a session: the tool of the last frame
//! (the Paint panel opens when its tool is chosen), and the bilateral weights and the
//! falloff last set (turned off and on again, they come back as they were).
struct PanelMemory
{
    ToolKind tool = ToolKind::Navigate;
    BilateralWeights bilateral;
    Falloff falloff;
    Bending bending;
};

//! The interaction state the editor owns (the document holds the data).
struct EditorState
{
    ToolKind tool = ToolKind::Navigate;
    ToolSettings tools;
    ToolOverlay overlay; //!< what the active tool draws now, in framebuffer pixels
    //! \brief The handle a press of the M or D tool would grab at the cursor, as drawn
    //! (framebuffer pixels): a pin's point, or an arrow's base and tip. Highlighted, so that
    //! an artist sees what a press takes before pressing.
    std::vector<ScreenPoint> grab_hover;
    HistoryStatus history; //!< refreshed by the session before each frame of the interface
    std::size_t selected_vertices = 0, selected_faces = 0; //!< counts, refreshed likewise
    SolverStatus solver;                                   //!< refreshed likewise
    std::vector<EnergySample> energies; //!< the current run's curve, refreshed likewise
    std::vector<std::string> problems;  //!< why the sets cannot run, refreshed likewise
    std::vector<std::string> notes;     //!< how the sets' overlaps are resolved, likewise
    //! What the current run does besides the settings' letter (LiveSolver::notes), taken
    //! at each restart
    std::vector<std::string> run_notes;
    //! Each region set's enclosed elements it leaves out (region_holes), by set name.
    //! Each set's mean normal (set_mean_normal; +z for sets of other kinds), in the sets'
    //! order: computed when the sets change, or the shape while no run plays (a pass over
    //! the set's faces, not one per frame of a run).
    std::vector<Vec3> set_directions;
    std::vector<std::pair<std::string, std::size_t>> region_holes;
    bool playing = false;          //!< refreshed likewise
    bool energy_log_scale = false; //!< the energy plot's vertical axis
    //! The plot's energy: of the whole mesh, or (false) of what moves: the terms' parts
    //! with a free vertex (EnergySample::held left out) and the relative gradient.
    bool energy_whole_mesh = false;
    //! The preset applied last and the settings it left: the preset menu names it while
    //! the settings are still those (not after a slider moved, nor after Undo).
    std::optional<std::pair<std::string, SolverSettings>> preset_applied;
    bool show_energy = true; //!< the energy plot window
    //! The heat map shown: each vertex coloured by its share of a term (nullopt: none).
    std::optional<EnergyTerm> heat_map;
    //! When a crashed session of this mesh left recovery files: when they were saved.
    std::optional<std::string> recovery_saved_at;
    float noise_sigma = 0.3f; //!< the noise tool's sigma, in mean edge lengths
    int noise_seed = 1;
    DisplayOptions display;
    PanelMemory panels;
    OrbitStyle orbit = OrbitStyle::Turntable;
    bool show_help = false;
    bool show_side_panel = true;
    std::string renderer_name;       //!< GL_RENDERER, for the status bar
    double frame_ms = 0;             //!< the last frame's time (0 before the first)
    bool offscreen = false;          //!< a frame for a file, not a window
    std::vector<std::string> recent; //!< most recent first
    std::string message;             //!< the last status or error message
    bool message_is_error = false;   //!< the message reports a failure

    // Requests the session leaves for the interface and the window.
    std::optional<cmd::Dialog> dialog; //!< a dialog to open
    bool quit_prompt = false;          //!< ask whether to discard unsaved changes
    bool quit = false;                 //!< confirmed: the window closes
    //! A screenshot to write after the next frame is drawn (empty path: the default name).
    std::optional<std::string> screenshot;
};

} // namespace meshfair::app
