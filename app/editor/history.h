// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "app/edit/edit_parts.h"
#include "app/editor/document.h"

namespace meshfair::app {

//! \brief What undo restores: the parts of a document a step changed, each as it was
//! before the step. Parts a step did not change are not kept, so a selection change costs
//! its flags and never the positions.
struct EditState
{
    std::optional<SelectionMask> selected_vertices;
    std::optional<SelectionMask> selected_faces;
    std::optional<std::vector<ConstraintSet>> sets;
    std::optional<SolverSettings> solver;
    std::optional<std::vector<Scalar>> positions; //!< with the two below
    std::optional<int> steps_from_base;
    std::optional<bool> reproducible;
    std::optional<std::shared_ptr<const ShapeRecipe>> shape_recipe;
    std::optional<std::vector<Scalar>> base_positions;
};

//! Copies the document's `parts` (EditPart flags).
EditState capture(const Document& document, unsigned parts);

//! \brief Undo and redo: a list of steps, each the state before it in the parts it
//! changed. Undo swaps a step's parts with the document's, so the step then holds the
//! state after it for redo: both directions restore exact bits, and a state is stored
//! once whichever way it was last crossed.
//!
//! Memory is bounded: when the stored parts exceed the limit, the oldest steps go (the
//! newest step is always kept, whatever its size).
class History
{
public:
    explicit History(std::size_t byte_limit = std::size_t(1) << 30) : limit_(byte_limit) {}

    //! \brief Records that `label` took the document from `before` to its current state.
    //! Parts that did not change are not kept; a step that changed nothing is not recorded
    //! (returns false). Clears the redo list. With `merge`, a step of the same label as the
    //! newest one joins it (a slider dragged through many values is one step), unless that
    //! one was recorded without `merge` or seal() came since.
    bool record(std::string label, EditState before, const Document& now, bool merge = false);
    //! Ends the newest step's series of merges: the next step is a step of its own (an
    //! interaction ended: a drag released, a widget let go, a script's action done).
    void seal() { sealed_ = true; }

    //! Undoes the newest step on `document`; returns the parts it changed (0: none).
    unsigned undo(Document& document);
    //! Redoes the step undone last; returns the parts it changed (0: none).
    unsigned redo(Document& document);

    std::size_t undo_count() const { return undo_.size(); }
    std::size_t redo_count() const { return redo_.size(); }
    //! The label of the step undo would revert (empty when none).
    std::string undo_label() const { return undo_.empty() ? std::string() : undo_.back().label; }
    std::string redo_label() const { return redo_.empty() ? std::string() : redo_.back().label; }
    //! What the stored steps hold, in bytes, and the limit.
    std::size_t bytes() const { return bytes_; }
    std::size_t limit() const { return limit_; }
    void set_limit(std::size_t byte_limit);
    //! Steps dropped so far to stay within the limit.
    std::size_t dropped() const { return dropped_; }
    void clear();

private:
    struct Step
    {
        std::string label;
        EditState state;
        std::size_t bytes = 0;
    };
    static std::size_t bytes_of(const EditState& state);
    static unsigned swap_with(EditState& state, Document& document);
    void enforce_limit();

    std::deque<Step> undo_, redo_;
    std::size_t bytes_ = 0, limit_, dropped_ = 0;
    bool sealed_ = true; // the newest step takes no merge
};

} // namespace meshfair::app
