// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// The set-editing commands of EditorSession::dispatch.
#include <algorithm>
#include <cmath>

#include "app/editor/command_executor.h"
#include "core/errors.h"

namespace meshfair::app {

// --- Constraint sets.
//! The selection as a set of `kind` takes it: vertex kinds take the selected vertices
//! (or the vertices of the selected faces), face kinds the selected faces (or the faces
//! whose vertices are all selected); a region keeps faces as faces.
void CommandExecutor::selected_elements(ConstraintKind kind, std::vector<Index>& vertices,
                                        std::vector<Index>& faces) const
{
    const bool faces_mode = st.tools.elements == ElementKind::Faces;
    if (kind == ConstraintKind::Region && faces_mode)
        faces = selected_indices(d.selected_faces);
    else if (takes_vertices(kind))
        vertices = selected_indices(faces_mode ? vertices_of_faces(d.mesh, d.selected_faces)
                                               : d.selected_vertices);
    else
        faces = selected_indices(faces_mode ? d.selected_faces
                                            : faces_of_vertices(d.mesh, d.selected_vertices));
}

bool CommandExecutor::operator()(const cmd::CreateSet& c) const
{
    ConstraintSet set;
    set.kind = c.kind;
    set.color = default_color(c.kind);
    selected_elements(c.kind, set.vertices, set.faces);
    if (set.vertices.empty() && set.faces.empty())
        return fail("nothing selected for a " + std::string(kind_name(c.kind)) + " set");
    std::string name = c.name;
    if (name.empty())
    {
        int k = 1;
        do
            name = std::string(kind_name(c.kind)) + " " + std::to_string(k++);
        while (s.set_named(name));
    }
    else if (s.set_named(name))
        return fail("there is already a set named '" + name + "'");
    set.name = std::move(name);
    const size_t selected = set.vertices.size() + set.faces.size();
    const size_t holes = set.kind == ConstraintKind::Region && c.close_holes
                             ? close_region_holes(set, d.mesh, d.topology)
                             : 0;
    const std::string elements = set.vertices.empty() ? " faces" : " vertices";
    if (holes > 0)
        say("set '" + set.name + "': " + std::to_string(selected) + elements + " selected and " +
            std::to_string(holes) +
            " enclosed vertices left out of the selection (holes closed): " +
            std::to_string(set.vertices.size() + set.faces.size()) + elements);
    else
        say("set '" + set.name + "': " + std::to_string(selected) + elements);
    d.sets.push_back(std::move(set));
    return true;
}

bool CommandExecutor::operator()(const cmd::DeleteSet& c) const
{
    const size_t k = set_index(c.set);
    d.sets.erase(d.sets.begin() + static_cast<std::ptrdiff_t>(k));
    say("deleted set '" + c.set + "'");
    return true;
}

bool CommandExecutor::operator()(const cmd::RenameSet& c) const
{
    const size_t k = set_index(c.set);
    if (c.name.empty())
        return fail("a set's name must not be empty");
    if (c.name != c.set && s.set_named(c.name))
        return fail("there is already a set named '" + c.name + "'");
    d.sets[k].name = c.name;
    return true;
}

bool CommandExecutor::operator()(const cmd::ShowSet& c) const
{
    d.sets[set_index(c.set)].visible = c.visible;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetColor& c) const
{
    d.sets[set_index(c.set)].color = c.color;
    return true;
}

bool CommandExecutor::operator()(const cmd::SelectSet& c) const
{
    const ConstraintSet& set = d.sets[set_index(c.set)];
    const bool faces = set.vertices.empty();
    SelectionMask& mask = faces ? d.selected_faces : d.selected_vertices;
    std::fill(mask.begin(), mask.end(), 0);
    apply_selection(mask, faces ? set.faces : set.vertices, SelectOp::Add);
    st.tools.elements = faces ? ElementKind::Faces : ElementKind::Vertices;
    return true;
}

bool CommandExecutor::operator()(const cmd::AddToSet& c) const
{
    ConstraintSet& set = d.sets[set_index(c.set)];
    // A region made of faces takes faces; the other kinds what they hold.
    const bool vertex_set =
        set.faces.empty() && (takes_vertices(set.kind) || !set.vertices.empty());
    std::vector<Index> vertices, faces;
    selected_elements(vertex_set ? ConstraintKind::Pin : ConstraintKind::Centroid, vertices, faces);
    std::vector<Index>& list = vertex_set ? set.vertices : set.faces;
    const std::vector<Index>& add = vertex_set ? vertices : faces;
    std::vector<Index> sorted_list = list;
    std::sort(sorted_list.begin(), sorted_list.end());
    size_t added = 0;
    for (const Index e : add)
        if (!std::binary_search(sorted_list.begin(), sorted_list.end(), e))
        {
            list.push_back(e);
            ++added;
            // The new elements of a moved pin set, or of a set with its own normals,
            // start where they are.
            if (!set.targets.empty())
            {
                const size_t k = 3 * static_cast<size_t>(e);
                set.targets.push_back(
                    {d.base_positions[k], d.base_positions[k + 1], d.base_positions[k + 2]});
            }
            if (!set.normals.empty())
                set.normals.push_back(set.normals.front());
            if (!set.weights.empty() && vertex_set)
                set.weights.push_back(1);
        }
    if (added == 0)
        return fail("nothing selected that is not in '" + c.set + "' already");
    say("added " + std::to_string(added) + (vertex_set ? " vertices" : " faces") + " to '" + c.set +
        "'");
    return true;
}

bool CommandExecutor::operator()(const cmd::RemoveFromSet& c) const
{
    ConstraintSet& set = d.sets[set_index(c.set)];
    const bool vertex_set = !set.vertices.empty();
    std::vector<Index> vertices, faces;
    selected_elements(vertex_set ? ConstraintKind::Pin : ConstraintKind::Centroid, vertices, faces);
    std::vector<Index> gone = vertex_set ? vertices : faces;
    std::sort(gone.begin(), gone.end());
    std::vector<Index>& list = vertex_set ? set.vertices : set.faces;
    size_t kept = 0, removed = 0;
    for (size_t k = 0; k < list.size(); ++k)
    {
        if (std::binary_search(gone.begin(), gone.end(), list[k]))
        {
            ++removed;
            continue;
        }
        // Targets and normals stay with their elements.
        if (!set.targets.empty())
            set.targets[kept] = set.targets[k];
        if (!set.normals.empty())
            set.normals[kept] = set.normals[k];
        if (!set.weights.empty() && vertex_set)
            set.weights[kept] = set.weights[k];
        list[kept++] = list[k];
    }
    if (removed == 0)
        return fail("nothing selected is in '" + c.set + "'");
    list.resize(kept);
    if (!set.targets.empty())
        set.targets.resize(kept);
    if (!set.normals.empty())
        set.normals.resize(kept);
    if (!set.weights.empty() && vertex_set)
        set.weights.resize(kept);
    say("removed " + std::to_string(removed) + (vertex_set ? " vertices" : " faces") + " from '" +
        c.set + "'" + (kept == 0 ? " (it is empty now: left out of the solve)" : ""));
    return true;
}

bool CommandExecutor::operator()(const cmd::CloseHoles& c) const
{
    ConstraintSet& set = d.sets[set_index(c.set)];
    if (set.kind != ConstraintKind::Region)
        return fail("only a region has holes to close");
    const size_t holes = close_region_holes(set, d.mesh, d.topology);
    if (holes == 0)
        return fail("region '" + c.set + "' encloses nothing it leaves out");
    say("region '" + c.set + "': the " + std::to_string(holes) +
        " enclosed vertices it left out now move");
    return true;
}

bool CommandExecutor::operator()(const cmd::EnableSet& c) const
{
    d.sets[set_index(c.set)].enabled = c.enabled;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetSetWeight& c) const
{
    ConstraintSet& set = d.sets[set_index(c.set)];
    if (!takes_weight(set.kind))
        return fail("a " + std::string(kind_name(set.kind)) + " set has no weight");
    if (!(c.mu >= 0) || !std::isfinite(c.mu))
        return fail("a set's weight must be a number >= 0");
    set.mu = c.mu;
    return true;
}

bool CommandExecutor::operator()(const cmd::SetNormalDirection& c) const
{
    ConstraintSet& set = d.sets[set_index(c.set)];
    if (set.faces.empty())
        return fail("set '" + c.set + "' has no faces");
    Vec3 v = c.direction;
    const Scalar length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(length > 0) || !std::isfinite(length))
        return fail("a normal direction must not be zero");
    for (Scalar& x : v)
        x /= length;
    set.normals.assign(set.faces.size(), v);
    return true;
}

bool CommandExecutor::operator()(const cmd::MovePins& c) const
{
    ConstraintSet& set = d.sets[set_index(c.set)];
    if (set.kind != ConstraintKind::Pin)
        return fail("set '" + c.set + "' is not a pin set");
    if (c.dome && *c.dome != d.solver)
    {
        d.solver = *c.dome;
        s.solver_.set_iterations_per_frame(d.solver.iterations_per_frame);
        say("dome: thin plate, direct method");
    }
    if (set.targets.empty())
        for (const Index v : set.vertices)
        {
            const size_t k = 3 * static_cast<size_t>(v);
            set.targets.push_back(
                {d.base_positions[k], d.base_positions[k + 1], d.base_positions[k + 2]});
        }
    for (Vec3& t : set.targets)
        for (size_t a = 0; a < 3; ++a)
            t[a] += c.offset[a];
    return true;
}

} // namespace meshfair::app
