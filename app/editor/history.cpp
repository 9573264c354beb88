// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/history.h"

#include <utility>

namespace meshfair::app {

namespace {

template <class T>
void drop_if_same(std::optional<T>& before, const T& now)
{
    if (before && *before == now)
        before.reset();
}

template <class T>
unsigned swap_part(std::optional<T>& stored, T& current, unsigned part)
{
    if (!stored)
        return 0;
    std::swap(*stored, current);
    return part;
}

std::size_t sets_bytes(const std::vector<ConstraintSet>& sets)
{
    std::size_t n = 0;
    for (const ConstraintSet& s : sets)
        n += sizeof(s) + s.name.size() + sizeof(Index) * (s.vertices.size() + s.faces.size()) +
             sizeof(Vec3) * (s.targets.size() + s.normals.size()) +
             sizeof(Scalar) * s.weights.size();
    return n;
}

} // namespace

EditState capture(const Document& d, unsigned parts)
{
    EditState s;
    if (parts & kSelection)
    {
        s.selected_vertices = d.selected_vertices;
        s.selected_faces = d.selected_faces;
    }
    if (parts & kSets)
        s.sets = d.sets;
    if (parts & kSettings)
        s.solver = d.solver;
    if (parts & kPositions)
    {
        s.positions = d.mesh.positions;
        s.steps_from_base = d.steps_from_base;
        s.reproducible = d.reproducible;
        s.shape_recipe = d.shape_recipe;
    }
    if (parts & kBasePositions)
        s.base_positions = d.base_positions;
    return s;
}

std::size_t History::bytes_of(const EditState& s)
{
    std::size_t n = 0;
    if (s.selected_vertices)
        n += s.selected_vertices->size();
    if (s.selected_faces)
        n += s.selected_faces->size();
    if (s.sets)
        n += sets_bytes(*s.sets);
    if (s.solver)
        n += sizeof(SolverSettings);
    if (s.positions)
        n += sizeof(Scalar) * s.positions->size();
    if (s.base_positions)
        n += sizeof(Scalar) * s.base_positions->size();
    return n;
}

unsigned History::swap_with(EditState& s, Document& d)
{
    return swap_part(s.selected_vertices, d.selected_vertices, kSelection) |
           swap_part(s.selected_faces, d.selected_faces, kSelection) |
           swap_part(s.sets, d.sets, kSets) | swap_part(s.solver, d.solver, kSettings) |
           swap_part(s.positions, d.mesh.positions, kPositions) |
           swap_part(s.steps_from_base, d.steps_from_base, kPositions) |
           swap_part(s.reproducible, d.reproducible, kPositions) |
           swap_part(s.shape_recipe, d.shape_recipe, kPositions) |
           swap_part(s.base_positions, d.base_positions, kBasePositions);
}

bool History::record(std::string label, EditState before, const Document& now, bool merge)
{
    drop_if_same(before.selected_vertices, now.selected_vertices);
    drop_if_same(before.selected_faces, now.selected_faces);
    drop_if_same(before.sets, now.sets);
    drop_if_same(before.solver, now.solver);
    if (before.positions && *before.positions == now.mesh.positions &&
        before.steps_from_base == now.steps_from_base && before.reproducible == now.reproducible &&
        before.shape_recipe == now.shape_recipe)
    {
        before.positions.reset();
        before.steps_from_base.reset();
        before.reproducible.reset();
        before.shape_recipe.reset();
    }
    drop_if_same(before.base_positions, now.base_positions);
    const std::size_t bytes = bytes_of(before);
    if (!before.selected_vertices && !before.selected_faces && !before.sets && !before.solver &&
        !before.positions && !before.base_positions)
        return false;
    for (const Step& s : redo_)
        bytes_ -= s.bytes;
    const bool was_redoable = !redo_.empty();
    redo_.clear();
    if (merge && !sealed_ && !was_redoable && !undo_.empty() && undo_.back().label == label)
    {
        // The newest step already holds the state before the first change of the series;
        // it must hold every part this change touched (else keep this one's).
        EditState& kept = undo_.back().state;
        const auto covers = [](const auto& a, const auto& b) { return a.has_value() || !b; };
        if (covers(kept.selected_vertices, before.selected_vertices) &&
            covers(kept.selected_faces, before.selected_faces) && covers(kept.sets, before.sets) &&
            covers(kept.solver, before.solver) && covers(kept.positions, before.positions) &&
            covers(kept.base_positions, before.base_positions))
            return true;
    }
    undo_.push_back({std::move(label), std::move(before), bytes});
    sealed_ = !merge;
    bytes_ += bytes;
    enforce_limit();
    return true;
}

unsigned History::undo(Document& document)
{
    if (undo_.empty())
        return 0;
    Step step = std::move(undo_.back());
    undo_.pop_back();
    const unsigned parts = swap_with(step.state, document);
    redo_.push_back(std::move(step));
    return parts;
}

unsigned History::redo(Document& document)
{
    if (redo_.empty())
        return 0;
    Step step = std::move(redo_.back());
    redo_.pop_back();
    const unsigned parts = swap_with(step.state, document);
    undo_.push_back(std::move(step));
    return parts;
}

void History::set_limit(std::size_t byte_limit)
{
    limit_ = byte_limit;
    enforce_limit();
}

void History::enforce_limit()
{
    while (bytes_ > limit_ && undo_.size() > 1)
    {
        bytes_ -= undo_.front().bytes;
        undo_.pop_front();
        ++dropped_;
    }
    // Then the steps farthest down the redo list.
    while (bytes_ > limit_ && undo_.size() + redo_.size() > 1 && !redo_.empty())
    {
        bytes_ -= redo_.front().bytes;
        redo_.pop_front();
        ++dropped_;
    }
}

void History::clear()
{
    undo_.clear();
    redo_.clear();
    bytes_ = 0;
}

} // namespace meshfair::app

namespace meshfair::app {

void DocumentVersions::bump(unsigned parts)
{
    selection += (parts & kSelection) ? 1 : 0;
    sets += (parts & kSets) ? 1 : 0;
    settings += (parts & kSettings) ? 1 : 0;
    positions += (parts & kPositions) ? 1 : 0;
    base += (parts & kBasePositions) ? 1 : 0;
    set_members += (parts & kSetMembers) ? 1 : 0;
}

} // namespace meshfair::app
