// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/persistence.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "core/errors.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"

namespace meshfair::app {

std::vector<std::string> save_document(Document& document, const std::string& path)
{
    std::vector<std::string> notes;
    // The file's numbering, kept; the attributes are in it too.
    io::write_mesh(file_order_mesh(document), path, {}, &document.attributes, &notes);
    document.path = path;
    document.modified = false;
    return notes;
}

Recipe current_recipe(const Document& d)
{
    return build_recipe(d.sets, d.solver, d.mesh, d.base_positions, d.steps_from_base);
}

Recipe file_recipe(const Document& d)
{
    return renumber_recipe(current_recipe(d), d.order.vertex_order, d.order.face_order);
}

void export_recipe(const Document& document, const std::string& path)
{
    io::write_file_atomically(path, recipe_to_json(file_recipe(document)).dump(2) + "\n");
}

ImportedRecipe import_recipe(const Document& document, const std::string& path)
{
    const Recipe recipe = read_recipe(path);
    check_recipe(recipe, document.mesh); // the file's indices named in messages
    const Recipe internal =
        renumber_recipe(recipe, document.order.vertex_index, document.order.face_index);
    return sets_from_recipe(internal, document.mesh);
}

std::vector<std::string> preset_names()
{
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(MESHFAIR_RECIPES_DIR, ec))
        if (entry.path().extension() == ".json")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string preset_description(const std::string& preset)
{
    try
    {
        return read_recipe(preset_path(preset)).description;
    }
    catch (const std::exception&)
    {
        return {}; // a preset that does not read is refused, with the reason, when chosen
    }
}

std::string preset_path(const std::string& preset)
{
    if (preset.find('/') != std::string::npos ||
        (preset.size() > 5 && preset.substr(preset.size() - 5) == ".json"))
        return preset;
    const std::vector<std::string> names = preset_names();
    if (std::find(names.begin(), names.end(), preset) == names.end())
    {
        std::string list;
        for (const std::string& n : names)
            list += (list.empty() ? "" : ", ") + n;
        throw InvalidInputError("no preset named '" + preset + "' (the presets: " + list + ")");
    }
    return (std::filesystem::path(MESHFAIR_RECIPES_DIR) / (preset + ".json")).string();
}

namespace {

double steady_seconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

std::string Autosaver::autosave(const Document& document, double interval_s)
{
    const std::uint64_t edits = document.versions.total();
    if (root_.empty() || (autosaved_ && *autosaved_ == edits))
        return {};
    if (!autosaved_ && edits == 0)
        return {}; // nothing edited since the document was opened
    const double now = steady_seconds();
    if (interval_s > 0 && now - last_ < interval_s)
        return {};
    last_ = now;
    try
    {
        write_recovery(document, root_);
        if (owns_ && path_ != document.path)
            remove_recovery(path_, root_); // saved under another name since
        owns_ = true;
        path_ = document.path;
        autosaved_ = edits;
        return {};
    }
    catch (const std::exception& e)
    {
        return std::string("autosave failed: ") + e.what();
    }
}

std::optional<RecoveryInfo> Autosaver::offer(const Document& document) const
{
    return find_recovery(document.path, root_);
}

RecoveryInfo Autosaver::recover(Document& document)
{
    const std::optional<RecoveryInfo> info = offer(document);
    if (!info)
        throw InvalidInputError("no recovery files for " + document.path);
    restore_recovery(*info, document);
    owns_ = true;
    path_ = document.path;
    return *info;
}

void Autosaver::discard(const Document& document)
{
    remove_recovery(document.path, root_);
}

void Autosaver::end_session()
{
    if (owns_)
        remove_recovery(path_, root_);
}

} // namespace meshfair::app
