// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>

#include "core/mesh/mesh.h"

namespace meshfair {

//! \brief Adds independent Gaussian noise N(0, sigma^2) to every coordinate of every
//! vertex, modified in place.
//!
//! Deterministic for a seed: the generator is std::mt19937_64 (fully specified by the
//! standard) and the normal deviates come from the Box-Muller transform written here,
//! not from std::normal_distribution, whose algorithm each standard library chooses.
//! \pre sigma >= 0 and finite.
//! \throw InvalidInputError for a negative or non-finite sigma.
void add_gaussian_noise(Mesh& mesh, Scalar sigma, std::uint64_t seed);

} // namespace meshfair
