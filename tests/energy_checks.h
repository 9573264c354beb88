// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "core/types.h"

namespace meshfair::test {

//! Checks -1/2 dE/dx (given as `rhs`, 3 #V) against central finite differences of
//! `energy` at x, for every coordinate. E is quadratic, so central differences are exact
//! up to rounding and the tolerance can be tight.
inline void check_rhs_is_half_negative_gradient(
    const std::function<Scalar(std::span<const Scalar>)>& energy, std::vector<Scalar> x,
    std::span<const Scalar> rhs, Scalar step = 1e-4)
{
    Scalar scale = 1;
    for (const Scalar r : rhs)
        scale = std::max(scale, std::abs(r));
    for (size_t k = 0; k < x.size(); ++k)
    {
        const Scalar saved = x[k];
        x[k] = saved + step;
        const Scalar up = energy(x);
        x[k] = saved - step;
        const Scalar down = energy(x);
        x[k] = saved;
        const Scalar gradient = (up - down) / (2 * step);
        CAPTURE(k);
        CHECK(-0.5 * gradient == doctest::Approx(rhs[k]).epsilon(1e-6).scale(scale));
    }
}

} // namespace meshfair::test
