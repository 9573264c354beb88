// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <vector>

#include "core/mesh/mesh.h"
#include "core/recipe/recipe.h"

namespace meshfair::bench {

//! How a fairing case is cut out of a mesh standing on its bottom (the bunny: y up).
struct FairCaseShape
{
    int up_axis = 1;            //!< the coordinate that points up
    Scalar fixed_bottom = 0.01; //!< fraction of the height held fixed at the bottom
    int pins = 7;               //!< the highest vertices, pinned
    Scalar first_lift = 0.05;   //!< the pins' first targets: raised by this x the diagonal
    Scalar second_lift = 0.06;  //!< where they move next (the re-solve)
};

//! \brief What a user fairing a region asks for: a region (every vertex above the bottom's
//! strip, which stays where it is) and a few pins at the top lifted to targets, the paper's
//! constrained edge energy E = sum over the edges |x_j - x_i|^2 minimized over the
//! region's vertices that are not pins (a unique minimizer: the fixed strip holds every
//! free part). Indices are in the mesh's own numbering.
struct FairCase
{
    std::vector<Index> region;       //!< ascending
    std::vector<Index> pins;         //!< highest first
    std::vector<Vec3> first_targets; //!< one per pin
    std::vector<Vec3> second_targets;
    Scalar diagonal = 0; //!< of the mesh's bounding box

    //! The region's vertices that are not pins, ascending: the unknowns.
    std::vector<Index> free_vertices() const;
    //! `targets` as 3 values per pin, as Session::set_hard_targets takes them.
    static std::vector<Scalar> flat(const std::vector<Vec3>& targets);
};

//! \brief The case on `mesh`; the pins are the highest of its first `pin_candidates`
//! vertices (subdivide_triangles keeps the base mesh's vertices first, so every
//! subdivision of a mesh gets the same pins at the same places).
//! \pre pin_candidates >= shape.pins, <= mesh.vertex_count().
FairCase make_fair_case(const Mesh& mesh, Index pin_candidates, const FairCaseShape& shape = {});

//! \brief The recipe that solves the case with `method`: the region, the pins at
//! `targets`, the edge term alone (no other section).
Recipe fair_recipe(const FairCase& fair_case, const std::vector<Vec3>& targets, Method method);

} // namespace meshfair::bench
