// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Writes the generated seeds: a few small meshes in every format and encoding, written
// by the library itself, into OUT/<kind>/<mesh>.<ext>. Kinds: obj off ply_ascii ply_le
// ply_be stl_ascii stl_binary, and ply_body_{ascii,le,be}: the body of the PLY file
// behind the 3-byte prefix (vertex count, face count, types 0x01 = double coordinates,
// uchar counts, int indices) that fuzz_ply_* expand into a canned header.
// Usage: fuzz_seedgen OUT

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/io/io.h"

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
    std::printf("fuzz_seedgen: wrote %d seeds under %s\n", files, out.c_str());
    return 0;
}
