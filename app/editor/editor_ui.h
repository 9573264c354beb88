// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "app/editor/document.h"
#include "app/editor/file_browser.h"
#include "app/editor/live_solver.h"
#include "app/render/camera.h"
#include "app/render/renderer.h"
#include "app/tools/selection_commands.h"
#include "app/tools/selection_tool.h"

namespace meshfair::app {

class InterfaceContext;

//! What the interface shows of the history (the Edit menu, the side panel).
struct HistoryStatus
{
    std::size_t undo_count = 0, redo_count = 0;
    std::string undo_label, redo_label;
    std::size_t bytes = 0, limit = 0, dropped = 0;
};

//! The interaction state the editor owns (the document holds the data).
struct EditorState
{
    ToolKind tool = ToolKind::Navigate;
    ToolSettings tools;
    ToolOverlay overlay;   //!< what the active tool draws now, in framebuffer pixels
    HistoryStatus history; //!< refreshed by the session before each frame of the interface
    std::size_t selected_vertices = 0, selected_faces = 0; //!< counts, refreshed likewise
    SolverStatus solver;                                   //!< refreshed likewise
    std::vector<EnergySample> energies; //!< the current run's curve, refreshed likewise
    std::vector<std::string> problems;  //!< why the sets cannot run, refreshed likewise
    bool playing = false;               //!< refreshed likewise
    bool energy_log_scale = false;      //!< the energy plot's vertical axis
    bool show_energy = true;            //!< the energy plot window
    //! The heat map shown: each vertex coloured by its share of a term (nullopt: none).
    std::optional<EnergyTerm> heat_map;
    //! When a crashed session of this mesh left recovery files: when they were saved.
    std::optional<std::string> recovery_saved_at;
    float noise_sigma = 0.3f; //!< the noise tool's sigma, in mean edge lengths
    int noise_seed = 1;
    DisplayOptions display;
    OrbitStyle orbit = OrbitStyle::Turntable;
    bool show_help = false;
    bool show_side_panel = true;
    std::string renderer_name;       //!< GL_RENDERER, for the status bar
    double frame_ms = 0;             //!< the last frame's time (0 before the first)
    bool offscreen = false;          //!< a frame for a file, not a window
    std::vector<std::string> recent; //!< most recent first
    std::string message;             //!< the last status or error message
};

//! What the user asked for in a frame of the interface; the window carries it out.
struct UiRequests
{
    std::optional<std::string> open_path;
    std::optional<std::string> save_path;
    std::optional<StandardView> view;
    bool frame_all = false;
    bool frame_selection = false;
    bool toggle_projection = false;
    bool screenshot = false;
    std::optional<ToolKind> tool;
    std::optional<ElementKind> elements;
    std::optional<SelectionCommand> command;
    bool undo = false;
    bool redo = false;
    std::optional<ConstraintKind> create_set;
    //! An edit of set `index` from the sets panel.
    struct SetEdit
    {
        enum class What
        {
            Delete,
            Rename,
            Show,
            Color,
            Select,
            Direction
        } what = What::Select;
        size_t index = 0;
        std::string name;
        bool visible = true;
        std::array<float, 3> color{1, 1, 1};
        Vec3 direction{0, 0, 1};
    };
    std::optional<SetEdit> set_edit;
    std::optional<SolverSettings> solver; //!< new settings from the solver panel
    bool solver_merge = true;             //!< part of a slider's series of changes
    bool seal_history = false;            //!< a widget was let go: its series of edits ends
    bool play = false, pause = false, step = false, reset_shape = false, apply_shape = false;
    std::optional<std::string> export_recipe_path, import_recipe_path;
    std::optional<std::pair<Scalar, std::uint64_t>> noise; //!< sigma (mean edges), seed
    std::optional<std::optional<EnergyTerm>> heat_map;     //!< a new heat map (or none)
    bool recover = false, discard_recovery = false;
    bool quit = false; //!< confirmed: no unsaved changes, or the user discarded them
};

//! One mouse or key binding, as the help overlay and docs/editor.md list it.
struct KeyBinding
{
    const char* input;
    const char* action;
};
std::span<const KeyBinding> key_bindings();

//! \brief The editor's Dear ImGui interface: menu bar, side panel, status bar, help
//! overlay, file browser and the unsaved-changes prompt. Pure ImGui: called between
//! ImGui::NewFrame and ImGui::Render by the window, or by draw_offscreen.
class EditorUi
{
public:
    UiRequests build(const Document& document, EditorState& state, const Camera& camera);
    //! Asks whether to discard unsaved changes before quitting (a window close, Ctrl+Q).
    void ask_to_quit(const Document& document, UiRequests& requests);
    void open_file_dialog(const Document& document);
    void save_file_dialog(const Document& document);
    void export_recipe_dialog(const Document& document);
    void import_recipe_dialog(const Document& document);

    //! \brief Lays out the interface for a `width` x `height` frame without a window (the
    //! offscreen screenshot's --ui): afterwards view_rect is known and layer.draw() draws
    //! the panels over the scene.
    void prepare_offscreen(InterfaceContext& layer, const Document& document, EditorState& state,
                           const Camera& camera, int width, int height);

    //! \brief The part of a `width` x `height` framebuffer the 3D view gets: all of it but
    //! the menu bar, the status bar and the side panel when shown.
    //! \pre a frame of the interface was laid out (the bars' heights come from its font).
    static ViewRect view_rect(int width, int height, const EditorState& state);

private:
    FileBrowser browser_;
    FileBrowser::Mode browser_mode_ = FileBrowser::Mode::Open;
    char rename_buffer_[128] = {};
    bool was_editing_ = false; // a widget was active in the last frame
    size_t renaming_ = 0;
    bool quit_prompt_ = false;
};

//! Adds `path` (made absolute) in front of the recent files (once, at most 10 kept).
void remember_recent(std::vector<std::string>& recent, const std::string& path);

//! \brief Where the recent files are kept between runs:
//! $XDG_CONFIG_HOME/meshfair/recent.txt, else ~/.config/meshfair/recent.txt; empty when
//! neither variable is set.
std::string recent_files_path();
//! The recent files listed in `file`, one per line (none when it cannot be read).
std::vector<std::string> load_recent(const std::string& file);
//! \brief Writes the list atomically, creating the folder; false (and nothing changed)
//! when it cannot: the recent list is a convenience, never a reason to fail.
bool save_recent(const std::string& file, const std::vector<std::string>& recent);

} // namespace meshfair::app
