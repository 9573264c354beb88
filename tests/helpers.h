// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/io/io.h"
#include "core/mesh/mesh.h"
#include "core/parallel/parallel.h"

namespace meshfair::test {

//! tests/data (small hand-written files).
std::filesystem::path data_dir();
//! assets/ (the bundled meshes).
std::filesystem::path assets_dir();
//! tests/adversarial (hostile input files, one folder per format).
std::filesystem::path adversarial_dir();
//! A fresh, empty directory for the calling test case, removed at exit.
std::filesystem::path temp_dir();

//! What a command printed and how it ended.
struct CommandRun
{
    int code = -1; //!< exit code, -1 when killed by a signal
    std::string out, err;
};
//! \brief Runs a shell command line with stdout and stderr captured (in the test's temp
//! dir).
CommandRun run_command(const std::string& command_line);
//! meshfair-cli run with `args` (already quoted for the shell), as run_command runs it.
CommandRun cli(const std::string& args);
//! `s` quoted for the shell.
std::string shell_quote(const std::string& s);

//! Writes `content` to `path` byte for byte.
void write_bytes(const std::filesystem::path& path, const std::string& content);

//! Reads `data` as `format`, naming it "t.obj", "t.off", ... in messages.
Mesh read_as(const std::string& data, io::Format format, io::ReadReport* report = nullptr);
//! The message of the FormatError that reading `data` raises, or "accepted".
std::string read_error(const std::string& data, io::Format format);

//! A scalar attribute property: its name, type and one value per row.
io::Property property(const char* name, io::ValueType type, std::vector<double> values);

//! A mesh from points and faces.
Mesh make_mesh(const std::vector<Vec3>& points, const std::vector<std::vector<Index>>& faces);
//! 0, 1, ..., n - 1.
std::vector<Index> all_indices(Index n);
//! first, first + stride, ... below n: every stride-th element of a set.
std::vector<Index> stride_indices(Index n, Index stride, Index first = 0);

// Synthetic meshes (pmp-style fixtures).
Mesh tetrahedron();             //!< 4 vertices, 4 triangles, closed
Mesh quad_cube();               //!< 8 vertices, 6 quads, closed
Mesh open_grid(int nx, int ny); //!< (nx+1)(ny+1) vertices, nx*ny quads in z = 0
Mesh nonmanifold_fan();         //!< 3 triangles sharing one edge
Mesh two_components();          //!< two disjoint triangles
Mesh with_isolated_vertex();    //!< a triangle plus an unused vertex
Mesh quad_torus(int nu, int nv, double R, double r); //!< closed quad torus
Mesh icosphere(int subdivisions);                    //!< subdivided icosahedron on the unit sphere
Mesh mixed_polygons(); //!< open patch of triangles, quads and a pentagon
//! One small mesh of each kind a term must take, named: closed triangles and quads, an open
//! grid, a non-manifold fan, mixed polygons, an isolated vertex.
std::vector<std::pair<const char*, Mesh>> small_mesh_kinds();
//! b's vertices and faces after a's (two components when apart), b moved by `shift`.
Mesh joined(const Mesh& a, const Mesh& b, Vec3 shift);

//! a . b
inline Scalar dot(const Vec3& a, const Vec3& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

//! Restores the default thread count when a test case ends, whatever happens.
struct ThreadCountGuard
{
    ~ThreadCountGuard() { set_thread_count(0); }
};

//! Adds deterministic Gaussian noise (sigma in absolute units).
void perturb(Mesh& mesh, double sigma, unsigned seed);

//! An open grid of 12 x 6 quads folded at x = 6 into an L: a flat floor and a vertical
//! wall meeting at a 90 degree crease.
Mesh folded_grid();

//! The mean angle in degrees between the unit normals u and clean (3 per face).
Scalar mean_angle_degrees(std::span<const Scalar> u, std::span<const Scalar> clean);

} // namespace meshfair::test
