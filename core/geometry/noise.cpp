// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/geometry/noise.h"

#include <cmath>
#include <numbers>
#include <random>

#include "core/errors.h"

namespace meshfair {

void add_gaussian_noise(Mesh& mesh, Scalar sigma, std::uint64_t seed)
{
    if (!(sigma >= 0) || !std::isfinite(sigma))
        throw InvalidInputError("add_gaussian_noise: sigma must be finite and >= 0");
    std::mt19937_64 engine(seed);
    // 53 random bits -> uniform in (0, 1], so log() never sees 0.
    auto uniform = [&engine] { return (static_cast<double>(engine() >> 11) + 1.0) * 0x1p-53; };
    const size_t n = mesh.positions.size();
    for (size_t k = 0; k < n; k += 2)
    {
        const double radius = std::sqrt(-2.0 * std::log(uniform()));
        const double angle = 2.0 * std::numbers::pi * uniform();
        mesh.positions[k] += sigma * radius * std::cos(angle);
        if (k + 1 < n)
            mesh.positions[k + 1] += sigma * radius * std::sin(angle);
    }
}

} // namespace meshfair
