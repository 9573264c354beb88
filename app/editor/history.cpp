// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/history.h"

#include <utility>

namespace meshfair::app {

EditState capture(const Document& d)
{
    return {d.selected_vertices, d.selected_faces};
}

std::size_t History::bytes_of(const EditState& s)
{
    std::size_t n = 0;
    if (s.selected_vertices)
        n += s.selected_vertices->size();
    if (s.selected_faces)
        n += s.selected_faces->size();
    return n;
}

void History::swap_with(EditState& s, Document& d)
{
    if (s.selected_vertices)
        std::swap(*s.selected_vertices, d.selected_vertices);
    if (s.selected_faces)
        std::swap(*s.selected_faces, d.selected_faces);
}

bool History::record(std::string label, EditState before, const Document& now)
{
    if (before.selected_vertices && *before.selected_vertices == now.selected_vertices)
        before.selected_vertices.reset();
    if (before.selected_faces && *before.selected_faces == now.selected_faces)
        before.selected_faces.reset();
    const std::size_t bytes = bytes_of(before);
    if (!before.selected_vertices && !before.selected_faces)
        return false;
    for (const Step& s : redo_)
        bytes_ -= s.bytes;
    redo_.clear();
    undo_.push_back({std::move(label), std::move(before), bytes});
    bytes_ += bytes;
    enforce_limit();
    return true;
}

bool History::undo(Document& document)
{
    if (undo_.empty())
        return false;
    Step step = std::move(undo_.back());
    undo_.pop_back();
    swap_with(step.state, document);
    redo_.push_back(std::move(step));
    return true;
}

bool History::redo(Document& document)
{
    if (redo_.empty())
        return false;
    Step step = std::move(redo_.back());
    redo_.pop_back();
    swap_with(step.state, document);
    undo_.push_back(std::move(step));
    return true;
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
