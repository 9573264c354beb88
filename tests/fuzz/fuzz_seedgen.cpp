// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Writes the generated seeds: a few small meshes in every format and encoding, written
// by the library itself, into OUT/<kind>/<mesh>.<ext>. Kinds: obj off ply_ascii ply_le
// ply_be stl_ascii stl_binary, and ply_body_{ascii,le,be}: the body of the PLY file
// behind the 3-byte prefix (vertex count, face count, types 0x01 = double coordinates,
// uchar counts, int indices) that fuzz_ply_* expand into a canned header. And recovery/:
// the editor's recovery files of a few sessions on fuzz_recovery's mesh, written by
// write_recovery and packed as fuzz_recovery reads them.
// Usage: fuzz_seedgen OUT

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "app/editor/recovery.h"
#include "core/io/io.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/recovery_input.h"

namespace {

using namespace meshfair;

Mesh make(std::initializer_list<Vec3> points, std::initializer_list<std::vector<Index>> faces)
{
    Mesh m;
    for (const Vec3& p : points)
        m.add_vertex(p[0], p[1], p[2]);
    for (const auto& f : faces)
        m.add_face(f);
    return m;
}

std::vector<std::pair<std::string, Mesh>> meshes()
{
    std::vector<std::pair<std::string, Mesh>> out;
    out.emplace_back("triangle", make({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
    out.emplace_back("quad", make({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}));
    out.emplace_back("tetrahedron", make({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                         {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}));
    out.emplace_back(
        "cube",
        make({{-1, -1, -1},
              {1, -1, -1},
              {1, 1, -1},
              {-1, 1, -1},
              {-1, -1, 1},
              {1, -1, 1},
              {1, 1, 1},
              {-1, 1, 1}},
             {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}));
    // Mixed polygon sizes, awkward numbers, a singular edge (0-1 in three faces) and an
    // isolated vertex.
    out.emplace_back("mixed", make({{-0.0, 0.1, 1.5e10},
                                    {1, 2.5e-7, -3},
                                    {0.3333333333333333, 1, 0},
                                    {2, 2, 2},
                                    {-1, 0.5, 0.25},
                                    {0.5, -1, 0.125},
                                    {1e-300, 0, 0},
                                    {3, 1, 4}},
                                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4, 5}, {2, 1, 7, 3, 4}}));
    out.emplace_back("points", make({{0, 0, 0}, {1, 2, 3}, {-4, 5, -6}}, {}));
    out.emplace_back("empty", Mesh{});
    // A polygon of 300 corners: PLY writes its face counts as uint.
    Mesh disk;
    disk.add_vertex(0, 0, 0);
    std::vector<Index> ring;
    for (int k = 0; k < 300; ++k)
    {
        const double a = 2 * 3.141592653589793 * k / 300;
        ring.push_back(disk.add_vertex(std::cos(a), std::sin(a), 0));
    }
    disk.add_face(ring);
    out.emplace_back("long-face", std::move(disk));
    return out;
}

void write(const std::filesystem::path& path, const std::string& data)
{
    std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out)
        throw std::runtime_error("cannot write " + path.string());
}

// Sessions on small_mesh: untouched; and edited, with a set of every kind (targets,
// normals, weight maps, weights of their own) and every solver option set.
std::vector<std::pair<std::string, app::Document>> sessions()
{
    using namespace app;
    std::vector<std::pair<std::string, Document>> out;
    Document d = make_document(fuzz::small_mesh(), "/fuzz/mesh.obj");
    out.emplace_back("untouched", d);
    d.mesh.positions[4] += 0.25;
    d.base_positions[7] -= 0.5;
    d.selected_vertices[3] = 1;
    d.selected_faces[2] = 1;
    d.sets = {{"region",
               ConstraintKind::Region,
               {0, 1, 2, 3},
               {},
               {},
               {},
               {1, 0, 0},
               true,
               true,
               std::nullopt,
               {1, 0.5, 0.25, 1}},
              {"faces",
               ConstraintKind::Region,
               {},
               {4, 5},
               {},
               {},
               {1, 0, 1},
               true,
               true,
               std::nullopt,
               {}},
              {"pins",
               ConstraintKind::Pin,
               {4, 8},
               {},
               {{0, 0, 1.5}, {0.5, 2, 0.5}},
               {},
               {0, 1, 0},
               true,
               true,
               std::nullopt,
               {}},
              {"anchors",
               ConstraintKind::Anchor,
               {5, 6, 9},
               {},
               {},
               {},
               {0, 0, 1},
               false,
               true,
               2.5,
               {1, 2, 0}},
              {"centroids",
               ConstraintKind::Centroid,
               {},
               {0, 1},
               {},
               {},
               {1, 1, 0},
               true,
               true,
               std::nullopt,
               {}},
              {"up",
               ConstraintKind::Normal,
               {},
               {2, 3},
               {},
               {{0, 1, 0}, {0, 0.6, 0.8}},
               {0, 1, 1},
               true,
               false,
               0.5,
               {}},
              {"hard",
               ConstraintKind::HardNormal,
               {},
               {6},
               {},
               {},
               {0.5, 0.5, 0.5},
               true,
               true,
               std::nullopt,
               {}},
              {"soft",
               ConstraintKind::SoftNormal,
               {},
               {7},
               {},
               {},
               {0.2, 0.4, 0.6},
               true,
               true,
               3.0,
               {}}};
    d.solver.lambda = 0.25;
    d.solver.iterations_per_frame = 3;
    d.solver.normal_source = NormalSource::Smoothed;
    d.solver.joint = true;
    d.solver.denominator = CentroidDenominator::Exact;
    d.solver.method = Method::Taubin;
    d.solver.bilateral = BilateralWeights{2.0, 0.3, 3, FaceNeighborhood::Vertex, 1.0};
    d.solver.keep_volume = true;
    d.solver.falloff = Falloff{5.0, false, FalloffCurve::Sharp, 2.0, true, false};
    d.steps_from_base = 17;
    d.reproducible = false;
    out.emplace_back("edited", d);
    d.solver.optimal_step = true;
    d.solver.method = Method::Jacobi;
    d.solver.bilateral.reset();
    d.solver.falloff.reset();
    out.emplace_back("optimal", d);
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: %s OUT\n", argv[0]);
        return 2;
    }
    const std::filesystem::path out = argv[1];
    using io::Encoding;
    using io::Format;
    struct Kind
    {
        const char* dir;
        Format format;
        Encoding encoding;
        const char* ext;
    };
    const Kind kinds[] = {{"obj", Format::Obj, Encoding::Ascii, "obj"},
                          {"off", Format::Off, Encoding::Ascii, "off"},
                          {"ply_ascii", Format::Ply, Encoding::Ascii, "ply"},
                          {"ply_le", Format::Ply, Encoding::BinaryLittleEndian, "ply"},
                          {"ply_be", Format::Ply, Encoding::BinaryBigEndian, "ply"},
                          {"stl_ascii", Format::Stl, Encoding::Ascii, "stl"},
                          {"stl_binary", Format::Stl, Encoding::BinaryLittleEndian, "stl"}};
    int files = 0;
    for (const auto& [name, mesh] : meshes())
        for (const Kind& kind : kinds)
        {
            const std::string data = io::write_mesh_data(mesh, kind.format, {kind.encoding});
            write(out / kind.dir / (name + "." + kind.ext), data);
            ++files;
            const std::string marker = "end_header\n";
            const size_t body = data.find(marker);
            if (kind.format != Format::Ply || body == std::string::npos ||
                mesh.vertex_count() > 255 || mesh.face_count() > 255)
                continue;
            std::string prefixed = {static_cast<char>(mesh.vertex_count()),
                                    static_cast<char>(mesh.face_count()), '\x01'};
            prefixed += data.substr(body + marker.size());
            write(out / (std::string("ply_body_") + (kind.dir + 4)) / (name + ".body"), prefixed);
            ++files;
        }
    const std::filesystem::path root = out / "recovery-folders";
    for (const auto& [name, document] : sessions())
    {
        app::write_recovery(document, (root / name).string());
        for (const auto& entry : std::filesystem::directory_iterator(root / name))
        {
            const auto file = [&](const char* f) {
                return io::read_file((entry.path() / f).string());
            };
            const app::RecoveryFiles packed{entry.path().string(), file("state.json"),
                                            file("positions.bin"), file("base.bin"),
                                            file("selection.bin")};
            write(out / "recovery" / (name + ".bin"), fuzz::recovery_input(packed));
            ++files;
        }
    }
    std::filesystem::remove_all(root);
    std::printf("fuzz_seedgen: wrote %d seeds under %s\n", files, out.c_str());
    return 0;
}
