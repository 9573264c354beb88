// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/recipe/energy_terms.h"

#include <doctest/doctest.h>

#include <set>
#include <string>

#include "tests/helpers.h"
#include "tests/session_checks.h"

using namespace meshfair;

TEST_SUITE("energy terms")
{
    TEST_CASE("the table names every term once, and its values sum to the total")
    {
        // Distinct values in each field: a field left out of the table, or listed twice,
        // breaks the sum.
        TermEnergies e;
        e.edge = 1;
        e.soft = 2;
        e.centroid = 4;
        e.normal = 8;
        e.normal_smoothing = 16;
        e.normal_soft = 32;
        e.bending = 64;
        Scalar sum = 0;
        std::set<std::string> keys, labels;
        std::set<EnergyTerm> shares;
        for (const EnergyTermInfo& t : energy_terms())
        {
            sum += e.*(t.energy);
            CHECK(keys.insert(std::string(t.key)).second);
            CHECK(labels.insert(std::string(t.label)).second);
            if (t.shares)
            {
                CHECK(shares.insert(*t.shares).second);
                CHECK(energy_term(*t.shares) == &t);
            }
        }
        CHECK(sum == e.total());
        CHECK(energy_term(EnergyTerm::Total) == nullptr);
        // Every term a heat map can show has its row.
        for (const EnergyTerm t : {EnergyTerm::Edge, EnergyTerm::Soft, EnergyTerm::Centroid,
                                   EnergyTerm::Normal, EnergyTerm::Bending})
            CHECK(shares.count(t) == 1);
    }

    TEST_CASE("a term is in a recipe exactly when its energy is")
    {
        const Mesh m = test::noisy(test::icosphere(2), 0.05);
        const Topology t = build_topology(m);
        Recipe r;
        r.hard = HardVertices{{0}, {}};
        // Targets off the surface: at the input every term has some energy.
        r.soft = SoftVertices{{false, {1, 2, 3}}, 0.5, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
        r.centroid = CentroidConstraints{
            {false, {0, 1}}, 1.0, {{0, 0, 0}, {0, 0, 0}}, CentroidDenominator::Paper};
        r.normal = NormalConstraints{{false, {2, 3}}, 1.0, NormalSource::Initial, {}};
        r.bending = Bending{1.0, 0.0};
        Session session(m, t, r);
        const TermEnergies e = session.energy(m.positions);
        for (const EnergyTermInfo& info : energy_terms())
        {
            CAPTURE(std::string(info.key));
            CHECK(info.in_recipe(r) == (e.*(info.energy) > 0));
            // The heat map's shares of a term sum to its energy.
            if (info.shares)
            {
                std::vector<Scalar> per_vertex(static_cast<size_t>(m.vertex_count()));
                session.vertex_energy(m.positions, *info.shares, per_vertex);
                Scalar sum = 0;
                for (const Scalar s : per_vertex)
                    sum += s;
                CHECK(sum == doctest::Approx(e.*(info.energy)).epsilon(1e-12));
            }
        }
    }
}
