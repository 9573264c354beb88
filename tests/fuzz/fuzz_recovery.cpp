// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Recovery files (docs/editor.md, "Crash recovery"), restored into a document of a fixed
// 10-vertex mesh (small_mesh). The input is the files packed as recovery_input.h says. A
// refusal (InvalidInputError) must leave the document as it was. A restored document must
// be one the editor can hold: positions, base and selection of the mesh's sizes with
// finite coordinates and 0/1 flags, set elements within the mesh with one target or
// normal per element; and when its sets can run, the recipe the editor builds from them
// (3 steps) must run without any error but a refusal, and stay finite when its numbers
// and the positions are within +-1000.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "app/edit/constraint_sets.h"
#include "app/editor/recovery.h"
#include "core/errors.h"
#include "core/recipe/session.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/fuzz/recovery_input.h"

namespace meshfair::fuzz {
namespace {

bool within(const std::vector<Scalar>& values, double bound)
{
    return std::all_of(values.begin(), values.end(),
                       [&](Scalar v) { return std::abs(v) <= bound; });
}

void check_document(const app::Document& d)
{
    const size_t nv = static_cast<size_t>(d.mesh.vertex_count());
    const size_t nf = static_cast<size_t>(d.mesh.face_count());
    if (d.mesh.positions.size() != 3 * nv || d.base_positions.size() != 3 * nv)
        fail("restored positions of another size");
    if (!all_finite(d.mesh.positions.data(), d.mesh.positions.size()) ||
        !all_finite(d.base_positions.data(), d.base_positions.size()))
        fail("restored coordinates that are not finite");
    if (d.selected_vertices.size() != nv || d.selected_faces.size() != nf)
        fail("a restored selection of another size");
    for (const char c : d.selected_vertices)
        if (c != 0 && c != 1)
            fail("a restored vertex selection flag other than 0 or 1");
    for (const char c : d.selected_faces)
        if (c != 0 && c != 1)
            fail("a restored face selection flag other than 0 or 1");
    for (const app::ConstraintSet& s : d.sets)
    {
        for (const Index v : s.vertices)
            if (v < 0 || static_cast<size_t>(v) >= nv)
                fail("set '" + s.name + "': a vertex out of range");
        for (const Index f : s.faces)
            if (f < 0 || static_cast<size_t>(f) >= nf)
                fail("set '" + s.name + "': a face out of range");
        if (!s.targets.empty() && s.targets.size() != s.vertices.size())
            fail("set '" + s.name + "': targets not one per vertex");
        if (!s.normals.empty() && s.normals.size() != s.faces.size())
            fail("set '" + s.name + "': normals not one per face");
        if (!s.weights.empty() && s.weights.size() != s.vertices.size())
            fail("set '" + s.name + "': weights not one per vertex");
    }
    const app::SolverSettings& p = d.solver;
    if (!(p.lambda > 0) || p.iterations_per_frame < 1 || p.steps_per_run < 1 ||
        p.normal_smoothing_iterations < 0 || !(p.tolerance >= 0) || !std::isfinite(p.lambda))
        fail("restored solver settings no editor writes");
}

// The recipe the editor's solver builds from the restored sets and settings, 3 steps.
void run_restored(const app::Document& d)
{
    if (!app::constraint_problems(d.sets, d.solver).empty())
        return; // the editor says why and does not run
    Recipe recipe;
    try
    {
        recipe = app::build_recipe(d.sets, d.solver, d.mesh, d.base_positions, 3);
        if (recipe.normal_smoothing)
            recipe.normal_smoothing->iterations = std::min(recipe.normal_smoothing->iterations, 3);
        check_recipe(recipe, d.mesh);
        std::vector<Scalar> x = d.mesh.positions;
        Session session(d.mesh, d.topology, recipe);
        session.apply_hard_targets(x);
        run(session, x);
        if (bounded(recipe) && within(d.mesh.positions, 1000) && within(d.base_positions, 1000) &&
            !all_finite(x.data(), x.size()))
            fail("a restored recipe with bounded numbers gives non-finite positions");
    }
    catch (const InvalidInputError&)
    {
    }
}

int test_one_input(const std::uint8_t* data, size_t size)
{
    if (size > kMaxInput)
        return 0;
    static const app::Document original = app::make_document(small_mesh(), "/fuzz/mesh.obj");
    app::Document d = original;
    const app::RecoveryFiles files =
        recovery_files(as_text(data, size), static_cast<size_t>(d.mesh.vertex_count()));
    try
    {
        app::restore_recovery_files(files, d);
    }
    catch (const InvalidInputError& e)
    {
        if (verbose())
            std::fprintf(stderr, "refused: %s\n", e.what());
        if (d.mesh.positions != original.mesh.positions || !d.sets.empty() ||
            d.selected_vertices != original.selected_vertices || d.modified)
            fail("a refused recovery changed the document");
        return 0;
    }
    if (!d.modified)
        fail("a restored document is not marked modified");
    if (verbose())
        std::fprintf(stderr, "restored: %zu sets\n", d.sets.size());
    check_document(d);
    run_restored(d);
    return 0;
}

} // namespace
} // namespace meshfair::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    return meshfair::fuzz::test_one_input(data, size);
}
