// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "tests/helpers.h"

#include <sys/wait.h>

#include <cstdlib>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <stdexcept>

#include <unistd.h>

#include "core/errors.h"
#include "core/geometry/noise.h"

namespace meshfair::test {

std::filesystem::path data_dir()
{
    return MESHFAIR_TEST_DATA_DIR;
}
std::filesystem::path adversarial_dir()
{
    return MESHFAIR_ADVERSARIAL_DIR;
}

std::filesystem::path assets_dir()
{
    return MESHFAIR_ASSETS_DIR;
}

std::filesystem::path temp_dir()
{
    static const std::filesystem::path root = [] {
        auto p = std::filesystem::temp_directory_path() /
                 ("meshfair-tests-" + std::to_string(::getpid()));
        std::filesystem::create_directories(p);
        return p;
    }();
    static struct Cleanup
    {
        ~Cleanup()
        {
            std::error_code ec;
            std::filesystem::remove_all(root, ec);
        }
    } cleanup;
    static int counter = 0;
    auto p = root / ("case-" + std::to_string(counter++));
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}

void write_bytes(const std::filesystem::path& path, const std::string& content)
{
    std::ofstream out(path, std::ios::binary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out)
        throw std::runtime_error("cannot write test file " + path.string());
}

Mesh read_as(const std::string& data, io::Format format, io::ReadReport* report)
{
    return io::read_mesh_data(data, format, "t." + std::string(io::format_name(format)), report);
}

std::string read_error(const std::string& data, io::Format format)
{
    try
    {
        read_as(data, format);
    }
    catch (const FormatError& e)
    {
        return e.what();
    }
    return "accepted";
}

io::Property property(const char* name, io::ValueType type, std::vector<double> values)
{
    return io::Property{name, type, false, io::ValueType::UInt8, std::move(values), {}};
}

Mesh make_mesh(const std::vector<Vec3>& points, const std::vector<std::vector<Index>>& faces)
{
    Mesh m;
    for (const auto& p : points)
        m.add_vertex(p[0], p[1], p[2]);
    for (const auto& f : faces)
        m.add_face(f);
    return m;
}

std::vector<Index> stride_indices(Index n, Index stride, Index first)
{
    std::vector<Index> out;
    for (Index k = first; k < n; k += stride)
        out.push_back(k);
    return out;
}

std::vector<Index> all_indices(Index n)
{
    std::vector<Index> v(n);
    for (Index i = 0; i < n; ++i)
        v[i] = i;
    return v;
}

Mesh tetrahedron()
{
    return make_mesh({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
                     {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
}

Mesh quad_cube()
{
    return make_mesh(
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
        {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
}

Mesh open_grid(int nx, int ny)
{
    Mesh m;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            m.add_vertex(i, j, 0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            const Index a = j * (nx + 1) + i;
            const std::vector<Index> q{a, a + 1, a + nx + 2, a + nx + 1};
            m.add_face(q);
        }
    return m;
}

Mesh nonmanifold_fan()
{
    return make_mesh({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}},
                     {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
}

Mesh two_components()
{
    return make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}},
                     {{0, 1, 2}, {3, 4, 5}});
}

Mesh with_isolated_vertex()
{
    return make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 3, 3}}, {{0, 1, 2}});
}

Mesh quad_torus(int nu, int nv, double R, double r)
{
    Mesh m;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
        {
            const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
            m.add_vertex((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                         r * std::sin(v));
        }
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i)
        {
            auto id = [&](int a, int b) { return static_cast<Index>((b % nv) * nu + (a % nu)); };
            const std::vector<Index> q{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
            m.add_face(q);
        }
    return m;
}

Mesh icosphere(int subdivisions)
{
    const double t = (1 + std::sqrt(5.0)) / 2;
    Mesh m = make_mesh(
        {{-1, t, 0},
         {1, t, 0},
         {-1, -t, 0},
         {1, -t, 0},
         {0, -1, t},
         {0, 1, t},
         {0, -1, -t},
         {0, 1, -t},
         {t, 0, -1},
         {t, 0, 1},
         {-t, 0, -1},
         {-t, 0, 1}},
        {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
         {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
         {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}});
    for (int s = 0; s < subdivisions; ++s)
    {
        Mesh next;
        next.positions = m.positions;
        std::map<std::pair<Index, Index>, Index> mid;
        auto midpoint = [&](Index a, Index b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end())
                return it->second;
            const Vec3 pa = m.position(a), pb = m.position(b);
            const Index v =
                next.add_vertex((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2);
            mid.emplace(key, v);
            return v;
        };
        for (Index f = 0; f < m.face_count(); ++f)
        {
            const auto v = m.face(f);
            const Index a = midpoint(v[0], v[1]), b = midpoint(v[1], v[2]),
                        c = midpoint(v[2], v[0]);
            for (const std::vector<Index>& tri : std::vector<std::vector<Index>>{
                     {v[0], a, c}, {v[1], b, a}, {v[2], c, b}, {a, b, c}})
                next.add_face(tri);
        }
        m = std::move(next);
    }
    for (Index i = 0; i < m.vertex_count(); ++i)
    {
        double* p = &m.positions[3 * i];
        const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int c = 0; c < 3; ++c)
            p[c] /= n;
    }
    return m;
}

Mesh joined(const Mesh& a, const Mesh& b, Vec3 shift)
{
    Mesh m = a;
    const Index offset = m.vertex_count();
    for (Index v = 0; v < b.vertex_count(); ++v)
        m.add_vertex(b.positions[3 * v] + shift[0], b.positions[3 * v + 1] + shift[1],
                     b.positions[3 * v + 2] + shift[2]);
    for (Index f = 0; f < b.face_count(); ++f)
    {
        std::vector<Index> face(b.face(f).begin(), b.face(f).end());
        for (Index& v : face)
            v += offset;
        m.add_face(face);
    }
    return m;
}

std::vector<std::pair<const char*, Mesh>> small_mesh_kinds()
{
    return {{"tetrahedron", tetrahedron()},       {"quad cube", quad_cube()},
            {"open grid", open_grid(4, 3)},       {"non-manifold fan", nonmanifold_fan()},
            {"mixed polygons", mixed_polygons()}, {"isolated vertex", with_isolated_vertex()}};
}

Mesh mixed_polygons()
{
    // A 3x2 patch: quads, two triangles and a pentagon, slightly non-planar.
    return make_mesh({{0, 0, 0},
                      {1, 0, 0.1},
                      {2, 0, 0},
                      {3, 0, 0.2},
                      {0, 1, 0.1},
                      {1, 1, 0},
                      {2, 1, 0.3},
                      {3, 1, 0},
                      {0, 2, 0},
                      {1, 2, 0.2},
                      {2, 2, 0},
                      {3, 2, 0.1},
                      {1.5, 2.6, 0.1}},
                     {{0, 1, 5, 4},
                      {1, 2, 6, 5},
                      {2, 3, 7},
                      {2, 7, 6},
                      {4, 5, 9, 8},
                      {5, 6, 10, 12, 9},
                      {6, 7, 11, 10}});
}

void perturb(Mesh& mesh, double sigma, unsigned seed)
{
    add_gaussian_noise(mesh, sigma, seed);
}

Mesh folded_grid()
{
    Mesh m = open_grid(12, 6);
    for (Index v = 0; v < m.vertex_count(); ++v)
        if (m.positions[3 * v] > 6)
        {
            m.positions[3 * v + 2] = m.positions[3 * v] - 6;
            m.positions[3 * v] = 6;
        }
    return m;
}

Scalar mean_angle_degrees(std::span<const Scalar> u, std::span<const Scalar> clean)
{
    Scalar sum = 0;
    for (size_t f = 0; 3 * f < u.size(); ++f)
    {
        Scalar dot = 0;
        for (int a = 0; a < 3; ++a)
            dot += u[3 * f + a] * clean[3 * f + a];
        sum += std::acos(std::clamp<Scalar>(dot, -1, 1)) * 180 / M_PI;
    }
    return sum / static_cast<Scalar>(u.size() / 3);
}

CommandRun cli(const std::string& args)
{
    return run_command(shell_quote(MESHFAIR_CLI) + " " + args);
}

std::string shell_quote(const std::string& s)
{
    std::string q = "'";
    for (const char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

CommandRun run_command(const std::string& command_line)
{
    static int counter = 0;
    const std::filesystem::path dir = temp_dir();
    const std::filesystem::path out = dir / ("out" + std::to_string(counter)),
                                err = dir / ("err" + std::to_string(counter++));
    const std::string command =
        command_line + " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string());
    const int status = std::system(command.c_str());
    CommandRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = io::read_file(out.string());
    r.err = io::read_file(err.string());
    return r;
}

} // namespace meshfair::test
