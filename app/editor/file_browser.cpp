// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/file_browser.h"

#include <algorithm>
#include <array>
#include <cstring>

#include <imgui.h>

namespace meshfair::app {

namespace fs = std::filesystem;

namespace {

bool is_listed(const fs::path& p, FileBrowser::Files files)
{
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (files == FileBrowser::Files::Recipes)
        return ext == ".json";
    return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}

} // namespace

std::vector<fs::directory_entry> FileBrowser::listing(const fs::path& dir, Files listed)
{
    std::vector<fs::directory_entry> folders, files;
    std::error_code ec;
    for (fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec))
    {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.')
            continue;
        std::error_code type_error;
        if (it->is_directory(type_error))
            folders.push_back(*it);
        else if (is_listed(it->path(), listed))
            files.push_back(*it);
    }
    const auto by_name = [](const fs::directory_entry& a, const fs::directory_entry& b) {
        return a.path().filename() < b.path().filename();
    };
    std::sort(folders.begin(), folders.end(), by_name);
    std::sort(files.begin(), files.end(), by_name);
    folders.insert(folders.end(), files.begin(), files.end());
    return folders;
}

void FileBrowser::open(Mode mode, const fs::path& start, const std::string& file_name, Files files,
                       std::string title)
{
    mode_ = mode;
    title_ = title.empty() ? (mode == Mode::Open ? "Open mesh" : "Save mesh as") : std::move(title);
    files_ = files;
    std::error_code ec;
    directory_ = fs::is_directory(start, ec) ? start : start.parent_path();
    if (directory_.empty())
        directory_ = fs::current_path(ec);
    directory_ = fs::absolute(directory_, ec);
    file_name_ = file_name;
    error_.clear();
    listed_.clear(); // read the folder afresh each time the dialog opens
    open_ = true;
    just_opened_ = true;
    focus_name_ = true;
}

std::optional<std::string> FileBrowser::draw(WidgetMap* widgets)
{
    if (!open_)
        return std::nullopt;
    // Where each widget was drawn, for scripts that click and type as a person does.
    const auto track = [&](const char* name) {
        if (widgets == nullptr || !ImGui::IsItemVisible())
            return;
        const ImGuiIO& io = ImGui::GetIO();
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        const double sx = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0;
        const double sy = io.DisplayFramebufferScale.y > 0 ? io.DisplayFramebufferScale.y : 1.0;
        (*widgets)[std::string("dialog/") + name] = {a.x * sx, a.y * sy, b.x * sx, b.y * sy};
    };
    const std::string title_id = title_ + "###file";
    const char* title = title_id.c_str();
    if (just_opened_)
    {
        ImGui::OpenPopup(title);
        just_opened_ = false;
    }
    std::optional<std::string> chosen;
    ImGui::SetNextWindowSize(ImVec2(620, 440), ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(title, &open_))
        return std::nullopt;
    if (ImGui::Button("Up") && directory_.has_parent_path())
        directory_ = directory_.parent_path();
    track("Up");
    ImGui::SameLine();
    ImGui::TextUnformatted(directory_.string().c_str());
    ImGui::BeginChild("entries", ImVec2(0, -ImGui::GetFrameHeightWithSpacing() * 2), true);
    // Listed once per directory, not once per frame.
    if (listed_ != directory_)
    {
        entries_ = listing(directory_, files_);
        listed_ = directory_;
    }
    for (const fs::directory_entry& entry : entries_)
    {
        const bool folder = entry.is_directory();
        const std::string label =
            (folder ? "[dir]  " : "       ") + entry.path().filename().string();
        const bool selected = !folder && entry.path().filename().string() == file_name_;
        if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick))
        {
            if (folder)
                directory_ = entry.path();
            else
            {
                file_name_ = entry.path().filename().string();
                if (ImGui::IsMouseDoubleClicked(0))
                    chosen = entry.path().string();
            }
        }
    }
    ImGui::EndChild();
    std::array<char, 512> name{};
    std::strncpy(name.data(), file_name_.c_str(), name.size() - 1);
    ImGui::SetNextItemWidth(-160);
    // The name field takes the keys as soon as the dialog shows (asked again until it has
    // them: a popup's first frame may be hidden), its text selected, so that typing at once
    // replaces it as in any file dialog.
    if (focus_name_ && !ImGui::IsAnyItemActive())
        ImGui::SetKeyboardFocusHere();
    const bool enter =
        ImGui::InputText("##name", name.data(), name.size(),
                         ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    if (ImGui::IsItemActive())
        focus_name_ = false;
    track("name");
    if (ImGui::IsItemActive())
        track("name#active");
    file_name_ = name.data();
    ImGui::SameLine();
    if ((ImGui::Button(mode_ == Mode::Open ? "Open" : "Save") || enter) && !file_name_.empty())
        chosen =
            (fs::path(file_name_).is_absolute() ? fs::path(file_name_) : directory_ / file_name_)
                .string();
    track("OK");
    ImGui::SameLine();
    if (ImGui::Button("Cancel"))
        open_ = false;
    track("Cancel");
    if (!error_.empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", error_.c_str());
    if (chosen)
    {
        if (mode_ == Mode::Save && !is_listed(*chosen, files_))
        {
            error_ = files_ == Files::Recipes ? "the name must end in .json"
                                              : "the name must end in .obj, .off, .ply or .stl";
            chosen.reset();
        }
        else
            open_ = false;
    }
    if (!open_)
        ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return chosen;
}

} // namespace meshfair::app
