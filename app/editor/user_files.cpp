// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/user_files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/io/io.h"

namespace meshfair::app {

std::string absolute_path(const std::string& path)
{
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    return ec ? path : absolute.lexically_normal().string();
}

void remember_recent(std::vector<std::string>& recent, const std::string& path)
{
    const std::string p = absolute_path(path);
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

namespace {

// A settings file of lines, written atomically with its folder; false when it cannot be:
// settings are a convenience, never a reason to fail.
bool write_lines(const std::string& file, const std::vector<std::string>& lines)
{
    if (file.empty())
        return false;
    std::string text;
    for (const std::string& line : lines)
        if (line.find('\n') == std::string::npos)
            text += line + "\n";
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

} // namespace

bool save_recent(const std::string& file, const std::vector<std::string>& recent)
{
    return write_lines(file, recent);
}

std::string up_axes_path()
{
    const std::string recent = recent_files_path();
    if (recent.empty())
        return {};
    return (std::filesystem::path(recent).parent_path() / "up-axes.txt").string();
}

std::optional<UpAxis> load_up_axis(const std::string& file, const std::string& mesh_path)
{
    if (file.empty())
        return std::nullopt;
    const std::string key = absolute_path(mesh_path);
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
    {
        const auto tab = line.find('\t');
        if (tab != std::string::npos && line.substr(tab + 1) == key)
            return up_axis_named(line.substr(0, tab)); // ("y" and "z" of older files too)
    }
    return std::nullopt;
}

bool save_up_axis(const std::string& file, const std::string& mesh_path, UpAxis axis)
{
    if (file.empty())
        return false;
    const std::string key = absolute_path(mesh_path);
    std::vector<std::string> lines{std::string(up_axis_name(axis)) + "\t" + key};
    std::ifstream in(file);
    for (std::string line; std::getline(in, line) && lines.size() < 1000;)
    {
        const auto tab = line.find('\t');
        if (tab != std::string::npos && line.substr(tab + 1) != key)
            lines.push_back(line);
    }
    return write_lines(file, lines);
}

} // namespace meshfair::app
