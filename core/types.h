// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <cstdint>

namespace meshfair {

//! Floating-point type of every coordinate and energy.
using Scalar = double;

//! Index of a vertex, face, edge or corner. 32 bits halve the memory traffic of
//! the solver's neighbour lists against 64-bit indices and still address 2^31 - 1
//! elements; readers refuse larger meshes.
using Index = std::int32_t;

//! Marks "no element", like the paper's -1.
inline constexpr Index kInvalidIndex = -1;

//! Largest element count a mesh may have (faces, corners, edges).
inline constexpr std::int64_t kMaxElements = 2147483647;
//! Largest vertex count: the coordinate index 3 i + 2 of every vertex i must fit in an
//! Index, so `positions[3 * i + a]` never overflows however it is computed.
inline constexpr std::int64_t kMaxVertices = kMaxElements / 3;

//! Largest coordinate magnitude the solver accepts (positions, targets, directions):
//! energies sum squared distances and normals multiply coordinates, which must not
//! overflow a double (1.8e308) even summed over 2^31 terms. Files may hold larger
//! finite values; smoothing refuses them with a message.
inline constexpr Scalar kMaxCoordinate = 1e100;

using Vec3 = std::array<Scalar, 3>;

} // namespace meshfair
