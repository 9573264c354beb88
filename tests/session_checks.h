// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>

#include "core/mesh/mesh.h"
#include "core/recipe/recipe.h"
#include "core/recipe/session.h"
#include "core/topology/topology.h"

namespace meshfair::test {

//! A named recipe, for loops over configurations of the terms.
struct RecipeCase
{
    const char* name;
    Recipe recipe;
};

//! `m` with each coordinate perturbed by sigma (test::perturb), seeded.
Mesh noisy(Mesh m, double sigma = 0.05, unsigned seed = 17);

//! \brief Each case with lambda = 0.5 and with the line search: the energy of every step is
//! no more than the one before (to rounding), and with `must_decrease` the last is below
//! the first. "centroid exact" is left out on quad meshes (quads sit on the exact
//! denominator's bound, tested apart).
void check_energy_never_increases(const Mesh& m, const Topology& t,
                                  std::span<const RecipeCase> cases, bool must_decrease);

//! \brief Each case (its iterations many), with lambda = 0.5 and with the line search,
//! reaches the direct minimizer of the same quadratic (direct_minimizer) to 1e-9.
void check_reaches_direct_minimizer(const Mesh& m, const Topology& t,
                                    std::span<const RecipeCase> cases);

//! \brief Positions of the fused step (step(), run()) against the general step's
//! (step(x)) from the same start: the same bits, or, when the session's fused step
//! takes the normal term from per-face shares (Session::normal_shares), within 1e-13 of
//! the bounding box's diagonal (a few steps' rounding; 1e-16 a step measured).
void check_fused_as_general(const Session& session, std::span<const Scalar> fused,
                            std::span<const Scalar> general);

//! \brief smooth(m, t, r) on one thread and on two give the same bits, and move the mesh.
void check_same_bits_on_one_and_two_threads(const Mesh& m, const Topology& t, const Recipe& r);

} // namespace meshfair::test
