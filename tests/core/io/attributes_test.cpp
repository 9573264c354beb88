// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/io/attributes.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/io/io.h"
#include "tests/helpers.h"

using namespace meshfair;
using io::Format;
using io::ValueType;

namespace {

struct Read
{
    Mesh mesh;
    io::MeshAttributes attributes;
    std::vector<std::string> notes;
};

Read read(const std::string& data, Format format)
{
    Read r;
    io::ReadReport report;
    r.mesh = io::read_mesh_data(data, format, "in", &report, &r.attributes);
    r.notes = report.notes;
    return r;
}

struct Written
{
    std::string data;
    std::vector<std::string> notes;
};

Written write(const Mesh& mesh, const io::MeshAttributes& attributes, Format format,
              io::Encoding encoding = io::Encoding::Ascii, io::Normals normals = io::Normals::Keep)
{
    Written w;
    w.data = io::write_mesh_data(mesh, format, {encoding, normals}, &attributes, &w.notes);
    return w;
}

// The quad cube as an OBJ with everything an exporter writes: vertex colours, a texture
// seam on every edge (4 vt per face), one normal per face (flat shading: hard edges), a
// material library, an object, groups, smoothing groups and materials.
std::string textured_cube_obj()
{
    const Mesh cube = test::quad_cube();
    std::string s = "mtllib cube.mtl\no cube\n";
    for (Index v = 0; v < cube.vertex_count(); ++v)
    {
        const Vec3 p = cube.position(v);
        s += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
             " " + std::to_string(0.125 * v) + " 0.5 " + std::to_string(1 - 0.125 * v) + "\n";
    }
    for (Index f = 0; f < cube.face_count(); ++f)
        for (int k = 0; k < 4; ++k)
            s += "vt " + std::to_string(0.25 * f + 0.0625 * k) + " " +
                 std::to_string(0.5 * (k / 2)) + "\n";
    for (Index f = 0; f < cube.face_count(); ++f)
    {
        const Vec3 n = face_normal(cube, cube.positions, f);
        s += "vn " + std::to_string(n[0]) + " " + std::to_string(n[1]) + " " +
             std::to_string(n[2]) + "\n";
    }
    for (Index f = 0; f < cube.face_count(); ++f)
    {
        if (f % 2 == 0)
            s += "g side" + std::to_string(f / 2) + "\nusemtl paint" + std::to_string(f / 2) +
                 "\ns " + (f == 0 ? "off" : "1") + "\n";
        s += "f";
        for (Index k = 0; k < 4; ++k)
            s += " " + std::to_string(cube.face(f)[static_cast<size_t>(k)] + 1) + "/" +
                 std::to_string(4 * f + k + 1) + "/" + std::to_string(f + 1);
        s += "\n";
    }
    return s;
}

// The per-corner values of corner k.
std::vector<double> at_corner(const io::CornerValues& c, size_t k)
{
    const Index e = c.corners[k];
    if (e == kInvalidIndex)
        return {};
    const auto d = static_cast<size_t>(c.dimension);
    return {c.values.begin() + static_cast<std::ptrdiff_t>(d * static_cast<size_t>(e)),
            c.values.begin() + static_cast<std::ptrdiff_t>(d * static_cast<size_t>(e) + d)};
}

void check_unit_near(const std::vector<double>& n, const Vec3& expected)
{
    REQUIRE(n.size() == 3);
    for (int a = 0; a < 3; ++a)
        CHECK(n[static_cast<size_t>(a)] == doctest::Approx(expected[a]).epsilon(1e-12));
}

Vec3 unit(const Vec3& v)
{
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / l, v[1] / l, v[2] / l};
}

// The area-weighted normal of vertex v: what recompute_normals gives a vertex.
Vec3 vertex_normal(const Mesh& mesh, Index v)
{
    Vec3 sum{0, 0, 0};
    for (Index f = 0; f < mesh.face_count(); ++f)
        for (const Index u : mesh.face(f))
            if (u == v)
            {
                const Vec3 a = face_area_vector(mesh, mesh.positions, f);
                for (int c = 0; c < 3; ++c)
                    sum[c] += a[c];
            }
    return unit(sum);
}

// A PLY's worth of attributes for the open grid: colours with alpha, normals, a quality
// that is NaN and infinite on some vertices, a face flag and per-corner texture
// coordinates, two other elements and comments.
io::MeshAttributes grid_attributes(const Mesh& grid)
{
    io::MeshAttributes a;
    const auto nv = static_cast<size_t>(grid.vertex_count());
    a.vertex = {"vertex", grid.vertex_count(), {}};
    std::vector<double> red(nv), green(nv), blue(nv), alpha(nv, 255), quality(nv), nz(nv, 1);
    for (size_t v = 0; v < nv; ++v)
    {
        red[v] = static_cast<double>(v % 256);
        green[v] = static_cast<double>((3 * v) % 256);
        blue[v] = 255 - static_cast<double>(v % 256);
        quality[v] = 0.1 * static_cast<double>(v);
    }
    quality[1] = std::numeric_limits<double>::quiet_NaN();
    quality[2] = -std::numeric_limits<double>::infinity();
    a.vertex.properties = {test::property("red", ValueType::UInt8, red),
                           test::property("green", ValueType::UInt8, green),
                           test::property("blue", ValueType::UInt8, blue),
                           test::property("alpha", ValueType::UInt8, alpha),
                           test::property("nx", ValueType::Float32, std::vector<double>(nv, 0)),
                           test::property("ny", ValueType::Float32, std::vector<double>(nv, 0)),
                           test::property("nz", ValueType::Float32, nz),
                           test::property("quality", ValueType::Float64, quality)};
    const auto nf = static_cast<size_t>(grid.face_count());
    io::Property flags = test::property("flags", ValueType::Int16, std::vector<double>(nf));
    io::Property texcoord{"texcoord", ValueType::Float32, true, ValueType::UInt8, {}, {0}};
    for (size_t f = 0; f < nf; ++f)
    {
        flags.values[f] = -static_cast<double>(f);
        for (Index k = 0; k < grid.face_size(static_cast<Index>(f)); ++k)
        {
            texcoord.values.push_back(0.125 * static_cast<double>(f));
            texcoord.values.push_back(0.25 * k);
        }
        texcoord.offsets.push_back(static_cast<Index>(texcoord.values.size()));
    }
    a.face = {"face", grid.face_count(), {flags, texcoord}};
    io::Property chain{"chain",          ValueType::Int32, true,
                       ValueType::UInt8, {0, 1, 2, 7},     {0, 3, 3, 4}};
    a.other_elements = {
        {"edge",
         3,
         {test::property("vertex1", ValueType::Int32, {0, 1, 2}),
          test::property("vertex2", ValueType::UInt32, {1, 2, 4000000000.0}), chain}},
        {"camera", 1, {test::property("view_px", ValueType::Float32, {0.5})}},
        {"empty", 2, {}}};
    a.comments = {"comment TextureFile grid.png", "obj_info scanned in 2012"};
    return a;
}

// Attribute equality with NaN equal to NaN.
bool same(const io::MeshAttributes& a, const io::MeshAttributes& b)
{
    io::MeshAttributes x = a, y = b;
    for (io::MeshAttributes* m : {&x, &y})
        for (io::Property& p : m->vertex.properties)
            for (double& v : p.values)
                if (std::isnan(v))
                    v = 12345.678; // a value no property here holds
    return x == y;
}

} // namespace

TEST_SUITE("Attributes")
{
    TEST_CASE("OBJ: texture coordinates, normals, colours, groups and materials round-trip")
    {
        const Read in = read(textured_cube_obj(), Format::Obj);
        CHECK(in.notes.empty());
        const io::MeshAttributes& a = in.attributes;
        CHECK(a.texcoords.entry_count() == 24);
        CHECK(a.texcoords.dimension == 2);
        CHECK(a.normals.entry_count() == 6);
        CHECK(a.vertex.find(io::kRed) != nullptr);
        REQUIRE(a.statements.size() == 11);
        CHECK(a.statements[0] == io::ObjStatement{0, "mtllib cube.mtl"});
        CHECK(a.statements[4] == io::ObjStatement{0, "s off"});
        CHECK(a.statements[5] == io::ObjStatement{2, "g side1"});
        CHECK(io::describe_attributes(a) ==
              std::vector<std::string>{"vertex colours (red green blue: double)",
                                       "texture coordinates: 24 vt on 24 corners",
                                       "normals: 6 vn on 24 corners",
                                       "groups and materials: 3 g, 1 mtllib, 1 o, 3 s, 3 usemtl"});

        const Written out = write(in.mesh, a, Format::Obj);
        CHECK(out.notes == std::vector<std::string>{"normals written as read, not recomputed "
                                                    "from the positions written"});
        const Read back = read(out.data, Format::Obj);
        CHECK(back.mesh == in.mesh);
        CHECK(back.attributes == a);
        CHECK(back.notes.empty());
        // The same text again: a second round trip changes nothing.
        CHECK(write(back.mesh, back.attributes, Format::Obj).data == out.data);
    }

    TEST_CASE("OBJ: a vt of one or three values, faces without vt, vt and vn errors")
    {
        const Read r = read(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.5\nvt 0.25 0.75 1\n"
            "f 1/1 2/2 3/1\nf 2 4 3\n",
            Format::Obj);
        CHECK(r.attributes.texcoords.dimension == 3);
        CHECK(r.attributes.texcoords.values == std::vector<double>{0.5, 0, 0, 0.25, 0.75, 1});
        CHECK(r.attributes.texcoords.corners == std::vector<Index>{0, 1, 0, -1, -1, -1});
        const Read back = read(write(r.mesh, r.attributes, Format::Obj).data, Format::Obj);
        CHECK(back.attributes == r.attributes);

        // A corner repeated (collapsed, with a note) takes its texture coordinate and
        // normal with it: the others keep theirs.
        const Read collapsed = read(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 2 0\nvt 0 1\n"
            "vn 1 0 0\nvn 0 1 0\nvn 0 0 1\nvn 1 1 1\n"
            "f 1/1/1 2/2/2 2/3/3 3/4/4\n",
            Format::Obj);
        CHECK(collapsed.mesh.face_vertices == std::vector<Index>{0, 1, 2});
        CHECK(collapsed.attributes.texcoords.corners == std::vector<Index>{0, 1, 3});
        CHECK(collapsed.attributes.normals.corners == std::vector<Index>{0, 1, 3});

        // Texture coordinates at only some corners of a face: dropped from it, with a note.
        const Read partial = read("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3/1\n", Format::Obj);
        CHECK(partial.attributes.texcoords.empty());
        CHECK(partial.notes == std::vector<std::string>{
                                   "ignored the texture coordinates of 1 face that give them at "
                                   "only some corners (first at in:5:1)",
                                   "ignored 1 texture coordinate (vt) that no face uses"});

        const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
        CHECK(test::read_error(tri + "f 1/2 2/1 3/1\n", Format::Obj) ==
              "t.obj:6:5: texture coordinate index 2 is past the last texture coordinate (vt) "
              "(the file defines 1)");
        CHECK(test::read_error(tri + "f 1//1 2//1 3//-2\n", Format::Obj) ==
              "t.obj:6:16: normal index -2 reaches before the first normal (vn) (1 normal is "
              "defined before this line)");
        CHECK(test::read_error(tri + "f 1/1/1/1 2 3\n", Format::Obj) ==
              "t.obj:6:3: face corner '1/1/1/1' has more than three indices (v/vt/vn)");
        CHECK(test::read_error(tri + "vn 0 1\n", Format::Obj) ==
              "t.obj:6:1: a normal needs x y z (vn x y z)");
        CHECK(test::read_error(tri + "vt 0 1 2 3\n", Format::Obj) ==
              "t.obj:6:10: unexpected value after the texture coordinate's u v w");
        CHECK(test::read_error(tri + "f 1/x 2/1 3/1\n", Format::Obj) ==
              "t.obj:6:5: texture coordinate index 'x' is not an integer");
        // Colours on some vertex lines only: not kept, with a note.
        const Read some = read("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", Format::Obj);
        CHECK(some.attributes.empty());
        CHECK(some.notes == std::vector<std::string>{"ignored the colours r g b of 1 of the 3 "
                                                     "vertex lines (colours are kept when every "
                                                     "vertex has one)"});
    }

    TEST_CASE("normals are recomputed from the positions written and hard edges stay hard")
    {
        Read in = read(textured_cube_obj(), Format::Obj);
        // Smoothing moved a vertex.
        in.mesh.positions[0] -= 0.5;
        in.mesh.positions[1] += 0.25;
        const Written out =
            write(in.mesh, in.attributes, Format::Obj, io::Encoding::Ascii, io::Normals::Recompute);
        CHECK(out.notes.empty());
        const Read back = read(out.data, Format::Obj);
        // One normal per face and vertex (the file's per-face normals split no further)...
        CHECK(back.attributes.normals.entry_count() == 24);
        // ... each its face's normal of the new positions: flat shading stays flat.
        for (Index f = 0; f < in.mesh.face_count(); ++f)
            for (Index k = in.mesh.face_offsets[f]; k < in.mesh.face_offsets[f + 1]; ++k)
                check_unit_near(at_corner(back.attributes.normals, static_cast<size_t>(k)),
                                face_normal(in.mesh, in.mesh.positions, f));
        // Everything else as read.
        CHECK(back.attributes.texcoords == in.attributes.texcoords);
        CHECK(back.attributes.statements == in.attributes.statements);
        CHECK(back.attributes.vertex == in.attributes.vertex);

        // Smooth shading (one vn per vertex): the area-weighted normal of the new positions.
        // Smooth shading (one vn per vertex), and one vn shared by every corner (exporters
        // that merge equal normals): each vertex gets the area-weighted normal of the new
        // positions, its own.
        for (const char* normals : {"vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                                    "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\n",
                                    "vn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n"})
        {
            CAPTURE(normals);
            const Read s =
                read(std::string("v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\n") + normals, Format::Obj);
            const Read renewed = read(write(s.mesh, s.attributes, Format::Obj, io::Encoding::Ascii,
                                            io::Normals::Recompute)
                                          .data,
                                      Format::Obj);
            CHECK(renewed.attributes.normals.entry_count() == 4);
            for (size_t k = 0; k < 6; ++k)
                check_unit_near(at_corner(renewed.attributes.normals, k),
                                vertex_normal(s.mesh, s.mesh.face_vertices[k]));
        }

        // PLY vertex and face normals alike; a vertex in no face keeps its normal.
        Mesh grid = test::open_grid(2, 1);
        grid.add_vertex(9, 9, 9);
        grid.positions[5] = 0.75; // vertex 1 lifted
        io::MeshAttributes a;
        a.vertex = {"vertex",
                    grid.vertex_count(),
                    {test::property("nx", ValueType::Float32, std::vector<double>(7, 0)),
                     test::property("ny", ValueType::Float32, std::vector<double>(7, 0.6)),
                     test::property("nz", ValueType::Float32, std::vector<double>(7, 0.8))}};
        a.face = {"face",
                  grid.face_count(),
                  {test::property("nx", ValueType::Float64, {1, 1}),
                   test::property("ny", ValueType::Float64, {0, 0}),
                   test::property("nz", ValueType::Float64, {0, 0})}};
        for (const io::Encoding e : {io::Encoding::Ascii, io::Encoding::BinaryBigEndian})
        {
            const Read p =
                read(write(grid, a, Format::Ply, e, io::Normals::Recompute).data, Format::Ply);
            const io::Channels v = io::find_channels(p.attributes.vertex);
            const io::Channels f = io::find_channels(p.attributes.face);
            REQUIRE(v.has_normal());
            REQUIRE(f.has_normal());
            for (Index i = 0; i < 6; ++i)
            {
                const Vec3 expected = vertex_normal(grid, i);
                for (int c = 0; c < 3; ++c) // stored as float32
                    CHECK(v.normal[c]->values[static_cast<size_t>(i)] ==
                          doctest::Approx(expected[c]).epsilon(1e-7));
            }
            CHECK(v.normal[1]->values[6] == doctest::Approx(0.6));
            for (Index i = 0; i < 2; ++i)
                for (int c = 0; c < 3; ++c)
                    CHECK(f.normal[c]->values[static_cast<size_t>(i)] ==
                          doctest::Approx(face_normal(grid, grid.positions, i)[c]).epsilon(1e-12));
        }
    }

    TEST_CASE("PLY: every property, list, element and comment round-trips in every encoding")
    {
        Mesh grid = test::open_grid(3, 2);
        const io::MeshAttributes a = grid_attributes(grid);
        for (const io::Encoding e :
             {io::Encoding::Ascii, io::Encoding::BinaryLittleEndian, io::Encoding::BinaryBigEndian})
        {
            CAPTURE(io::encoding_name(e));
            const Written out = write(grid, a, Format::Ply, e);
            CHECK(out.notes == std::vector<std::string>{"normals written as read, not recomputed "
                                                        "from the positions written"});
            const Read back = read(out.data, Format::Ply);
            CHECK(back.mesh == grid);
            CHECK(back.notes.empty());
            // The comments gain MeshFair's own, first.
            io::MeshAttributes signed_a = a;
            signed_a.comments.insert(signed_a.comments.begin(), "comment MeshFair");
            CHECK(same(back.attributes, signed_a));
            CHECK(std::isnan(back.attributes.vertex.find("quality")->values[1]));
            CHECK(out.data.find("comment TextureFile grid.png\nobj_info scanned in 2012\n") !=
                  std::string::npos);
            // Written again: the same bytes (MeshFair's own comment is not repeated).
            CHECK(write(back.mesh, back.attributes, Format::Ply, e).data == out.data);
        }
        // Float32 values are written as the shortest text of the float.
        const std::string ascii = write(grid, a, Format::Ply).data;
        CHECK(ascii.find(" 0.125 0.25 ") != std::string::npos);
    }

    TEST_CASE("a header of many elements is described by the first few and a count")
    {
        std::string ply = "ply\nformat ascii 1.0\n";
        for (int k = 0; k < 20; ++k)
            ply += "element e" + std::to_string(k) + (k == 11 ? " 2\nproperty uchar q\n" : " 0\n");
        ply +=
            "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n1\n2\n"
            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
        const Read in = read(ply, Format::Ply);
        REQUIRE(in.attributes.other_elements.size() == 20);
        const std::vector<std::string> lines = io::describe_attributes(in.attributes);
        REQUIRE(lines.size() == io::kElementsListed + 1);
        CHECK(lines[0] == "element 'e0' (0 rows, 0 properties)");
        CHECK(lines[7] == "element 'e7' (0 rows, 0 properties)");
        CHECK(lines[8] == "12 more elements (2 rows, 1 property in all)");
        // Every element is still kept and written back.
        CHECK(read(write(in.mesh, in.attributes, Format::Ply).data, Format::Ply)
                  .attributes.other_elements == in.attributes.other_elements);
    }

    TEST_CASE("OFF: normals, colours with alpha, texture coordinates and face colours round-trip")
    {
        const std::string text =
            "STCNOFF\n4 2 0\n0 0 0 0 0 1 255 0 0 128 0 0\n1 0 0 0 0 1 0 255 0 255 1 0\n"
            "1 1 0 0 0 1 0 0 255 255 1 1\n0 1 0 0 0 1 9 9 9 255 0 1\n"
            "3 0 1 2 0.5 0.25 1.0\n3 0 2 3 1.0 0.0 0.0\n";
        const Read in = read(text, Format::Off);
        CHECK(in.notes.empty());
        CHECK(io::describe_attributes(in.attributes) ==
              std::vector<std::string>{"vertex colours (red green blue alpha: uchar)",
                                       "vertex normals (nx ny nz: double)",
                                       "vertex texture coordinates (texture_u texture_v: double)",
                                       "face colours (red green blue: double)"});
        const Written out = write(in.mesh, in.attributes, Format::Off);
        CHECK(out.data.starts_with("STCNOFF\n"));
        const Read back = read(out.data, Format::Off);
        CHECK(back.mesh == in.mesh);
        CHECK(back.attributes == in.attributes);
        // Fractions keep a decimal point, so they are not read back as integer colours.
        CHECK(out.data.find("3 0 2 3 1.0 0.0 0.0\n") != std::string::npos);
    }

    TEST_CASE("conversions keep what the target holds and name the rest")
    {
        const Read obj = read(textured_cube_obj(), Format::Obj);

        // OBJ -> PLY: colours as they are, the seams' texture coordinates per corner,
        // normals per vertex (their mean at the cube's corners), groups in a note.
        const Written ply = write(obj.mesh, obj.attributes, Format::Ply);
        CHECK(ply.notes ==
              std::vector<std::string>{
                  "normals written as read, not recomputed from the positions written",
                  "PLY holds one normal per vertex: 8 vertices with different normals on "
                  "different faces (hard edges) get their mean",
                  "PLY cannot hold the OBJ groups, objects, smoothing groups and materials "
                  "'mtllib cube.mtl', 'o cube', 'g side0', 'usemtl paint0', 's off', 'g side1', "
                  "'usemtl paint1', 's 1' and 3 more; they are not written"});
        const Read from_ply = read(ply.data, Format::Ply);
        CHECK(from_ply.attributes.vertex.find(io::kRed)->values ==
              obj.attributes.vertex.find(io::kRed)->values);
        const io::CornerValues t = io::corner_texcoords(from_ply.mesh, from_ply.attributes);
        for (size_t k = 0; k < 24; ++k)
            CHECK(at_corner(t, k) == at_corner(obj.attributes.texcoords, k));
        check_unit_near({from_ply.attributes.vertex.find("nx")->values[0],
                         from_ply.attributes.vertex.find("ny")->values[0],
                         from_ply.attributes.vertex.find("nz")->values[0]},
                        unit(vertex_normal(obj.mesh, 0)));

        // ... and back to OBJ: the same texture coordinate at every corner.
        const Read again =
            read(write(from_ply.mesh, from_ply.attributes, Format::Obj).data, Format::Obj);
        for (size_t k = 0; k < 24; ++k)
            CHECK(at_corner(again.attributes.texcoords, k) ==
                  at_corner(obj.attributes.texcoords, k));
        CHECK(again.attributes.vertex == obj.attributes.vertex);

        // OBJ -> OFF: colours as fractions, the seams cannot be held per vertex.
        const Written off = write(obj.mesh, obj.attributes, Format::Off);
        CHECK(off.data.starts_with("CNOFF\n"));
        CHECK(off.notes.size() == 4);
        CHECK(off.notes[2] ==
              "OFF holds one texture coordinate pair per vertex: the texture coordinates, which "
              "differ between the faces of some vertices (seams) or are missing on some faces, "
              "are not written");
        CHECK(read(off.data, Format::Off).attributes.vertex.find(io::kGreen)->values ==
              obj.attributes.vertex.find(io::kGreen)->values);

        // OBJ -> STL: the shape only; everything else named.
        const Written stl =
            write(obj.mesh, obj.attributes, Format::Stl, io::Encoding::BinaryLittleEndian);
        CHECK(stl.notes.size() == 5);
        CHECK(stl.notes[1] ==
              "STL cannot hold the vertex properties 'red', 'green', 'blue'; "
              "they are not written");
        CHECK(stl.notes[2] ==
              "STL cannot hold the OBJ per-corner values texture coordinates "
              "(vt), normals (vn; facet normals are written instead); they are "
              "not written");
        CHECK(stl.notes[4] ==
              "STL holds triangles: 6 polygons of more than 3 sides written as "
              "fans of triangles from their first corner");

        // PLY -> OBJ: integer colours as fractions, per-corner texture coordinates as vt;
        // the rest named.
        Mesh grid = test::open_grid(3, 2);
        const io::MeshAttributes pa = grid_attributes(grid);
        const Written grid_obj = write(grid, pa, Format::Obj);
        CHECK(grid_obj.notes ==
              std::vector<std::string>{
                  "normals written as read, not recomputed from the positions written",
                  "OBJ cannot hold the vertex properties 'alpha', 'quality'; they are not "
                  "written",
                  "OBJ cannot hold the face properties 'flags'; they are not written",
                  "OBJ cannot hold the elements 'edge' (3 rows), 'camera' (1 row), 'empty' (2 "
                  "rows); they are not written"});
        // The PLY's header comments become OBJ comments (formats.md's table).
        CHECK(
            grid_obj.data.find("\n# comment TextureFile grid.png\n# obj_info scanned in 2012\n") !=
            std::string::npos);
        const Read grid_back = read(grid_obj.data, Format::Obj);
        CHECK(grid_back.attributes.vertex.find(io::kBlue)->values[0] == 1.0); // 255 / 255
        CHECK(grid_back.attributes.vertex.find(io::kRed)->values[2] == 2.0 / 255);
        CHECK(grid_back.attributes.texcoords.entry_count() == 24);
        CHECK(at_corner(grid_back.attributes.texcoords, 5) == std::vector<double>{0.125, 0.25});
        CHECK(grid_back.attributes.normals.entry_count() == 12); // one vn per vertex

        // PLY -> OFF: integer colours stay integers; the face flags and lists are named.
        const Written grid_off = write(grid, pa, Format::Off);
        CHECK(grid_off.data.starts_with("CNOFF\n"));
        CHECK(grid_off.data.find("\n# comment TextureFile grid.png\n") != std::string::npos);
        CHECK(read(grid_off.data, Format::Off).attributes.vertex.find(io::kRed)->type ==
              ValueType::UInt8);

        // Per-vertex texture coordinates (no seam) go to PLY as texture_u texture_v.
        const Read plain = read(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
            "f 1/1 2/2 3/3\n",
            Format::Obj);
        const Read plain_ply =
            read(write(plain.mesh, plain.attributes, Format::Ply).data, Format::Ply);
        CHECK(io::find_channels(plain_ply.attributes.vertex).has_uv());
        CHECK(plain_ply.attributes.vertex.find("texture_v")->values ==
              std::vector<double>{0, 0, 1});
    }

    TEST_CASE("NaN or infinite values stay out of OBJ and OFF, with a note")
    {
        // A PLY may hold them (a scanner's missing normal); OBJ and OFF readers refuse them.
        const Read ply = read(
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
            "property float y\nproperty float z\nproperty float nx\n"
            "property float ny\nproperty float nz\nproperty float u\n"
            "property float v\nelement face 1\n"
            "property list uchar int vertex_indices\nend_header\n"
            "0 0 0 0 -inf 1 0 0\n1 0 0 0 0 1 nan 0\n0 1 0 0 0 1 0 1\n3 0 1 2\n",
            Format::Ply);
        for (const Format f : {Format::Obj, Format::Off})
        {
            const Written w = write(ply.mesh, ply.attributes, f);
            const std::string name(f == Format::Obj ? "OBJ" : "OFF");
            CHECK(w.notes ==
                  std::vector<std::string>{
                      "normals written as read, not recomputed from the positions written",
                      name + " cannot hold NaN or infinite values: the " +
                          (f == Format::Obj ? "texture coordinates" : "vertex normals") +
                          " are not written",
                      name + " cannot hold NaN or infinite values: the " +
                          (f == Format::Obj ? "normals" : "texture coordinates") +
                          " are not written"});
            const Read back = read(w.data, f); // a file its readers accept
            CHECK(back.mesh == ply.mesh);
            CHECK(back.attributes.empty());
        }
    }

    TEST_CASE("attributes that do not fit the mesh are refused before anything is written")
    {
        const Mesh grid = test::open_grid(1, 1);
        io::MeshAttributes a;
        a.vertex = {"vertex", 3, {test::property("quality", ValueType::Float32, {1, 2, 3})}};
        CHECK_THROWS_WITH_AS(io::write_mesh_data(grid, Format::Ply, {}, &a),
                             "the vertex attributes has 3 rows for a mesh with 4",
                             InvalidInputError);
        a = {};
        a.texcoords = {2, {0, 0}, {0, 0, 0, 1}};
        CHECK_THROWS_WITH_AS(io::write_mesh_data(grid, Format::Obj, {}, &a),
                             "the texture coordinates name entry 1 of 1", InvalidInputError);
    }
}
