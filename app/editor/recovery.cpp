// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/recovery.h"
#include "app/editor/user_files.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>

#include "app/editor/edit_state_json.h"
#include "core/errors.h"
#include "core/io/checked_json.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"

namespace meshfair::app {

namespace fs = std::filesystem;

namespace {

using Json = nlohmann::json;

// One folder per mesh path.
fs::path folder(const std::string& mesh_path, const std::string& root)
{
    char id[32];
    std::snprintf(id, sizeof id, "%016zx", std::hash<std::string>{}(absolute_path(mesh_path)));
    return fs::path(root) / id;
}

template <class T>
std::string bytes_of(const std::vector<T>& v)
{
    return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <class T>
std::vector<T> vector_of(const std::string& bytes, size_t count, const fs::path& file)
{
    if (bytes.size() != count * sizeof(T))
        throw InvalidInputError("'" + file.string() + "': " + std::to_string(bytes.size()) +
                                " bytes, expected " + std::to_string(count * sizeof(T)) +
                                " (not this mesh's recovery file)");
    std::vector<T> v(count);
    if (count > 0)
        std::memcpy(v.data(), bytes.data(), bytes.size());
    return v;
}

// Coordinates: a file's bytes that are not finite numbers are damage, not a shape.
std::vector<Scalar> coordinates_of(const std::string& bytes, size_t count, const fs::path& file)
{
    std::vector<Scalar> v = vector_of<Scalar>(bytes, count, file);
    for (size_t k = 0; k < v.size(); ++k)
        if (!std::isfinite(v[k]))
            throw InvalidInputError("'" + file.string() + "': vertex " + std::to_string(k / 3) +
                                    " has a coordinate that is not a finite number");
    return v;
}

bool running(long pid)
{
    return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}

} // namespace

std::string recovery_root()
{
    const char* state = std::getenv("XDG_STATE_HOME");
    if (state != nullptr && state[0] == '/')
        return std::string(state) + "/meshfair/recovery";
    const char* home = std::getenv("HOME");
    if (home != nullptr && home[0] == '/')
        return std::string(home) + "/.local/state/meshfair/recovery";
    return {};
}

void write_recovery(const Document& d, const std::string& root)
{
    const fs::path dir = folder(d.path, root);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        throw WriteError("'" + dir.string() +
                         "': cannot create the recovery folder: " + ec.message());
    io::write_file_atomically((dir / "positions.bin").string(), bytes_of(d.mesh.positions));
    io::write_file_atomically((dir / "base.bin").string(), bytes_of(d.base_positions));
    io::write_file_atomically((dir / "selection.bin").string(),
                              bytes_of(d.selected_vertices) + bytes_of(d.selected_faces));
    Json sets = Json::array();
    for (const ConstraintSet& s : d.sets)
        sets.push_back(set_json(s));
    const std::time_t now = std::time(nullptr);
    char when[32];
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
    const Json state = {{"mesh", absolute_path(d.path)},
                        {"pid", static_cast<long>(::getpid())},
                        {"saved_at", when},
                        {"vertices", d.mesh.vertex_count()},
                        {"faces", d.mesh.face_count()},
                        {"steps_from_base", d.steps_from_base},
                        {"reproducible", d.reproducible},
                        {"sets", sets},
                        {"up", std::string(up_axis_name(d.up_axis))},
                        {"solver", settings_json(d.solver)}};
    io::write_file_atomically((dir / "state.json").string(), state.dump(1));
}

std::optional<RecoveryInfo> find_recovery(const std::string& mesh_path, const std::string& root)
{
    if (root.empty())
        return std::nullopt;
    const fs::path dir = folder(mesh_path, root);
    std::error_code ec;
    if (!fs::exists(dir / "state.json", ec))
        return std::nullopt;
    try
    {
        const CheckedJson j =
            CheckedJson::parse(io::read_file((dir / "state.json").string()), "state.json");
        RecoveryInfo info{dir.string(), j["mesh"].text(), static_cast<long>(j["pid"].integer()),
                          j["saved_at"].text()};
        if (info.mesh_path != absolute_path(mesh_path) || running(info.pid))
            return std::nullopt; // another mesh's, or a session still open
        return info;
    }
    catch (const std::exception&)
    {
        return std::nullopt; // unreadable or damaged: nothing to offer
    }
}

void restore_recovery(const RecoveryInfo& info, Document& d)
{
    const fs::path dir(info.dir);
    RecoveryFiles files;
    files.dir = info.dir;
    files.state = io::read_file((dir / "state.json").string());
    files.positions = io::read_file((dir / "positions.bin").string());
    files.base = io::read_file((dir / "base.bin").string());
    files.selection = io::read_file((dir / "selection.bin").string());
    restore_recovery_files(files, d);
}

void restore_recovery_files(const RecoveryFiles& files, Document& d)
{
    const fs::path dir(files.dir);
    const fs::path state_file = dir / "state.json";
    Document next = d;
    try
    {
        const CheckedJson j = CheckedJson::parse(files.state, state_file.string());
        const Index nv = d.mesh.vertex_count(), nf = d.mesh.face_count();
        const std::int64_t saved_nv = count_at(j, "vertices", 0),
                           saved_nf = count_at(j, "faces", 0);
        if (saved_nv != nv || saved_nf != nf)
            throw InvalidInputError("'" + state_file.string() + "': saved for a mesh of " +
                                    std::to_string(saved_nv) + " vertices and " +
                                    std::to_string(saved_nf) + " faces, this one has " +
                                    std::to_string(nv) + " and " + std::to_string(nf));
        const size_t n3 = 3 * static_cast<size_t>(nv);
        next.mesh.positions = coordinates_of(files.positions, n3, dir / "positions.bin");
        next.base_positions = coordinates_of(files.base, n3, dir / "base.bin");
        std::vector<char> selection =
            vector_of<char>(files.selection, static_cast<size_t>(nv) + static_cast<size_t>(nf),
                            dir / "selection.bin");
        for (size_t k = 0; k < selection.size(); ++k)
            if (selection[k] != 0 && selection[k] != 1)
                throw InvalidInputError("'" + (dir / "selection.bin").string() + "': byte " +
                                        std::to_string(k) + " is " +
                                        std::to_string(static_cast<unsigned char>(selection[k])) +
                                        ", not a selection flag (0 or 1)");
        next.selected_vertices.assign(selection.begin(), selection.begin() + nv);
        next.selected_faces.assign(selection.begin() + nv, selection.end());
        next.sets.clear();
        const CheckedJson sets = j["sets"];
        if (!sets.is_array())
            sets.fail("must be a list");
        for (const CheckedJson& s : sets.elements())
            next.sets.push_back(set_of(s, nv, nf));
        next.solver = settings_of(j["solver"]);
        next.steps_from_base = count_at(j, "steps_from_base", 0);
        if (const auto up = j.find("up")) // (older files have none: the session's stays)
        {
            const std::optional<UpAxis> axis = up_axis_named(up->text());
            if (!axis)
                up->fail("must be an axis such as \"+z\"");
            next.up_axis = *axis;
        }
        next.reproducible = j["reproducible"].boolean();
    }
    // What no editor writes, said as "damaged": "(sets[1].mu must be a number >= 0)".
    catch (const JsonValueError& e)
    {
        throw InvalidInputError("'" + state_file.string() + "': damaged recovery file (" +
                                e.path() + " " + e.why() + ")");
    }
    catch (const JsonSyntaxError& e)
    {
        throw InvalidInputError("'" + state_file.string() + "': damaged recovery file (" +
                                "not valid JSON at line " + std::to_string(e.line()) + ", column " +
                                std::to_string(e.column()) + ": " + e.why() + ")");
    }
    next.modified = true;
    d = std::move(next);
}

void remove_recovery(const std::string& mesh_path, const std::string& root)
{
    if (root.empty())
        return;
    std::error_code ec;
    fs::remove_all(folder(mesh_path, root), ec);
}

} // namespace meshfair::app
