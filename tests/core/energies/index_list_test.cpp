// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/index_list.h"

#include <doctest/doctest.h>

#include "core/energies/face_centroid_term.h"
#include "core/recipe/session.h"
#include "tests/helpers.h"

using namespace meshfair;

TEST_SUITE("IndexList")
{
    TEST_CASE("every index in order is kept as a count, any other list as given")
    {
        const IndexList all(test::all_indices(5));
        CHECK(all.identity());
        CHECK(all.data() == nullptr);
        CHECK(all.size() == 5);
        const std::vector<Index> seen(all.begin(), all.end());
        CHECK(seen == test::all_indices(5));

        // The same elements in another order, a subset, and a gap are lists.
        for (const std::vector<Index>& given :
             {std::vector<Index>{1, 0, 2}, std::vector<Index>{0, 1, 3}, std::vector<Index>{2}})
        {
            const IndexList list(given);
            CHECK_FALSE(list.identity());
            CHECK(list.data() != nullptr);
            CHECK(list.size() == given.size());
            CHECK(std::vector<Index>(list.begin(), list.end()) == given);
            for (size_t k = 0; k < given.size(); ++k)
                CHECK(list[k] == given[k]);
        }
        CHECK(IndexList(std::vector<Index>{}).empty());
        CHECK(IndexList().empty());
    }

    TEST_CASE("a term of every face gives the same bits as the same faces listed out of order")
    {
        // Every face in order (no list kept) against every face in reverse order (a list):
        // energies and residuals agree (the residual pass walks the faces by index).
        Mesh m = test::mixed_polygons();
        const Topology t = build_topology(m);
        const std::vector<Index> in_order = test::all_indices(m.face_count());
        const std::vector<Index> reversed(in_order.rbegin(), in_order.rend());
        const std::vector<Scalar> x0 = m.positions;
        FaceCentroidTerm all(m, t, in_order, 1.5, CentroidDenominator::Paper);
        FaceCentroidTerm listed(m, t, reversed, 1.5, CentroidDenominator::Paper);
        all.use_centroids_of(x0);
        listed.use_centroids_of(x0);
        CHECK(all.faces().identity());
        CHECK_FALSE(listed.faces().identity());
        test::perturb(m, 0.2, 3);
        std::vector<Scalar> ra(3 * in_order.size(), 0), rb(3 * in_order.size(), 0);
        all.face_residuals(m.positions.data(), all.faces().data(), 0, m.face_count(), ra.data());
        listed.face_residuals(m.positions.data(), listed.faces().data(), 0, m.face_count(),
                              rb.data());
        CHECK(ra == rb);
        CHECK(all.energy(m.positions) ==
              doctest::Approx(listed.energy(m.positions)).epsilon(1e-15));
    }
}
