// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// tinyobjloader as an independent oracle for MeshFair's OBJ reader: on every OBJ file
// both accept, they must find the same faces and the same coordinates (tinyobjloader's
// number parser is off by up to 3 ulp, MeshFair's is exact).
#include <doctest/doctest.h>
#include <tiny_obj_loader.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/io.h"
#include "tests/helpers.h"

namespace fs = std::filesystem;

namespace meshfair {

namespace {

struct OracleMesh
{
    std::vector<double> positions;
    std::vector<std::vector<int>> faces;
};

// What tinyobjloader reads; false when it refuses the text.
bool oracle_read(std::string text, OracleMesh& out)
{
    // tinyobjloader splits lines at LF only and does not know the byte-order mark.
    if (text.starts_with("\xEF\xBB\xBF"))
        text.erase(0, 3);
    for (size_t k = 0; k < text.size(); ++k)
        if (text[k] == '\r' && (k + 1 == text.size() || text[k + 1] != '\n'))
            text[k] = '\n';
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // An empty material text keeps it off the disk.
    if (!reader.ParseFromString(text, std::string(), config))
        return false;
    out.positions = reader.GetAttrib().vertices;
    for (const auto& shape : reader.GetShapes())
    {
        size_t k = 0;
        for (const unsigned char n : shape.mesh.num_face_vertices)
        {
            std::vector<int> face;
            for (unsigned c = 0; c < n; ++c, ++k)
                face.push_back(shape.mesh.indices[k].vertex_index);
            out.faces.push_back(face);
        }
    }
    return true;
}

bool within_3_ulp(double a, double b)
{
    return a == b || std::abs(a - b) <= 4 * std::numeric_limits<double>::epsilon() *
                                            std::max(std::abs(a), std::abs(b));
}

// Checks agreement on `text`; returns false when the comparison does not apply
// (faces MeshFair normalized, or polygons past tinyobjloader's 255-corner limit).
bool agrees_with_oracle(const std::string& text, const std::string& what)
{
    INFO(what);
    io::ReadReport report;
    const Mesh mesh = io::read_mesh_data(text, io::Format::Obj, what, &report);
    for (const std::string& note : report.notes)
        if (note.starts_with("collapsed"))
            return false;
    for (Index f = 0; f < mesh.face_count(); ++f)
        if (mesh.face_size(f) > 255)
            return false;
    OracleMesh oracle;
    REQUIRE(oracle_read(text, oracle));
    REQUIRE(oracle.positions.size() == mesh.positions.size());
    size_t differing = 0;
    for (size_t k = 0; k < oracle.positions.size(); ++k)
        differing += within_3_ulp(oracle.positions[k], mesh.positions[k]) ? 0 : 1;
    CHECK(differing == 0);
    REQUIRE(oracle.faces.size() == static_cast<size_t>(mesh.face_count()));
    size_t other_faces = 0;
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const auto face = mesh.face(f);
        other_faces += std::vector<int>(face.begin(), face.end()) == oracle.faces[f] ? 0 : 1;
    }
    CHECK(other_faces == 0);
    return true;
}

} // namespace

TEST_SUITE("obj oracle")
{
    TEST_CASE("tinyobjloader reads the bundled bunny as MeshFair does")
    {
        CHECK(agrees_with_oracle(io::read_file((test::assets_dir() / "bunny.obj").string()),
                                 "bunny.obj"));
    }

    TEST_CASE("tinyobjloader reads every accepted OBJ file of the adversarial suite alike")
    {
        int compared = 0, skipped = 0;
        for (const auto& entry : fs::directory_iterator(test::adversarial_dir() / "obj"))
        {
            const std::string text = io::read_file(entry.path().string());
            try
            {
                (agrees_with_oracle(text, entry.path().filename().string()) ? compared : skipped) +=
                    1;
            }
            catch (const InvalidInputError&)
            {
                // Refused by MeshFair: the suite checks the message.
            }
        }
        MESSAGE(compared << " files compared, " << skipped << " with normalized faces");
        CHECK(compared >= 10);
    }
}

} // namespace meshfair
