// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <utility>

#include "app/bench/quality_meshes.h"
#include "app/bench/quality_metrics.h"
#include "app/bench/quality_noise.h"
#include "app/bench/reference_filters.h"
#include "app/bench/sdfilter_peer.h"
#include "core/energies/volume_constraint.h"
#include "core/geometry/face_geometry.h"
#include "core/topology/topology.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::bench;
using namespace meshfair::test;

namespace {

Scalar edge_length(const Mesh& m, const Topology& t, Index e)
{
    const Vec3 p = m.position(t.edge_vertices[2 * e]), q = m.position(t.edge_vertices[2 * e + 1]);
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

// Closed (every edge has two faces), consistently oriented (each directed edge once, its
// reverse once), vertex-manifold (the faces around each vertex form one fan) and a sphere
// (V - E + F = 2).
void check_closed_oriented_manifold(const Mesh& m)
{
    const Topology t = build_topology(m);
    CHECK(t.boundary_edge_count == 0);
    CHECK(t.singular_edge_count == 0);
    CHECK(t.vertex_count - t.edge_count() + m.face_count() == 2);
    std::map<std::pair<Index, Index>, int> directed;
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const auto face = m.face(f);
        for (size_t k = 0; k < face.size(); ++k)
            ++directed[{face[k], face[(k + 1) % face.size()]}];
    }
    bool is_oriented = true;
    for (const auto& [edge, count] : directed)
        is_oriented = is_oriented && count == 1 && directed.contains({edge.second, edge.first});
    CHECK(is_oriented);
    // Around vertex v, each face maps its corner's previous vertex to its next one; one
    // cycle through all of them is one fan.
    bool is_manifold = true;
    for (Index v = 0; v < m.vertex_count() && is_manifold; ++v)
    {
        std::map<Index, Index> next_of;
        for (const Index corner : t.corners_of_vertex(v))
        {
            const CornerNeighbors n = corner_neighbors(m, t, corner);
            next_of[n.previous] = n.next;
        }
        Index at = next_of.begin()->first;
        size_t steps = 0;
        do
        {
            at = next_of.contains(at) ? next_of[at] : kInvalidIndex;
            ++steps;
        } while (at != next_of.begin()->first && at != kInvalidIndex && steps <= next_of.size());
        is_manifold = at != kInvalidIndex && steps == next_of.size() &&
                      next_of.size() == t.corners_of_vertex(v).size();
    }
    CHECK(is_manifold);
}

// A copy of x rotated by `angle` about the axis through `origin` along unit `axis`.
std::vector<Scalar> rotated(std::span<const Scalar> x, const Vec3& axis, Scalar angle,
                            const Vec3& origin = {0, 0, 0})
{
    const Scalar c = std::cos(angle), s = std::sin(angle);
    std::vector<Scalar> y(x.size());
    for (size_t i = 0; i < x.size(); i += 3)
    {
        const Vec3 p{x[i] - origin[0], x[i + 1] - origin[1], x[i + 2] - origin[2]};
        const Scalar d = axis[0] * p[0] + axis[1] * p[1] + axis[2] * p[2];
        const Vec3 k{axis[1] * p[2] - axis[2] * p[1], axis[2] * p[0] - axis[0] * p[2],
                     axis[0] * p[1] - axis[1] * p[0]};
        for (int a = 0; a < 3; ++a) // Rodrigues
            y[i + a] = origin[a] + p[a] * c + k[a] * s + axis[a] * d * (1 - c);
    }
    return y;
}

// Mean angle between the normals of the faces with a corner on a crease of the cube
// [-1, 1]^3 (two coordinates at +-1).
Scalar crease_normal_angle_deg(const Mesh& m, std::span<const Scalar> x)
{
    Scalar sum = 0;
    int count = 0;
    for (Index f = 0; f < m.face_count(); ++f)
    {
        bool on_crease = false;
        for (const Index v : m.face(f))
        {
            int at_side = 0;
            for (int a = 0; a < 3; ++a)
                at_side += std::abs(std::abs(m.positions[3 * v + a]) - 1) < 1e-12;
            on_crease = on_crease || at_side >= 2;
        }
        if (!on_crease)
            continue;
        const Vec3 n = face_normal(m, x, f), n0 = face_normal(m, m.positions, f);
        sum += std::acos(std::clamp(n[0] * n0[0] + n[1] * n0[1] + n[2] * n0[2], -1.0, 1.0));
        ++count;
    }
    return sum / count * 180 / std::numbers::pi;
}

} // namespace

TEST_SUITE("QualityMeshes")
{
    TEST_CASE("every generated mesh is a closed, oriented 2-manifold with near-uniform edges")
    {
        for (const std::string& name : generated_mesh_names())
        {
            CAPTURE(name);
            if (name == "scan-patch" || name == "holed-part")
                continue; // open: the next test case
            const Mesh m = generated_mesh(name);
            validate_mesh(m);
            check_closed_oriented_manifold(m);
            CHECK(m.vertex_count() >= 5000);
            CHECK(m.vertex_count() <= 20000);
            CHECK(signed_volume(m, m.positions) > 0);
            // Near-uniform: the cube's and quad box's grids have diagonals (sqrt 2) and the
            // rounded box's edges shrink on its rounds, so only a band is asked for.
            const Topology t = build_topology(m);
            const Scalar mean = mean_edge_length(t, m.positions);
            Scalar shortest = mean, longest = mean, variance = 0;
            for (Index e = 0; e < t.edge_count(); ++e)
            {
                const Scalar l = edge_length(m, t, e);
                shortest = std::min(shortest, l), longest = std::max(longest, l);
                variance += (l - mean) * (l - mean) / t.edge_count();
            }
            MESSAGE(name, ": ", m.vertex_count(), " vertices, edges ", shortest / mean, " - ",
                    longest / mean, " of the mean, cv ", std::sqrt(variance) / mean);
            CHECK(shortest > 0.35 * mean);
            CHECK(longest < 1.8 * mean);
            CHECK(std::sqrt(variance) < 0.2 * mean);
        }
        CHECK_THROWS_AS(generated_mesh("sphere"), std::invalid_argument);
    }

    TEST_CASE("the scan patch is an open disk facing up, the holed part the part with six holes")
    {
        const auto check_open = [](const Mesh& m, Index loops) {
            validate_mesh(m);
            const Topology t = build_topology(m);
            CHECK(t.singular_edge_count == 0);
            CHECK(t.boundary_edge_count > 0);
            // A sphere with `loops` holes: V - E + F = 2 - loops; each directed edge once.
            CHECK(t.vertex_count - t.edge_count() + m.face_count() == 2 - loops);
            std::map<std::pair<Index, Index>, int> directed;
            for (Index f = 0; f < m.face_count(); ++f)
                for (size_t k = 0; k < m.face(f).size(); ++k)
                    ++directed[{m.face(f)[k], m.face(f)[(k + 1) % m.face(f).size()]}];
            CHECK(std::ranges::all_of(directed, [](const auto& e) { return e.second == 1; }));
            const VolumeConstraint v(m, t, m.positions,
                                     std::vector<char>(static_cast<size_t>(m.vertex_count()), 0));
            CHECK(v.loop_count() == loops);
            CHECK(m.vertex_count() >= 5000);
            CHECK(m.vertex_count() <= 20000);
        };
        const Mesh patch = scan_patch_mesh();
        check_open(patch, 1);
        for (Index f = 0; f < patch.face_count(); ++f)
            CHECK(face_normal(patch, patch.positions, f)[2] > 0.5);
        const Mesh holed = holed_part_mesh();
        check_open(holed, 6);
        // The holes' caps stand in for the faces cut away: the capped volume is the part's
        // to the few per mille the cut corner's and creases' caps miss.
        const Mesh part = cad_part_mesh();
        const Scalar closed = signed_volume(part, part.positions);
        const Topology t = build_topology(holed);
        const Scalar capped = capped_volume(holed, t, holed.positions);
        CHECK(std::abs(capped - closed) < 0.005 * closed);
    }

    TEST_CASE("the cube's volume is side^3")
    {
        CHECK(std::abs(signed_volume(cube_mesh(), cube_mesh().positions) - 8) < 1e-9);
        const Mesh small = cube_mesh(7, 1.5);
        CHECK(std::abs(signed_volume(small, small.positions) - 1.5 * 1.5 * 1.5) < 1e-9);
        CHECK(small.vertex_count() == 6 * 7 * 7 + 2);
    }

    TEST_CASE("the cylinder's and cut sphere's volumes are within the inscribed-polygon deficit")
    {
        // Every vertex lies on the exact surface and the solid is convex, so the mesh is
        // inside it: V_mesh < V. A ring of n points encloses (n / 2pi) sin(2pi / n) of its
        // circle's area, 1 - (2pi/n)^2 / 6 to leading order, and a chord of the sphere's
        // meridian misses the same share of the arc; with a / r = edge / radius for the ring
        // closest to the axis of the curved part (largest loss), the volume lost is at most
        // two such shares.
        const Scalar edge = 0.045;
        const Mesh cylinder = cylinder_mesh(1, 2, edge);
        const Scalar v_cylinder = std::numbers::pi * 2;
        const Scalar loss_cylinder = 1 - signed_volume(cylinder, cylinder.positions) / v_cylinder;
        MESSAGE("cylinder: relative volume loss ", loss_cylinder);
        CHECK(loss_cylinder > 0);
        CHECK(loss_cylinder < 2 * edge * edge / 6);

        const Mesh sphere = cut_sphere_mesh(1, -0.5, 0.7, 0.04);
        const auto primitive = [](Scalar z) { return std::numbers::pi * (z - z * z * z / 3); };
        const Scalar v_sphere = primitive(0.7) - primitive(-0.5);
        const Scalar rho_min = std::sqrt(1 - 0.7 * 0.7);
        const Scalar loss_sphere = 1 - signed_volume(sphere, sphere.positions) / v_sphere;
        MESSAGE("cut sphere: relative volume loss ", loss_sphere);
        CHECK(loss_sphere > 0);
        CHECK(loss_sphere < 2 * std::pow(0.04 / rho_min, 2) / 6);
    }

    TEST_CASE("the CAD part has the polyhedron's volume and creases of the designed angles")
    {
        const Mesh m = cad_part_mesh();
        // Block 2 x 1.5 x 1, minus the chamfer's prism (0.3 x 0.3 / 2 x 2), the bevel's
        // (0.6 x 0.35 / 2 x 2) and the corner's tetrahedron (0.5^3 / 6); they do not overlap.
        const Scalar volume = 3 - 0.09 - 0.21 - 0.125 / 6;
        CHECK(std::abs(signed_volume(m, m.positions) - volume) < 1e-9);

        const Topology t = build_topology(m);
        const std::vector<Scalar> angles = dihedral_angles_deg(m, t, m.positions);
        const Scalar deg = 180 / std::numbers::pi;
        const Scalar bevel = std::atan2(0.35, 0.6) * deg;
        const std::vector<Scalar> designed = {
            0, 45, 90, bevel, 90 - bevel, std::acos(1 / std::sqrt(3.0)) * deg};
        std::vector<int> count(designed.size(), 0);
        std::vector<int> creases_at(static_cast<size_t>(m.vertex_count()), 0);
        bool all_designed = true;
        for (Index e = 0; e < t.edge_count(); ++e)
        {
            size_t k = 0;
            while (k < designed.size() && std::abs(angles[e] - designed[k]) > 1e-6)
                ++k;
            all_designed = all_designed && k < designed.size();
            if (k < designed.size())
                ++count[k];
            if (angles[e] > 1)
                ++creases_at[t.edge_vertices[2 * e]], ++creases_at[t.edge_vertices[2 * e + 1]];
        }
        CHECK(all_designed);
        for (size_t k = 0; k < designed.size(); ++k)
        {
            CAPTURE(designed[k]);
            CHECK(count[k] > 0);
        }
        // Corners where three creases meet: the block's six untouched corners, the chamfer's,
        // bevel's and corner cut's ends (each crease reaching a vertex counts twice there).
        const auto corners = std::count(creases_at.begin(), creases_at.end(), 3);
        CHECK(corners >= 8);
    }

    TEST_CASE("the quad box stays all quads")
    {
        const Mesh m = rounded_box_quad_mesh(12, 0.3);
        check_closed_oriented_manifold(m);
        CHECK(m.corner_count() == 4 * m.face_count());
        CHECK(m.face_count() == 6 * 12 * 12);
        // Every vertex is at the rounding radius from the inner box [-0.7, 0.7]^3.
        for (Index i = 0; i < m.vertex_count(); ++i)
        {
            const Vec3 p = m.position(i);
            Scalar outside2 = 0;
            for (int a = 0; a < 3; ++a)
                outside2 += std::pow(std::max(0.0, std::abs(p[a]) - 0.7), 2);
            CHECK(std::sqrt(outside2) == doctest::Approx(0.3).epsilon(1e-12));
        }
    }
}

TEST_SUITE("QualityNoise")
{
    TEST_CASE("noise is fixed by the seed")
    {
        const Mesh m = cube_mesh(10);
        for (const NoiseCase& noise : standard_noise_cases())
        {
            CAPTURE(noise_name(noise.model));
            const std::vector<Scalar> a = noisy_positions(m, noise, 7);
            CHECK(noisy_positions(m, noise, 7) == a);
            CHECK(noisy_positions(m, noise, 8) != a);
            CHECK(a != m.positions);
        }
        CHECK(standard_noise_cases().size() == 10);
        CHECK_THROWS_AS(noisy_positions(m, {NoiseModel::GaussianNormal, -1}, 1),
                        std::invalid_argument);
    }

    TEST_CASE("each model has its scale and direction")
    {
        const Mesh m = cube_mesh();
        const Topology t = build_topology(m);
        const Scalar edge = mean_edge_length(t, m.positions);
        const std::vector<Scalar> normals = vertex_normals(m, m.positions);
        const Index nv = m.vertex_count();
        // Per vertex: the offset's component along the clean normal and across it.
        const auto split = [&](const std::vector<Scalar>& x, Index i) {
            Vec3 d;
            Scalar along = 0;
            for (int a = 0; a < 3; ++a)
            {
                d[a] = x[3 * i + a] - m.positions[3 * i + a];
                along += d[a] * normals[3 * i + a];
            }
            Scalar across2 = 0;
            for (int a = 0; a < 3; ++a)
                across2 += std::pow(d[a] - along * normals[3 * i + a], 2);
            return std::pair{along, std::sqrt(across2)};
        };
        // With 9602 samples the sample standard deviation is within 0.8% of sigma (one
        // standard error); 3% leaves four.
        const Scalar sigma = 0.4 * edge;
        {
            const std::vector<Scalar> x = noisy_positions(m, {NoiseModel::GaussianNormal, 0.4}, 3);
            Scalar sum2 = 0, across = 0;
            for (Index i = 0; i < nv; ++i)
            {
                const auto [along, off] = split(x, i);
                sum2 += along * along;
                across = std::max(across, off);
            }
            CHECK(std::sqrt(sum2 / nv) == doctest::Approx(sigma).epsilon(0.03));
            CHECK(across < 1e-12);
        }
        {
            // Random directions: the same root-mean-square length, a third of the variance
            // along the normal.
            const std::vector<Scalar> x = noisy_positions(m, {NoiseModel::GaussianRandom, 0.4}, 3);
            Scalar along2 = 0, length2 = 0;
            for (Index i = 0; i < nv; ++i)
            {
                const auto [along, off] = split(x, i);
                along2 += along * along;
                length2 += along * along + off * off;
            }
            CHECK(std::sqrt(length2 / nv) == doctest::Approx(sigma).epsilon(0.03));
            CHECK(along2 / length2 == doctest::Approx(1.0 / 3).epsilon(0.06));
        }
        {
            const std::vector<Scalar> x = noisy_positions(m, {NoiseModel::Impulsive, 0.7}, 3);
            int moved = 0, up = 0;
            bool exact = true;
            for (Index i = 0; i < nv; ++i)
            {
                const auto [along, off] = split(x, i);
                if (along == 0 && off == 0)
                    continue;
                ++moved;
                up += along > 0;
                exact = exact && std::abs(std::abs(along) - 0.7 * edge) < 1e-12 && off < 1e-12;
            }
            CHECK(moved == std::lround(0.1 * nv));
            CHECK(exact);
            CHECK(up > moved / 3);
            CHECK(up < 2 * moved / 3);
        }
        {
            // Along the scanner's line of sight: every offset parallel to it, of RMS sigma.
            const std::vector<Scalar> x = noisy_positions(m, {NoiseModel::GaussianScan, 0.4}, 3);
            Scalar sum2 = 0, across = 0;
            for (Index i = 0; i < nv; ++i)
            {
                Vec3 d;
                for (int a = 0; a < 3; ++a)
                    d[a] = x[3 * i + a] - m.positions[3 * i + a];
                const Scalar along =
                    d[0] * kScanDirection[0] + d[1] * kScanDirection[1] + d[2] * kScanDirection[2];
                sum2 += along * along;
                for (int a = 0; a < 3; ++a)
                    across = std::max(across, std::abs(d[a] - along * kScanDirection[a]));
            }
            CHECK(std::sqrt(sum2 / nv) == doctest::Approx(sigma).epsilon(0.03));
            CHECK(across < 1e-12);
        }
    }
}

TEST_SUITE("QualityMetrics")
{
    TEST_CASE("an unchanged mesh scores zero")
    {
        for (const Mesh& m :
             {cube_mesh(12), cut_sphere_mesh(1, -0.5, 0.7, 0.1), rounded_box_quad_mesh(8, 0.3)})
        {
            const SurfaceDistance clean(m, m.positions);
            CHECK(mean_normal_angle_deg(m, m.positions, m.positions) == 0);
            CHECK(mean_relative_distance(clean, m.positions) == 0);
            CHECK(volume_change_percent(m, m.positions, m.positions) == 0);
        }
    }

    TEST_CASE("a face turned over counts where it lay in the surface, not where it was a fold")
    {
        // A flat grid: its middle vertex pushed through the plane turns its faces by 180
        // degrees far beyond their neighbours' 90; a grid with a face folded in the input
        // does not count that face when it turns back.
        Mesh grid = open_grid(4, 4);
        std::vector<Scalar> x = grid.positions;
        const Index middle = 2 * 5 + 2;
        x[3 * middle] += 3; // across the whole ring: the star's faces reverse
        const Index turned = turned_over_faces(grid, x, grid.positions);
        CHECK(turned > 0);
        CHECK(turned_over_faces(grid, grid.positions, grid.positions) == 0);
        // The turned shape as the input: its reversed faces are folds, and turning them
        // back is not turning faces over.
        CHECK(turned_over_faces(grid, grid.positions, x) == 0);
    }

    TEST_CASE("theta of a rigidly rotated face is the rotation angle")
    {
        const Mesh triangle = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        const Mesh quad = make_mesh({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
        for (const Mesh* m : {&triangle, &quad})
            for (const Scalar degrees : {0.5, 10.0, 37.0, 90.0, 150.0})
            {
                const Scalar angle = degrees * std::numbers::pi / 180;
                // About an axis in the face's plane: the normal turns by the angle; about the
                // normal it does not turn.
                const Vec3 axis{std::sqrt(0.5), std::sqrt(0.5), 0};
                CHECK(mean_normal_angle_deg(*m, rotated(m->positions, axis, angle), m->positions) ==
                      doctest::Approx(degrees).epsilon(1e-12));
                CHECK(mean_normal_angle_deg(*m, rotated(m->positions, {0, 0, 1}, angle),
                                            m->positions) < 1e-12);
            }
    }

    TEST_CASE("E_v of an offset along a flat face's normal is the offset over the diagonal")
    {
        const Mesh grid = open_grid(10, 6);
        const SurfaceDistance clean(grid, grid.positions);
        CHECK(clean.diagonal() == doctest::Approx(std::hypot(10.0, 6.0)));
        const Scalar d = 0.37;
        std::vector<Scalar> x = grid.positions;
        for (size_t k = 2; k < x.size(); k += 3)
            x[k] += d;
        CHECK(mean_relative_distance(clean, x) == doctest::Approx(d / clean.diagonal()));
        // One interior vertex moved: its distance is d, the mean is d / #V.
        x = grid.positions;
        const Index v = 3 * 11 + 4;
        x[3 * v + 2] -= d;
        CHECK(clean.distance(Vec3{x[3 * v], x[3 * v + 1], x[3 * v + 2]}) ==
              doctest::Approx(d).epsilon(1e-14));
        CHECK(mean_relative_distance(clean, x) ==
              doctest::Approx(d / clean.diagonal() / grid.vertex_count()));
    }

    TEST_CASE("the grid's nearest-surface distance equals the brute-force minimum")
    {
        const Mesh m = cut_sphere_mesh(1, -0.5, 0.7, 0.1);
        const SurfaceDistance clean(m, m.positions);
        std::mt19937_64 random(5);
        std::uniform_real_distribution<Scalar> coordinate(-1.6, 1.6);
        for (int k = 0; k < 300; ++k)
        {
            const Vec3 p{coordinate(random), coordinate(random), coordinate(random)};
            Scalar brute = std::numeric_limits<Scalar>::infinity();
            for (Index f = 0; f < m.face_count(); ++f)
            {
                const auto face = m.face(f);
                brute = std::min(
                    brute, point_triangle_distance(p, m.position(face[0]), m.position(face[1]),
                                                   m.position(face[2])));
            }
            CHECK(clean.distance(p) == brute);
        }
        // The closest point's regions: a vertex, an edge and the face.
        const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
        CHECK(point_triangle_distance({-1, -1, 0}, a, b, c) == doctest::Approx(std::sqrt(2.0)));
        CHECK(point_triangle_distance({0.5, -2, 0}, a, b, c) == doctest::Approx(2));
        CHECK(point_triangle_distance({1, 1, 0}, a, b, c) == doctest::Approx(std::sqrt(0.5)));
        CHECK(point_triangle_distance({0.2, 0.2, -3}, a, b, c) == doctest::Approx(3));
    }

    TEST_CASE("dV of a uniform scaling is the cube of the factor")
    {
        const Mesh m = cylinder_mesh(1, 2, 0.2);
        std::vector<Scalar> x = m.positions;
        for (Scalar& v : x)
            v = 1.01 * v + 0.5; // scaled and moved
        CHECK(volume_change_percent(m, x, m.positions) ==
              doctest::Approx(100 * (std::pow(1.01, 3) - 1)).epsilon(1e-9));
    }

    TEST_CASE("percentile by nearest rank")
    {
        std::vector<Scalar> v;
        for (int k = 20; k >= 1; --k)
            v.push_back(k);
        CHECK(percentile(v, 95) == 19);
        CHECK(percentile(v, 100) == 20);
        CHECK(percentile(v, 5) == 1);
        CHECK(percentile(v, 50) == 10);
        CHECK(std::isnan(percentile({}, 95)));
    }

    TEST_CASE("the seam figure is zero on a flat grid and sees a fold at the border")
    {
        const Mesh grid = open_grid(20, 20);
        const Topology t = build_topology(grid);
        // The region: x < 10 (the vertices with x = 9 form its border ring).
        std::vector<Index> region;
        for (Index i = 0; i < grid.vertex_count(); ++i)
            if (grid.positions[3 * i] < 9.5)
                region.push_back(i);
        const SeamFigure flat = seam_figure(grid, t, grid.positions, region);
        CHECK(flat.border_p95_deg == 0);
        CHECK(flat.inner_border_p95_deg == 0);
        CHECK(flat.interior_p95_deg == 0);
        // Border rings: the edges with an end at x = 7 .. 11; interior: both ends in x <= 6.
        // Only edges with two faces count: a column x = 1 .. 19 has 20 vertical ones, a gap
        // between columns 19 horizontal ones (not those at y = 0 and 20).
        CHECK(flat.border_edges == 5 * 20 + 6 * 19);
        CHECK(flat.inner_border_edges == 3 * 20 + 3 * 19);
        CHECK(flat.interior_edges == 6 * 20 + 6 * 19);

        // Fold the outside up by 30 degrees along x = 10: only the border rings see it.
        std::vector<Scalar> x = grid.positions;
        const Scalar angle = 30 * std::numbers::pi / 180;
        for (Index i = 0; i < grid.vertex_count(); ++i)
            if (x[3 * i] > 10)
            {
                const Scalar u = x[3 * i] - 10;
                x[3 * i] = 10 + u * std::cos(angle);
                x[3 * i + 2] = u * std::sin(angle);
            }
        const SeamFigure folded = seam_figure(grid, t, x, region);
        CHECK(folded.border_p95_deg == doctest::Approx(30));
        CHECK(folded.interior_p95_deg == 0);
        CHECK(folded.inner_border_p95_deg == 0);
    }
}

TEST_SUITE("ReferenceFilters")
{
    TEST_CASE("the bilateral filter lowers theta and keeps the cube's creases better than Taubin")
    {
        const Mesh m = cube_mesh(16);
        const Topology t = build_topology(m);
        const std::vector<Scalar> noisy = noisy_positions(m, {NoiseModel::GaussianNormal, 0.2}, 11);
        std::vector<Scalar> bilateral = noisy, taubin = noisy;
        bilateral_normal_filter(m, t, bilateral);
        taubin_smooth(t, taubin);
        const Scalar theta_noisy = mean_normal_angle_deg(m, noisy, m.positions);
        const Scalar theta_bilateral = mean_normal_angle_deg(m, bilateral, m.positions);
        const Scalar theta_taubin = mean_normal_angle_deg(m, taubin, m.positions);
        const Scalar crease_bilateral = crease_normal_angle_deg(m, bilateral);
        const Scalar crease_taubin = crease_normal_angle_deg(m, taubin);
        MESSAGE("theta noisy ", theta_noisy, ", bilateral ", theta_bilateral, ", taubin ",
                theta_taubin, "; at the creases bilateral ", crease_bilateral, ", taubin ",
                crease_taubin);
        CHECK(theta_bilateral < 0.3 * theta_noisy);
        CHECK(theta_bilateral < 0.7 * theta_taubin);
        CHECK(crease_bilateral < 0.5 * crease_taubin);
    }

    TEST_CASE("the bilateral filter keeps a flat grid and nearly keeps a clean cube")
    {
        const Mesh grid = open_grid(8, 5);
        const Topology grid_topology = build_topology(grid);
        std::vector<Scalar> x = grid.positions;
        bilateral_normal_filter(grid, grid_topology, x);
        CHECK(x == grid.positions);
        // Across a crease |n_f - n_g| = sqrt 2: W_r = exp(-2 / (2 0.35^2)), 3e-4, tilts the
        // crease faces' normals a little.
        const Mesh cube = cube_mesh(6);
        std::vector<Scalar> y = cube.positions;
        bilateral_normal_filter(cube, build_topology(cube), y);
        CHECK(mean_normal_angle_deg(cube, y, cube.positions) < 0.1);
    }

    TEST_CASE("Taubin lambda|mu loses less volume than plain Laplacian smoothing")
    {
        const Mesh m = icosphere(3);
        const Topology t = build_topology(m);
        const std::vector<Scalar> noisy = noisy_positions(m, {NoiseModel::GaussianRandom, 0.3}, 2);
        std::vector<Scalar> taubin = noisy, laplacian = noisy;
        taubin_smooth(t, taubin);
        taubin_smooth(t, laplacian, TaubinSettings{20, 0.5, 0});
        const Scalar lost_taubin = -volume_change_percent(m, taubin, m.positions);
        const Scalar lost_laplacian = -volume_change_percent(m, laplacian, m.positions);
        MESSAGE("volume lost: taubin ", lost_taubin, "%, laplacian ", lost_laplacian, "%");
        CHECK(lost_laplacian > 5);
        CHECK(std::abs(lost_taubin) < 0.2 * lost_laplacian);
        // Both smooth: theta drops below the noisy mesh's.
        const Scalar theta_noisy = mean_normal_angle_deg(m, noisy, m.positions);
        CHECK(mean_normal_angle_deg(m, taubin, m.positions) < theta_noisy);
    }

    TEST_CASE("SDFilter (libmeshsdfilter-dev) denoises the cube to its creases, quietly")
    {
        const Mesh m = cube_mesh(16);
        const std::vector<Scalar> noisy = noisy_positions(m, {NoiseModel::GaussianNormal, 0.2}, 11);
        std::vector<Scalar> x = noisy;
        std::streambuf* const out = std::cout.rdbuf();
        REQUIRE(sdfilter_denoise(m, x));
        CHECK(std::cout.rdbuf() == out); // its progress kept off stdout, the stream given back
        const Scalar theta_noisy = mean_normal_angle_deg(m, noisy, m.positions);
        const Scalar theta = mean_normal_angle_deg(m, x, m.positions);
        MESSAGE("theta noisy ", theta_noisy, ", sdfilter ", theta);
        CHECK(theta < 0.2 * theta_noisy);
        CHECK(crease_normal_angle_deg(m, x) < crease_normal_angle_deg(m, noisy));
        // Quads are split into triangles for it: the same vertices come back, smoothed.
        Mesh quads;
        for (int j = 0; j <= 6; ++j)
            for (int i = 0; i <= 6; ++i)
                quads.add_vertex(i, j, 0.05 * ((i * 7 + j * 3) % 5 - 2));
        for (Index j = 0; j < 6; ++j)
            for (Index i = 0; i < 6; ++i)
            {
                const Index a = 7 * j + i;
                const std::array<Index, 4> q{a, a + 1, a + 8, a + 7};
                quads.add_face(q);
            }
        std::vector<Scalar> y = quads.positions;
        REQUIRE(sdfilter_denoise(quads, y));
        REQUIRE(y.size() == quads.positions.size());
        Scalar bumps_before = 0, bumps_after = 0;
        for (size_t k = 2; k < y.size(); k += 3)
        {
            bumps_before += std::abs(quads.positions[k]);
            bumps_after += std::abs(y[k] - 0.0);
        }
        CHECK(bumps_after < bumps_before);
    }
}
