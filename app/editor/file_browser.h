// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/widget_rect.h"

namespace meshfair::app {

//! \brief A file dialog drawn with Dear ImGui (Debian ships no native dialog library):
//! a directory listing (folders first, then the mesh files MeshFair reads), a path bar,
//! and for saving a file name field. open() shows it; draw() every frame returns the chosen
//! path once, when the user confirms.
class FileBrowser
{
public:
    enum class Mode
    {
        Open,
        Save
    };

    //! What the browser lists and accepts.
    enum class Files
    {
        Meshes, //!< .obj, .off, .ply, .stl
        Recipes //!< .json
    };

    //! Shows the dialog under `title` (empty: "Open mesh" or "Save mesh as").
    void open(Mode mode, const std::filesystem::path& start, const std::string& file_name = {},
              Files files = Files::Meshes, std::string title = {});
    Files files() const { return files_; }
    bool is_open() const { return open_; }
    //! \brief Where each widget was drawn, by name ("dialog/name", "dialog/OK", "dialog/Cancel";
    //! "dialog/name#active" while the name field has the keys).
    std::optional<std::string> draw(WidgetMap* widgets = nullptr);
    const std::string& title() const { return title_; }

    //! The entries of `dir` shown to the user: folders (but not hidden ones), then files with
    //! a mesh extension (or .json for recipes), each group sorted by name.
    static std::vector<std::filesystem::directory_entry> listing(const std::filesystem::path& dir,
                                                                 Files files = Files::Meshes);

private:
    std::string title_;
    Mode mode_ = Mode::Open;
    Files files_ = Files::Meshes;
    bool open_ = false;
    bool just_opened_ = false;
    bool focus_name_ = false; // the name field is to take the keys
    std::filesystem::path directory_;
    std::filesystem::path listed_; // the directory `entries_` lists
    std::vector<std::filesystem::directory_entry> entries_;
    std::string file_name_;
    std::string error_;
};

} // namespace meshfair::app
