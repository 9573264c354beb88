// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

namespace meshfair::app {

//! The parts of a document the user edits, as flags: what a step may change.
enum EditPart : unsigned
{
    kSelection = 1,      //!< the vertex and face selections
    kSets = 2,           //!< the constraint sets
    kSettings = 4,       //!< the solver settings
    kPositions = 8,      //!< the current shape
    kBasePositions = 16, //!< the shape the recipe starts from (changed by Apply)
    //! Which elements the sets hold, their names and whether they solve: a version only
    //! (the history keeps it with kSets), so that what depends on the sets' membership
    //! alone (notes, a region's holes and border) is not redone when pins move.
    kSetMembers = 32
};

} // namespace meshfair::app
