// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "tests/session_checks.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"
#include "core/recipe/session.h"
#include "core/solver/solver.h"
#include "tests/direct_minimizer.h"
#include "tests/helpers.h"

namespace meshfair::test {

void check_fused_as_general(const Session& session, std::span<const Scalar> fused,
                            std::span<const Scalar> general)
{
    REQUIRE(fused.size() == general.size());
    if (!session.normal_shares())
    {
        CHECK(std::memcmp(fused.data(), general.data(), fused.size() * sizeof(Scalar)) == 0);
        return;
    }
    const Scalar diagonal = bounding_box(general).diagonal();
    Scalar largest = 0;
    for (size_t k = 0; k < fused.size(); ++k)
        largest = std::max(largest, std::abs(fused[k] - general[k]));
    INFO("largest difference " << largest << ", diagonal " << diagonal);
    CHECK(largest <= 1e-13 * diagonal);
}

Mesh noisy(Mesh m, double sigma, unsigned seed)
{
    perturb(m, sigma, seed);
    return m;
}

void check_energy_never_increases(const Mesh& m, const Topology& t,
                                  std::span<const RecipeCase> cases, bool must_decrease)
{
    for (RecipeCase c : cases)
        for (const bool optimal : {false, true})
        {
            if (std::string(c.name) == "centroid exact" && m.face_size(0) == 4)
                continue;
            CAPTURE(c.name);
            CAPTURE(optimal);
            c.recipe.optimal_step = optimal;
            Mesh x = m;
            const SmoothResult r = smooth(x, t, c.recipe);
            for (size_t k = 1; k < r.energies.size(); ++k)
                CHECK(r.energies[k].total() <= r.energies[k - 1].total() * (1 + 1e-14) + 1e-300);
            if (must_decrease)
                CHECK(r.energies.back().total() < r.energies.front().total());
        }
}

void check_reaches_direct_minimizer(const Mesh& m, const Topology& t,
                                    std::span<const RecipeCase> cases)
{
    for (RecipeCase c : cases)
        for (const bool optimal : {false, true})
        {
            CAPTURE(c.name);
            CAPTURE(optimal);
            c.recipe.optimal_step = optimal;
            const Session session(m, t, c.recipe);
            const std::vector<Scalar> expected = direct_minimizer(
                m, t, c.recipe, m.positions,
                std::vector<Index>(session.free_vertices().begin(), session.free_vertices().end()));
            Mesh x = m;
            smooth(x, t, c.recipe);
            for (Index k = 0; k < 3 * m.vertex_count(); ++k)
                CHECK(x.positions[static_cast<size_t>(k)] ==
                      doctest::Approx(expected[static_cast<size_t>(k)]).scale(1).epsilon(1e-9));
        }
}

void check_same_bits_on_one_and_two_threads(const Mesh& m, const Topology& t, const Recipe& r)
{
    std::vector<std::vector<Scalar>> results;
    for (const int threads : {1, 2})
    {
        set_thread_count(threads);
        Mesh x = m;
        smooth(x, t, r);
        results.push_back(x.positions);
    }
    set_thread_count(0);
    CHECK(std::memcmp(results[0].data(), results[1].data(), results[0].size() * sizeof(Scalar)) ==
          0);
    CHECK(results[0] != m.positions);
}

} // namespace meshfair::test
