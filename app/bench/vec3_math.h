// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// The few 3-vector operations the quality benchmark's meshes and metrics use on Vec3
// (std::array), so its own code reads like the formulas it computes.

#include <cmath>

#include "core/types.h"

namespace meshfair::bench {

inline Vec3 operator+(const Vec3& a, const Vec3& b)
{
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b)
{
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator*(Scalar s, const Vec3& a)
{
    return {s * a[0], s * a[1], s * a[2]};
}
inline Scalar dot(const Vec3& a, const Vec3& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Scalar norm(const Vec3& a)
{
    return std::sqrt(dot(a, a));
}
//! a / |a|; a must not be zero.
inline Vec3 normalized(const Vec3& a)
{
    return (1 / norm(a)) * a;
}

} // namespace meshfair::bench
