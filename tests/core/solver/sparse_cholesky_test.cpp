// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// The sparse Cholesky factorization (CHOLMOD) and the half Hessian of the free vertices:
// each term's column against its own energy, by polarization.
#include <doctest/doctest.h>

#include <dlfcn.h>
#include <omp.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/energies/bending_term.h"
#include "core/energies/edge_term.h"
#include "core/energies/face_centroid_term.h"
#include "core/energies/face_normal_term.h"
#include "core/energies/soft_vertex_term.h"
#include "core/errors.h"
#include "core/geometry/face_geometry.h"
#include "core/solver/free_hessian.h"
#include "core/solver/free_system.h"
#include "core/solver/preparation_progress.h"
#include "core/solver/sparse_cholesky.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

// The path graph's Laplacian plus `shift` on the diagonal, upper triangle by columns.
SymmetricMatrix shifted_path(std::int64_t n, Scalar shift)
{
    SymmetricMatrix a;
    a.size = n;
    a.column_start.push_back(0);
    for (std::int64_t c = 0; c < n; ++c)
    {
        if (c > 0)
        {
            a.row.push_back(c - 1);
            a.value.push_back(-1);
        }
        a.row.push_back(c);
        a.value.push_back((c > 0 ? 1 : 0) + (c + 1 < n ? 1 : 0) + shift);
        a.column_start.push_back(static_cast<std::int64_t>(a.row.size()));
    }
    return a;
}

// The dense matrix of a SymmetricMatrix (both triangles).
std::vector<Scalar> dense(const SymmetricMatrix& a)
{
    const auto n = static_cast<size_t>(a.size);
    std::vector<Scalar> d(n * n, 0);
    for (size_t c = 0; c < n; ++c)
        for (auto k = static_cast<size_t>(a.column_start[c]);
             k < static_cast<size_t>(a.column_start[c + 1]); ++k)
        {
            const auto r = static_cast<size_t>(a.row[k]);
            CHECK(r <= c);
            d[r * n + c] += a.value[k];
            if (r != c)
                d[c * n + r] += a.value[k];
        }
    return d;
}

} // namespace

TEST_SUITE("SparseCholesky")
{
    TEST_CASE("solves a positive definite system for several right-hand sides")
    {
        const SymmetricMatrix a = shifted_path(50, 0.1);
        SparseCholesky cholesky;
        cholesky.analyse(a);
        REQUIRE(cholesky.factor(a));
        std::mt19937 random(3);
        std::uniform_real_distribution<Scalar> value(-1, 1);
        std::vector<Scalar> x(150);
        for (Scalar& v : x)
            v = value(random);
        std::vector<Scalar> b(150);
        for (int c = 0; c < 3; ++c)
            a.multiply(std::span<const Scalar>(x).subspan(50 * c, 50),
                       std::span<Scalar>(b).subspan(50 * c, 50));
        cholesky.solve(b, 3);
        for (size_t k = 0; k < x.size(); ++k)
            CHECK(b[k] == doctest::Approx(x[k]).epsilon(1e-12));
        CHECK(cholesky.stats().factor_nonzeros >= 50);
    }

    TEST_CASE("a new factorization of the same pattern, then a matrix that is not definite")
    {
        SparseCholesky cholesky;
        cholesky.analyse(shifted_path(10, 1));
        REQUIRE(cholesky.factor(shifted_path(10, 1)));
        REQUIRE(cholesky.factor(shifted_path(10, 2)));
        std::vector<Scalar> b(10, 1);
        cholesky.solve(b, 1);
        std::vector<Scalar> back(10);
        shifted_path(10, 2).multiply(b, back);
        for (const Scalar v : back)
            CHECK(v == doctest::Approx(1).epsilon(1e-12));
        // The path's Laplacian alone is singular: the constants are its null space.
        CHECK_FALSE(cholesky.factor(shifted_path(10, 0)));
        CHECK_FALSE(cholesky.factored());
        CHECK_THROWS_AS(cholesky.solve(b, 1), SolverError);
    }

    TEST_CASE("a matrix of the analysed pattern is told from one of another")
    {
        SparseCholesky cholesky;
        CHECK_FALSE(cholesky.analysed_for(shifted_path(10, 1))); // nothing analysed
        cholesky.analyse(shifted_path(10, 1));
        CHECK(cholesky.analysed_for(shifted_path(10, 1)));
        CHECK(cholesky.analysed_for(shifted_path(10, 7))); // other values: the same pattern
        CHECK_FALSE(cholesky.analysed_for(shifted_path(11, 1)));
        // The same size and count of entries, one row moved: (0, 2) in place of (1, 2).
        SymmetricMatrix moved = shifted_path(10, 1);
        REQUIRE(moved.row[moved.column_start[2]] == 1);
        moved.row[moved.column_start[2]] = 0;
        CHECK_FALSE(cholesky.analysed_for(moved));
        // One entry more: (0, 2) beside (1, 2).
        SymmetricMatrix more = shifted_path(10, 1);
        more.row.insert(more.row.begin() + more.column_start[2], 0);
        more.value.insert(more.value.begin() + more.column_start[2], 0);
        for (size_t c = 3; c < more.column_start.size(); ++c)
            ++more.column_start[c];
        CHECK_FALSE(cholesky.analysed_for(more));
        // A factorization on the kept analysis counts as one more, with no analysis time.
        REQUIRE(cholesky.factor(shifted_path(10, 1)));
        CHECK(cholesky.stats().factorizations == 1);
        REQUIRE(cholesky.factor(shifted_path(10, 7)));
        CHECK(cholesky.stats().factorizations == 2);
        CHECK(cholesky.stats().analyse_seconds == 0);
    }

    TEST_CASE(
        "a small factor runs OpenBLAS on one thread, unless the environment says, and "
        "OpenMP's regions as they were")
    {
        // The BLAS CHOLMOD loads (Debian's alternatives: OpenBLAS, which the setup
        // installs), loaded by the first factorization.
        const int levels = omp_get_max_active_levels();
        SparseCholesky cholesky;
        cholesky.analyse(shifted_path(200, 1));
        REQUIRE(cholesky.factor(shifted_path(200, 1)));
        std::vector<Scalar> b(200, 1);
        cholesky.solve(b, 1);
        // (CHOLMOD's own regions ran on one thread meanwhile: the setting is given back.)
        CHECK(omp_get_max_active_levels() == levels);
        CHECK(levels > 0);
        CHECK(cholesky.stats().factor_flops > 0);
        CHECK(cholesky.stats().factor_flops < 2e9);
        void* blas = dlopen("libblas.so.3", RTLD_NOW | RTLD_NOLOAD);
        REQUIRE(blas != nullptr);
        using Get = int (*)();
        const auto threads = reinterpret_cast<Get>(dlsym(blas, "openblas_get_num_threads"));
        REQUIRE(dlsym(blas, "openblas_get_num_threads") != nullptr);
        if (const char* given = std::getenv("OPENBLAS_NUM_THREADS"))
            CHECK(threads() == std::atoi(given));
        else
            CHECK(threads() == 1);
        dlclose(blas);
    }

    TEST_CASE(
        "the ordering and the factorization are reported as phases, and a cancel stops "
        "the next one, with no conjugate gradients in its place")
    {
        const SymmetricMatrix a = shifted_path(300, 1);
        auto progress = std::make_shared<PreparationProgress>();
        std::vector<PreparationProgress::Snapshot> seen;
        progress->set_listener([&](const PreparationProgress::Snapshot& p) { seen.push_back(p); });
        SparseCholesky cholesky;
        cholesky.report_to(progress);
        cholesky.analyse(a);
        REQUIRE(cholesky.factor(a));
        REQUIRE(seen.size() == 2);
        CHECK(seen[0].phase == PreparationProgress::Phase::Ordering);
        CHECK(seen[0].unknowns == 300);
        CHECK(seen[0].expected_seconds > 0);
        CHECK(seen[1].phase == PreparationProgress::Phase::Factoring);
        CHECK(seen[1].flops == cholesky.stats().factor_flops);
        CHECK(seen[1].flops > 0);
        CHECK(seen[1].expected_seconds > 0);
        const PreparationProgress::Snapshot now = progress->snapshot();
        CHECK(now.phase == PreparationProgress::Phase::Factoring);
        CHECK(now.seconds >= 0);
        CHECK(now.fraction() >= 0);
        CHECK(now.fraction() < 1);
        CHECK_FALSE(now.cancelled);

        // Cancelled while the ordering runs (here: as it begins): no analysis, so no
        // factorization, and the factor before it is gone.
        progress->set_listener([&](const PreparationProgress::Snapshot& p) {
            if (p.phase == PreparationProgress::Phase::Ordering)
                progress->cancel();
        });
        CHECK_THROWS_AS(cholesky.analyse(shifted_path(200, 1)), PreparationCancelled);
        CHECK(progress->snapshot().cancelled);
        CHECK_FALSE(cholesky.factored());
        CHECK_FALSE(cholesky.analysed_for(shifted_path(200, 1)));
        CHECK_THROWS_AS(cholesky.factor(shifted_path(200, 1)), SolverError);

        // Through the free system's solver: the cancel comes out as it is, where a failed
        // factorization would have been solved by conjugate gradients with a note.
        auto fresh = std::make_shared<PreparationProgress>();
        fresh->set_listener([&](const PreparationProgress::Snapshot& p) {
            if (p.phase == PreparationProgress::Phase::Factoring)
                fresh->cancel(); // the analysis done, before its factorization
        });
        auto carrier = std::make_unique<SparseCholesky>();
        carrier->report_to(fresh);
        std::vector<std::string> notes;
        CHECK_THROWS_AS(FreeSystemSolver(a, 1, false, 0, notes, std::move(carrier)),
                        PreparationCancelled);
        CHECK(notes.empty());
        // Without a cancel the carrier's progress sees the phases of the factor it becomes.
        auto watched = std::make_shared<PreparationProgress>();
        int phases = 0;
        watched->set_listener([&](const PreparationProgress::Snapshot&) { ++phases; });
        carrier = std::make_unique<SparseCholesky>();
        carrier->report_to(watched);
        FreeSystemSolver solver(a, 1, false, 0, notes, std::move(carrier));
        CHECK(phases == 2);
        REQUIRE(solver.factorization() != nullptr);
        CHECK(solver.factorization()->progress() == watched);
    }

    TEST_CASE("misuse is refused: no analysis, a wrong size, a malformed matrix")
    {
        SparseCholesky cholesky;
        CHECK_THROWS_AS(cholesky.factor(shifted_path(4, 1)), SolverError);
        cholesky.analyse(shifted_path(4, 1));
        CHECK_THROWS_AS(cholesky.factor(shifted_path(5, 1)), SolverError);
        REQUIRE(cholesky.factor(shifted_path(4, 1)));
        std::vector<Scalar> b(7, 0);
        CHECK_THROWS_AS(cholesky.solve(b, 2), SolverError);
        SymmetricMatrix broken = shifted_path(4, 1);
        broken.column_start.back() = 1;
        CHECK_THROWS_AS(cholesky.analyse(broken), SolverError);
    }
}

TEST_SUITE("free Hessian")
{
    // Every term's half Hessian A (E(x + d) = E(x) - 2 r^T d + d^T A d) read off its
    // energy: for a quadratic E, d^T A d = E(x + d) - E(x) + 2 r^T d, and with r taken
    // from the gradient by polarization, A's entries are
    // (E(x + s e_p + s e_q) - E(x + s e_p) - E(x + s e_q) + E(x)) / (2 s^2).
    TEST_CASE("each term's columns are the Hessian of its energy, on every kind of mesh")
    {
        for (const auto& named : {std::pair{"tetrahedron", test::tetrahedron()},
                                  {"quad cube", test::quad_cube()},
                                  {"open grid", test::open_grid(3, 2)},
                                  {"non-manifold fan", test::nonmanifold_fan()},
                                  {"mixed polygons", test::mixed_polygons()}})
        {
            // Not a structured binding: CAPTURE's lambda cannot name one (clang 14).
            const char* name = named.first;
            CAPTURE(name);
            Mesh m = named.second;
            test::perturb(m, 0.1, 5);
            const Topology t = build_topology(m);
            const Index nv = m.vertex_count(), nf = m.face_count();
            std::vector<Index> faces, vertices;
            for (Index f = 0; f < nf; f += 2)
                faces.push_back(f);
            for (Index v = 0; v < nv; v += 2)
                vertices.push_back(v);
            std::vector<Scalar> face_w(faces.size()), vertex_w(vertices.size());
            for (size_t k = 0; k < face_w.size(); ++k)
                face_w[k] = 0.5 + static_cast<Scalar>(k);
            for (size_t k = 0; k < vertex_w.size(); ++k)
                vertex_w[k] = 1.5 + static_cast<Scalar>(k);
            const EdgeTerm edge(t);
            const std::vector<Scalar> targets(3 * vertices.size(), 0.25);
            const SoftVertexTerm soft(nv, vertices, 0.7, targets, vertex_w);
            FaceCentroidTerm centroid(m, t, faces, 1.3, CentroidDenominator::Paper, face_w);
            centroid.set_targets_to_centroids(m.positions);
            const FaceNormalTerm normal(m, t, faces, 2.1, face_w);
            const BendingTerm bending(t, 0.9);
            const std::vector<Scalar> normals = face_normals(m, m.positions);
            const auto energy = [&](std::span<const Scalar> x) {
                return edge.energy(x) + soft.energy(x) + centroid.energy(x) +
                       normal.energy(x, normals) + bending.energy(x);
            };
            std::vector<Index> free;
            for (Index v = 0; v < nv; ++v)
                if (v != 1) // one fixed vertex: its entries are dropped
                    free.push_back(v);
            const SymmetricMatrix a =
                assemble_free_hessian(nv, free, true, [&](Index i, HessianColumn& col) {
                    edge.add_hessian_column(i, col);
                    soft.add_hessian_column(i, col);
                    centroid.add_hessian_column(i, col);
                    normal.add_hessian_column(i, normals, col);
                    bending.add_hessian_column(i, col);
                });
            const std::vector<Scalar> d = dense(a);
            const auto n = static_cast<size_t>(a.size);
            REQUIRE(n == 3 * free.size());
            const Scalar s = 0.5;
            std::vector<Scalar> x = m.positions;
            const Scalar e0 = energy(x);
            const auto coordinate = [&](size_t p) {
                return 3 * static_cast<size_t>(free[p / 3]) + p % 3;
            };
            for (size_t p = 0; p < n; ++p)
                for (size_t q = p; q < n; ++q)
                {
                    x[coordinate(p)] += s;
                    const Scalar ep = energy(x);
                    x[coordinate(q)] += s;
                    const Scalar epq = energy(x);
                    x[coordinate(p)] -= s;
                    const Scalar eq = energy(x);
                    x[coordinate(q)] -= s;
                    const Scalar expected = (epq - ep - eq + e0) / (2 * s * s);
                    CAPTURE(p);
                    CAPTURE(q);
                    CHECK(d[p * n + q] == doctest::Approx(expected).epsilon(1e-9).scale(1));
                }
            // Without the normal term the matrix is one coordinate's: the same entries
            // as the blocks' xx.
            const auto isotropic = [&](Index i, HessianColumn& col) {
                edge.add_hessian_column(i, col);
                soft.add_hessian_column(i, col);
                centroid.add_hessian_column(i, col);
                bending.add_hessian_column(i, col);
            };
            const std::vector<Scalar> d1 = dense(assemble_free_hessian(nv, free, false, isotropic));
            const SymmetricMatrix s3 = assemble_free_hessian(nv, free, true, isotropic);
            const std::vector<Scalar> d3 = dense(s3);
            const size_t m1 = free.size();
            for (size_t p = 0; p < m1; ++p)
                for (size_t q = 0; q < m1; ++q)
                    for (size_t a1 = 0; a1 < 3; ++a1)
                        for (size_t a2 = 0; a2 < 3; ++a2)
                            CHECK(d3[(3 * p + a1) * n + 3 * q + a2] ==
                                  (a1 == a2 ? d1[p * m1 + q] : 0));
        }
    }
}
