// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/mesh/mesh.h"

#include <doctest/doctest.h>

#include <limits>

#include "core/errors.h"
#include "tests/helpers.h"

using namespace meshfair;

TEST_SUITE("Mesh")
{
    TEST_CASE("faces are stored as offsets and keep their polygon size")
    {
        const Mesh m = test::mixed_polygons();
        CHECK(m.vertex_count() == 13);
        CHECK(m.face_count() == 7);
        CHECK(m.face_size(0) == 4);
        CHECK(m.face_size(2) == 3);
        CHECK(m.face_size(5) == 5);
        CHECK(m.face(5)[3] == 12);
        CHECK_NOTHROW(validate_mesh(m));
    }

    TEST_CASE("validate_mesh refuses what the paper's face definition excludes")
    {
        Mesh m = test::tetrahedron();
        SUBCASE("index out of range")
        {
            m.face_vertices[4] = 4;
            CHECK_THROWS_WITH_AS(validate_mesh(m), doctest::Contains("face 1 uses vertex 4"),
                                 InvalidInputError);
        }
        SUBCASE("repeated vertex")
        {
            m.face_vertices[2] = 0;
            CHECK_THROWS_WITH_AS(validate_mesh(m), doctest::Contains("face 0 repeats vertex 0"),
                                 InvalidInputError);
        }
        SUBCASE("non-finite coordinate")
        {
            m.positions[7] = std::numeric_limits<double>::quiet_NaN();
            CHECK_THROWS_WITH_AS(validate_mesh(m), doctest::Contains("vertex 2"),
                                 InvalidInputError);
        }
        SUBCASE("too small face")
        {
            const std::vector<Index> edge{0, 1};
            m.add_face(edge);
            CHECK_THROWS_WITH_AS(validate_mesh(m), doctest::Contains("face 4 has 2 vertices"),
                                 InvalidInputError);
        }
    }

    TEST_CASE("repeated_vertex finds repeats in long faces too")
    {
        std::vector<Index> face;
        for (Index i = 0; i < 100; ++i)
            face.push_back(i);
        CHECK(repeated_vertex(face) == kInvalidIndex);
        face[70] = 3;
        CHECK(repeated_vertex(face) == 3);
    }
}
