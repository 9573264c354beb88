// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/render/camera.h"
#include "core/mesh/mesh.h"
#include "core/recipe/recipe.h"
#include "core/topology/topology.h"

namespace meshfair::app {

//! What a constraint set does, one kind per section of the core's recipe (docs/recipe.md).
enum class ConstraintKind
{
    Region,     //!< what may move (vertices, or faces: their vertices); the rest is fixed
    Pin,        //!< hard vertex constraints, optionally moved to targets
    Anchor,     //!< soft vertex constraints (mu)
    Centroid,   //!< soft face-centroid constraints (mu, denominator)
    Normal,     //!< face-normal constraints (mu; initial, smoothed or custom normals)
    HardNormal, //!< normals held fixed while the normals are smoothed
    SoftNormal  //!< soft normal constraints while the normals are smoothed (mu)
};
inline constexpr int kConstraintKinds = 7;

struct SolverSettings;

//! \brief Everything the editor knows of a kind, in one row of one table (constraint_kinds):
//! what the functions below read, so that a kind's facts are in one place.
struct ConstraintKindInfo
{
    ConstraintKind kind;
    std::string_view name;  //!< files' and scripts' word: "hard_normal"
    std::string_view label; //!< the interface's: "hard normal"
    bool vertices;          //!< its sets hold vertices (a region: vertices or faces)
    bool normals;           //!< a normal kind: its faces carry directions (arrows, D tool)
    //! The solver settings' weight of its sets without their own (none: no weight).
    Scalar SolverSettings::*weight;
    bool weight_map;                        //!< a map per vertex may be painted
    std::optional<ConstraintKind> loses_to; //!< the kind that wins an element in both
    std::array<float, 3> color;             //!< a new set's colour (palette.h)
};
//! The kinds, in ConstraintKind's order.
std::span<const ConstraintKindInfo> constraint_kinds();
const ConstraintKindInfo& kind_info(ConstraintKind kind);

//! "region", "pin", "anchor", "centroid", "normal", "hard_normal", "soft_normal".
std::string_view kind_name(ConstraintKind kind);
std::optional<ConstraintKind> kind_named(std::string_view name);
//! Whether a kind's sets hold vertices (region: vertices or faces).
bool takes_vertices(ConstraintKind kind);

//! \brief A named set of the editor's recipe: its kind, its elements and what it carries.
//! Several sets of one kind are merged into the recipe's one section of that kind (their
//! union; for an element in two sets, the first set's target, normal and weight), each
//! element with its set's weight (the core's per-element weights).
struct ConstraintSet
{
    std::string name;
    ConstraintKind kind = ConstraintKind::Region;
    //! Region (from vertex mode), Pin, Anchor: increasing when made from a selection; a
    //! recipe's order when imported (a pin's targets follow it).
    std::vector<Index> vertices;
    std::vector<Index> faces; //!< Region (from face mode) and the face kinds, likewise
    //! Pin only: one target per vertex once moved; empty: the vertices stay where they are.
    std::vector<Vec3> targets;
    //! Normal kinds: one unit normal per face when set by hand (the gizmo sets them all to
    //! one direction); empty: the source's normals (Normal) or the input's (the others).
    std::vector<Vec3> normals;
    std::array<float, 3> color{1, 1, 1};
    bool visible = true; //!< its glyphs are drawn (display only)
    bool enabled = true; //!< it takes part in the solve
    //! Anchor, centroid, normal and soft normal sets: the set's own weight mu; nullopt: the
    //! kind's weight of the solver settings.
    std::optional<Scalar> mu;
    //! \brief A weight map (painted, or a recipe's per-vertex weights): one value per vertex
    //! of `vertices`; empty: every vertex 1. Anchor sets: vertex k is held with mu *
    //! weights[k] >= 0. Region sets: vertex k's freedom in [0, 1] (region_anchor_weight):
    //! 1 moves as a region vertex does, 0 stays fixed as a vertex outside the region does,
    //! and in between it is held toward where the run starts, so that a painted region
    //! fades into the fixed rest without a seam.
    std::vector<Scalar> weights;
    bool operator==(const ConstraintSet&) const = default;
};

//! \brief The weights and iteration settings of the editor's recipe (the solver panel).
struct SolverSettings
{
    bool optimal_step = false; //!< the exact line search instead of lambda
    Scalar lambda = 0.5;
    Scalar tolerance = 0;
    int iterations_per_frame = 1;
    //! Play runs this many steps, then pauses (the pace of a run, not part of the recipe).
    int steps_per_run = 20;
    //! Play runs until they converge instead: the gradient relative to the run's start at
    //! most the tolerance (1e-6 when it is 0).
    bool until_converged = false;
    Scalar anchor_mu = 1;
    Scalar centroid_mu = 1;
    CentroidDenominator denominator = CentroidDenominator::Paper;
    Scalar normal_mu = 1;
    //! Normals of the Normal sets without normals of their own: Initial or Smoothed.
    NormalSource normal_source = NormalSource::Initial;
    int normal_smoothing_iterations = 10;
    //! set: normal smoothing takes its iterations from the noise in the mesh, scaled by
    //! the strength (Recipe's "iterations": "auto"); normal_smoothing_iterations otherwise
    std::optional<AdaptiveIterations> adaptive_smoothing;
    Scalar normal_smoothing_lambda = 0.5;
    Scalar soft_normal_mu = 1;
    bool joint = false;
    Scalar gamma = 1;
    //! Jacobi steps, Taubin's lambda|mu pairs, or the direct method: the shape shown is then
    //! the minimizer of the sets, solved again whenever they change (the editor runs no
    //! gradient descent).
    Method method = Method::Jacobi;
    Scalar taubin_mu = -0.53;
    //! The time of each backward-Euler step of Method::Implicit (Recipe::time).
    Scalar time = 1;
    //! Feature-preserving normal smoothing (with smoothed normals or joint mode), when set.
    std::optional<BilateralWeights> bilateral;
    //! Keep the enclosed volume of each component (open ones as `volume` says).
    bool keep_volume = false;
    KeepVolume volume;
    //! Shorten the steps that would turn faces over (Recipe::prevent_flips).
    bool prevent_flips = false;
    //! Anchors fading from the regions' border and from the pins, when set.
    std::optional<Falloff> falloff;
    //! The thin plate (a dome, not a horn, under a dragged pin), when set.
    std::optional<Bending> bending;
    bool operator==(const SolverSettings&) const = default;
};

//! \brief `settings` with the pace of `pace`: the steps per frame, the steps per run and
//! "until converged", which say how the editor runs a recipe and are not part of it.
SolverSettings with_pace(SolverSettings settings, const SolverSettings& pace);

//! \brief The settings with which a pin drag raises a dome (the M tool): the minimizer of
//! the sets with the thin plate, as Blender's proportional editing or a Move brush gives
//! it. The direct method unless the settings solve for the minimizer already (conjugate
//! gradients), the bending term (mu 1) when there is none, and none of what the direct
//! method refuses (joint mode, the kept volume, the exact line search). nullopt when
//! `settings` raise a dome already, or when no enabled region set fixes the rest: over a
//! whole mesh, pins alone would hold the thin plate's minimizer only by collapsing it
//! toward them, so the drag then runs as the settings say.
std::optional<SolverSettings> dome_settings(const std::vector<ConstraintSet>& sets,
                                            const SolverSettings& settings);

//! Whether a kind's sets can carry a weight map (anchor and region sets).
bool takes_weight_map(ConstraintKind kind);
//! \brief The anchor weight that holds a region vertex of freedom w in (0, 1]: (1 - w) / w,
//! 0 at full freedom and without bound as w -> 0, where the vertex is fixed; so a map fading
//! to 0 meets the fixed rest continuously.
Scalar region_anchor_weight(Scalar freedom);
//! The weight map's value of a set's k-th vertex (1 without a map).
inline Scalar map_value(const ConstraintSet& set, size_t k)
{
    return set.weights.empty() ? Scalar(1) : set.weights[k];
}

//! Whether a kind's sets carry a weight mu (anchor, centroid, normal, soft normal).
bool takes_weight(ConstraintKind kind);
//! The weight a set's elements get: its own, or its kind's in `settings`.
Scalar weight_of(const ConstraintSet& set, const SolverSettings& settings);

//! \brief Why the enabled sets cannot run, one sentence per problem naming the sets
//! (empty: they can): hard and soft normals and joint mode need a normal set, hard and soft
//! normals act only while normals are smoothed, custom normals need the "initial" source for
//! the other normal sets. Overlaps are no problem (constraint_notes).
std::vector<std::string> constraint_problems(const std::vector<ConstraintSet>& sets,
                                             const SolverSettings& settings);
//! \brief How the enabled sets' overlaps are resolved, one sentence each: a pin wins over
//! an anchor, a hard normal over a soft one, and of two sets of one kind the first in the
//! list gives the element its target, normal and weight; an empty set is left out.
std::vector<std::string> constraint_notes(const std::vector<ConstraintSet>& sets);

//! \brief The core recipe of the sets and settings, running `iterations` steps, in the
//! mesh's numbering; `positions` (3 #V, the base shape) place the pins without targets
//! of a set list where others have targets, and give the input normals of faces whose set
//! has custom normals mixed with others.
//! \pre constraint_problems(sets, settings) is empty.
Recipe build_recipe(const std::vector<ConstraintSet>& sets, const SolverSettings& settings,
                    const Mesh& mesh, std::span<const Scalar> positions, int iterations);

//! \brief The recipe's hard vertices of the sets (build_recipe's `hard`), or nullopt without
//! an enabled pin set: reading the pin sets alone, for a pin drag that moves only them
//! (build_recipe walks every set, a region of a million vertices included).
std::optional<HardVertices> pin_constraints(const std::vector<ConstraintSet>& sets,
                                            std::span<const Scalar> positions);

//! \brief Whether two lists of sets with their settings make the same solver run: the
//! same kinds, elements, normals (and pin targets unless `ignoring_pin_targets`) in the
//! same order and the same settings but the steps per frame. Names, colours and
//! visibility do not count. What decides whether the editor's solver must precompute
//! again, or only move its pins, or nothing.
bool same_run(const std::vector<ConstraintSet>& a, const SolverSettings& a_settings,
              const std::vector<ConstraintSet>& b, const SolverSettings& b_settings,
              bool ignoring_pin_targets);

//! \brief The set with its vertices listed in increasing vertex_key[v], its faces in
//! increasing face_key[f] (ties kept in order), each with its target, weight or normal.
ConstraintSet ordered_by(ConstraintSet set, std::span<const Index> vertex_key,
                         std::span<const Index> face_key);

//! \brief The vertices a region set leaves out but encloses: what closing it (one ring grown,
//! then one shrunk) adds, and each part of the vertices left out (connected through edges
//! among them) that the region surrounds: not the largest such part of its mesh component
//! (the rest of the mesh), and at most a quarter of the region's vertices in that
//! component (so that a band around the middle does not take in a whole end). A
//! front-facing selection of a noisy scan misses vertices hidden in pits (a nostril's
//! inside, dozens of rings deep); left out of a region they stay fixed among moving ones
//! and become spikes.
//! \pre `set` is a region; topology has the neighbour, corner and edge parts.
//! Returns the vertices.
std::vector<Index> region_holes(const ConstraintSet& set, const Mesh& mesh,
                                const Topology& topology);
//! \brief Takes a region's holes in (a region of faces: the faces around them whose corners
//! all move then); returns how many vertices were holes.
size_t close_region_holes(ConstraintSet& set, const Mesh& mesh, const Topology& topology);

//! The sets and settings of a recipe (Import recipe): one set per section, named by kind.
struct ImportedRecipe
{
    std::vector<ConstraintSet> sets;
    SolverSettings settings;
    int iterations = 0;
    std::string description; //!< the recipe's "description"
    //! The up axis the file was exported with (its "editor" object), if it says.
    std::optional<UpAxis> up;
    //! The sets and settings are the editor's own, as exported (its "editor" object): the
    //! settings with their pace (steps per frame and per run), which a recipe has not.
    bool editor = false;
    //! What the import could not take as it was, for the status line; empty: all of it.
    std::string note;
};
//! \pre check_recipe(recipe, mesh) holds.
ImportedRecipe sets_from_recipe(const Recipe& recipe, const Mesh& mesh);

//! \brief The sets after a preset (cmd::ApplyPreset): the user's regions and pins, then the
//! user's sets of the kinds the preset has none of, then the preset's other sets; the
//! preset's regions and pins only for a kind the user has none of.
std::vector<ConstraintSet> merge_preset(const std::vector<ConstraintSet>& user,
                                        std::vector<ConstraintSet> preset);

//! The colour a new set of `kind` gets (each kind its hue, as its glyphs show it).
std::array<float, 3> default_color(ConstraintKind kind);

} // namespace meshfair::app
