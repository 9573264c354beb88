// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/io.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "core/errors.h"
#include "tests/helpers.h"

using namespace meshfair;

TEST_SUITE("MeshIo")
{
    TEST_CASE("format comes from the extension, in any case")
    {
        CHECK(io::format_from_path("a/b.OBJ") == io::Format::Obj);
        CHECK(io::format_from_path("x.Ply") == io::Format::Ply);
        CHECK(io::format_from_path("x.off") == io::Format::Off);
        CHECK(io::format_from_path("x.stl") == io::Format::Stl);
        CHECK_THROWS_WITH_AS(io::format_from_path("dir.obj/mesh"),
                             doctest::Contains("unknown mesh format"), InvalidInputError);
        CHECK_THROWS_AS(io::format_from_path("mesh.3ds"), InvalidInputError);
    }

    TEST_CASE("a missing file is refused with its name")
    {
        CHECK_THROWS_WITH_AS(io::read_mesh("/nonexistent/m.obj"),
                             doctest::Contains("'/nonexistent/m.obj': cannot open"),
                             InvalidInputError);
    }

    TEST_CASE("atomic writing replaces a file whole and leaves no temporary behind")
    {
        const auto dir = test::temp_dir();
        const auto path = (dir / "out.obj").string();
        io::write_file_atomically(path, "old");
        io::write_file_atomically(path, "new content");
        CHECK(io::read_file(path) == "new content");
        CHECK(std::distance(std::filesystem::directory_iterator(dir),
                            std::filesystem::directory_iterator()) == 1);
    }

    TEST_CASE("a failed write leaves the existing file intact")
    {
        const auto dir = test::temp_dir();
        const auto path = (dir / "keep.obj").string();
        io::write_file_atomically(path, "precious");
        // Writing into a directory that does not exist fails before touching anything.
        CHECK_THROWS_AS(io::write_file_atomically((dir / "no/such/dir.obj").string(), "x"),
                        WriteError);
        CHECK_THROWS_AS(io::write_file_atomically(dir.string(), "x"), WriteError);
        CHECK(io::read_file(path) == "precious");
    }

    TEST_CASE("every format round-trips coordinates and order bit-exactly")
    {
        Mesh m = test::mixed_polygons();
        test::perturb(m, 0.37, 7); // coordinates with all 17 significant digits
        const std::vector<Index> isolated_face{0, 12, 8};
        m.add_face(isolated_face);
        struct Case
        {
            io::Format format;
            io::Encoding encoding;
        };
        for (const Case c : {Case{io::Format::Obj, io::Encoding::Ascii},
                             Case{io::Format::Off, io::Encoding::Ascii},
                             Case{io::Format::Ply, io::Encoding::Ascii},
                             Case{io::Format::Ply, io::Encoding::BinaryLittleEndian},
                             Case{io::Format::Ply, io::Encoding::BinaryBigEndian}})
        {
            CAPTURE(io::format_name(c.format));
            CAPTURE(io::encoding_name(c.encoding));
            const std::string data = io::write_mesh_data(m, c.format, {c.encoding});
            const Mesh back = io::read_mesh_data(data, c.format, "round-trip");
            CHECK(back == m);
        }
    }

    TEST_CASE("ASCII STL round-trips polygons as their fan triangles, welded in order")
    {
        const Mesh m = test::quad_cube();
        const std::string data = io::write_mesh_data(m, io::Format::Stl, {io::Encoding::Ascii});
        const Mesh back = io::read_mesh_data(data, io::Format::Stl, "cube.stl");
        CHECK(back.face_count() == 12);
        // Vertices are numbered in order of first appearance along the fan triangles
        // (v0, vk, vk+1) of each face, and faces 2k, 2k+1 are the fan of face k.
        std::vector<Index> first_seen;
        std::vector<Index> fan;
        for (Index f = 0; f < m.face_count(); ++f)
        {
            const auto face = m.face(f);
            for (size_t k = 1; k + 1 < face.size(); ++k)
                for (const Index v : {face[0], face[k], face[k + 1]})
                {
                    fan.push_back(v);
                    if (std::find(first_seen.begin(), first_seen.end(), v) == first_seen.end())
                        first_seen.push_back(v);
                }
        }
        REQUIRE(back.vertex_count() == 8);
        for (Index i = 0; i < 8; ++i)
            CHECK(back.position(i) == m.position(first_seen[i]));
        for (size_t c = 0; c < fan.size(); ++c)
            CHECK(back.position(back.face_vertices[c]) == m.position(fan[c]));
    }
}
