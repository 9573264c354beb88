// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/persistence.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "app/editor/edit_state_json.h"
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

namespace {

// The sets with each one's elements in the order of their indices in the file (targets,
// normals and weights following), still in the document's numbering: a set made from a
// selection lists its elements ascending in the document's (locality) numbering, which the
// file's numbering scatters; in the file's order the lists written are runs wherever the
// file keeps neighbours together. meshfair-cli gives the same bits from either order (the
// tests that compare its output with the editor's shape run on exported recipes).
std::vector<ConstraintSet> in_file_order(std::vector<ConstraintSet> sets,
                                         const LocalityOrder& order)
{
    for (ConstraintSet& s : sets)
        s = ordered_by(std::move(s), order.vertex_order, order.face_order);
    return sets;
}

// The recipe of `sets` and `settings` in the file's numbering, each list in the file's order
// (the region's too: the union of the region sets, which build_recipe lists in the
// document's numbering).
Recipe file_recipe_of(const Document& d, const std::vector<ConstraintSet>& sets,
                      const SolverSettings& settings, int iterations)
{
    Recipe r = renumber_recipe(
        build_recipe(in_file_order(sets, d.order), settings, d.mesh, d.base_positions, iterations),
        d.order.vertex_order, d.order.face_order);
    if (r.region)
    {
        std::sort(r.region->vertices.begin(), r.region->vertices.end());
        std::sort(r.region->faces.begin(), r.region->faces.end());
    }
    return r;
}

} // namespace

Recipe file_recipe(const Document& d)
{
    return file_recipe_of(d, d.sets, d.solver, d.steps_from_base);
}

namespace {

// A set with its elements renumbered: vertex i becomes vertex_map[i], face f face_map[f]
// (targets, normals and weights follow their elements).
ConstraintSet renumbered(ConstraintSet set, std::span<const Index> vertex_map,
                         std::span<const Index> face_map)
{
    for (Index& v : set.vertices)
        v = vertex_map[static_cast<size_t>(v)];
    for (Index& f : set.faces)
        f = face_map[static_cast<size_t>(f)];
    return set;
}

// The "editor" object of an exported recipe: the sets as the artist made them, in the
// file's numbering, the settings and the up axis.
nlohmann::json editor_json(const Document& d)
{
    nlohmann::json sets = nlohmann::json::array();
    for (const ConstraintSet& s : in_file_order(d.sets, d.order))
        sets.push_back(set_json(renumbered(s, d.order.vertex_order, d.order.face_order)));
    return {{"up", std::string(up_axis_name(d.up_axis))},
            {"sets", std::move(sets)},
            {"solver", settings_json(d.solver)}};
}

// The sets of an "editor" object, checked against the mesh (in the file's numbering), in
// the document's numbering; with its settings and up axis. \throw JsonValueError
ImportedRecipe imported_editor(const CheckedJson& j, const Document& d)
{
    ImportedRecipe out;
    const Index nv = d.mesh.vertex_count(), nf = d.mesh.face_count();
    const CheckedJson sets = j["sets"];
    if (!sets.is_array())
        sets.fail("must be a list");
    for (const CheckedJson& s : sets.elements())
        out.sets.push_back(renumbered(set_of(s, nv, nf), d.order.vertex_index, d.order.face_index));
    out.settings = settings_of(j["solver"]);
    const CheckedJson up = j["up"];
    const std::optional<UpAxis> axis = up_axis_named(up.text());
    if (!axis)
        up.fail("must be an axis such as \"+z\"");
    out.up = *axis;
    out.editor = true;
    return out;
}

} // namespace

void export_recipe(const Document& document, const std::string& path)
{
    nlohmann::json j = recipe_to_json(file_recipe(document));
    j["editor"] = editor_json(document);
    io::write_file_atomically(path, j.dump(2) + "\n");
}

ImportedRecipe import_recipe(const Document& document, const std::string& path)
{
    const CheckedJson root = CheckedJson::parse(io::read_file(path), path); // (parsed once)
    const Recipe recipe = parse_recipe(root);
    check_recipe(recipe, document.mesh); // the file's indices named in messages
    const Recipe internal =
        renumber_recipe(recipe, document.order.vertex_index, document.order.face_index);
    ImportedRecipe from_sections = sets_from_recipe(internal, document.mesh);
    const std::optional<CheckedJson> saved = root.find("editor");
    if (!saved || !saved->has("sets"))
        return from_sections;
    // The editor's own sets, names, colours and maps as they were; taken when they still
    // make the recipe's sections (a file edited by hand since may not: its sections then).
    ImportedRecipe editor = imported_editor(*saved, document);
    editor.iterations = from_sections.iterations;
    editor.description = from_sections.description;
    // Compared as written: in the file's numbering and order.
    Recipe rebuilt;
    try
    {
        if (constraint_problems(editor.sets, editor.settings).empty())
            rebuilt = file_recipe_of(document, editor.sets, editor.settings, recipe.iterations);
    }
    catch (const std::exception&)
    {
        rebuilt = Recipe{};
    }
    rebuilt.description = recipe.description;
    if (recipe_to_json(rebuilt) == recipe_to_json(recipe))
        return editor;
    from_sections.note =
        "its sets were made from the recipe's sections: the editor's own (names, colours, "
        "maps) no longer make them (the file was edited since it was exported)";
    return from_sections;
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
