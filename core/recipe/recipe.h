// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/energies/bilateral_face_weights.h"
#include "core/energies/face_centroid_term.h"
#include "core/energies/falloff.h"
#include "core/energies/volume_constraint.h"
#include "core/mesh/mesh.h"

namespace meshfair {

//! Descent direction of each step.
enum class Method
{
    Jacobi,          //!< generalized Jacobi: each vertex's own minimizer (the product's mode)
    GradientDescent, //!< dx = -1/2 dE/dx (unpreconditioned), for the paper's comparison
    //! Taubin's lambda|mu \cite taubin_1995: each step is a Jacobi step of length lambda
    //! then one of length taubin_mu < -lambda (shrinks less; for comparison)
    Taubin,
    //! \brief The minimizer of the energy over the free vertices, by sparse Cholesky
    //! (SparseCholesky: CHOLMOD): each step solves A_ff dx = r(x) with A the half Hessian,
    //! which lands a quadratic recipe on its minimizer in one step; further steps refine
    //! it to rounding. The matrix is factored once per precomputation; moved targets
    //! change only r.
    Direct,
    //! \brief The same minimizer by conjugate gradients preconditioned by A_ff's diagonal
    //! blocks (the paper's Jacobi blocks), from where the step starts: no factor, for systems
    //! whose factor would not fit in memory; the direct method falls back to it when the
    //! factor's estimate exceeds the recipe's factor budget or CHOLMOD runs out of memory.
    ConjugateGradient,
    //! \brief Backward-Euler steps of the energy's flow dx/dt = r(x) = -1/2 dE/dx over the
    //! free vertices, each of time Recipe::time (implicit fairing, Desbrun et al. 1999):
    //! (I / t + A_ff) dx = r(x), with the sparse Cholesky factor of that matrix (once per
    //! precomputation). Unconditionally stable: the amount of smoothing is a time (the
    //! steps times t), not a count of small steps; as t grows a step tends to the direct
    //! method's. The shift I / t makes the system positive definite, so it also smooths a
    //! whole mesh that nothing holds.
    Implicit
};

//! The methods whose step solves for the minimizer (Direct, ConjugateGradient).
inline bool solves_for_minimizer(Method m)
{
    return m == Method::Direct || m == Method::ConjugateGradient;
}

//! The methods whose step solves a sparse linear system of the free vertices (factored
//! once per precomputation): the minimizer's (Direct, ConjugateGradient) and Implicit's.
inline bool solves_linear_system(Method m)
{
    return solves_for_minimizer(m) || m == Method::Implicit;
}

//! A list of element indices, or every element of the mesh ("all").
struct IndexSet
{
    bool all = false;
    std::vector<Index> indices;
};

//! Only these vertices may move; every other vertex is held fixed (hard) where it is.
//! Given as vertices, or as faces (their vertices).
struct Region
{
    std::vector<Index> vertices;
    std::vector<Index> faces;
};

//! Hard vertex constraints, moved to targets first when targets are given.
struct HardVertices
{
    std::vector<Index> vertices;
    std::vector<Vec3> targets; //!< empty: stay where they are
};

// weights: element k (k-th listed, or of the mesh with "all") weighs mu * weights[k] >= 0;
// empty: all weigh mu, bit for bit as one weight. (= {}: positional inits stay complete.)
//! Where each set of a JSON list of sets ends in the merged element list (parse_recipe
//! merges "soft": [{...}, {...}] into one), so that messages name "soft[1]". Empty: one set.
using SetEnds = std::vector<size_t>;

struct SoftVertices
{
    IndexSet vertices; //!< "all" = every vertex that is not hard
    Scalar mu = 1;
    std::vector<Vec3> targets;        //!< empty: the input positions
    std::vector<Scalar> weights = {}; //!< vertex k weighs mu * weights[k]; empty: mu
    SetEnds set_ends = {};            //!< for messages only
};

struct CentroidConstraints
{
    IndexSet faces;
    Scalar mu = 1;
    std::vector<Vec3> targets; //!< empty: the input centroids
    CentroidDenominator denominator = CentroidDenominator::Paper;
    std::vector<Scalar> weights = {}; //!< face k weighs mu * weights[k]; empty: mu
    SetEnds set_ends = {};            //!< for messages only
};

enum class NormalSource
{
    Initial,  //!< unit face normals of the input
    Smoothed, //!< the input normals after normal smoothing (the paper's "integration")
    Custom    //!< given per face
};

struct NormalConstraints
{
    IndexSet faces;
    Scalar mu = 1;
    NormalSource source = NormalSource::Initial;
    std::vector<Vec3> normals;        //!< Custom only: one per constrained face (normalized)
    std::vector<Scalar> weights = {}; //!< face k weighs mu * weights[k]; empty: mu
    SetEnds set_ends = {};            //!< for messages only
};

struct HardNormals
{
    std::vector<Index> faces;
    std::vector<Vec3> normals; //!< empty: the input normals
};

struct SoftNormals
{
    std::vector<Index> faces;
    Scalar mu = 1;
    std::vector<Vec3> normals;        //!< empty: the input normals
    std::vector<Scalar> weights = {}; //!< face k weighs mu * weights[k]; empty: mu
};

//! \brief Normal smoothing's iterations from the noise in the mesh ("iterations": "auto"):
//! iterations = clamp(round(per_noise * strength * sigma), 1, 400), sigma the noise
//! estimate_noise finds in the vertices of the normal term's faces, in mean edge lengths.
//! Noise of 0.1 and of 0.7 edge lengths then take the same recipe; strength (the editor's
//! slider) scales the noise taken: 2 smooths as for noise twice as strong.
struct AdaptiveIterations
{
    Scalar per_noise = 50; //!< iterations per mean edge length of noise
    Scalar strength = 1;
    bool operator==(const AdaptiveIterations&) const = default;
};

//! The most iterations an adaptive normal smoothing takes.
inline constexpr int kMaxAdaptiveIterations = 400;

struct NormalSmoothing
{
    int iterations = 10; //!< unless `adaptive`
    Scalar lambda = 0.5;
    HardNormals hard;
    SoftNormals soft;
    //! absent: every dual edge weighs 1 (the paper's E_U)
    std::optional<BilateralWeights> bilateral = {};
    //! set: the iterations follow the mesh's noise ("iterations": "auto")
    std::optional<AdaptiveIterations> adaptive = {};
};

struct Joint
{
    Scalar gamma = 1;
};

//! \brief The thin-plate term (BendingTerm): mu times the squared umbrella operator over
//! every vertex, so a region meets the fixed rest without a crease and a dragged pin
//! raises a dome. `membrane` weighs the edge term beside it: 0 (the default) is the thin
//! plate alone, whose minimizer is the smooth dome; 1 is the paper's edge term as well.
struct Bending
{
    Scalar mu = 1;
    Scalar membrane = 0;
    bool operator==(const Bending&) const = default;
};

//! \brief Soft anchors that fade with the distance along the surface from the fixed rest
//! around a region (its border) and from the pins (hard vertices): vertex i at distance d
//! is held with mu * curve(d / radius) (0 from the radius on), toward its input position
//! near the border and toward its input position moved by the same fraction of its
//! nearest pin's displacement near a pin (Blender's proportional editing), so the smoothed
//! patch meets the rest without a seam and a dragged pin raises a smooth bump. The anchors
//! add to the soft section's (docs/math.md, "Falloff").
struct Falloff
{
    Scalar radius = 8;
    bool radius_in_edge_lengths = true; //!< radius in mean edge lengths, else mesh units
    FalloffCurve curve = FalloffCurve::Smooth;
    Scalar mu = 1;
    bool border = true; //!< fade from the region's border (with a region)
    bool pins = true;   //!< fade from the hard vertices (with hard vertices)
    bool operator==(const Falloff&) const = default;
};

//! Keep the enclosed volume of every component (VolumeConstraint): of the closed ones, and
//! of the open ones as the `open` rule says.
struct KeepVolume
{
    OpenVolume open = OpenVolume::Capped;
    //! Only on components with no fixed vertex ("components": "free"; else "all").
    bool free_components_only = false;
    bool operator==(const KeepVolume&) const = default;
};

//! \brief Everything one smoothing run needs besides the mesh: the constraint sets and
//! weights of \cite taubin_2012 ("Combining all the Smoothing Strategies") and the
//! iteration settings. Absent sections are inactive; the edge term is always on (scaled by
//! the bending section's membrane weight when there is one).
//! The JSON form is documented in docs/recipe.md (see recipe_json.h).
struct Recipe
{
    //! What the recipe is for, in a sentence (a preset's menu says it); no effect on a run.
    std::string description;
    int iterations = 10;
    bool optimal_step = false; //!< exact line search instead of the fixed lambda
    Scalar lambda = 0.5;
    Scalar tolerance = 0; //!< stop when the relative energy decrease falls below
    Method method = Method::Jacobi;
    Scalar taubin_mu = -0.53; //!< the second step's length, Method::Taubin only
    //! \brief Method::Implicit only: the time of each backward-Euler step, > 0, in the
    //! units of the flow dx/dt = -1/2 dE/dx (for plain smoothing of a mesh of valence 6, a
    //! Jacobi step of lambda moves a vertex as far as a time of about lambda / 6 does).
    Scalar time = 1;
    //! \brief The direct method's memory for its factor, in MB: a factor whose estimate
    //! (after the symbolic analysis) exceeds it is not computed, and conjugate gradients
    //! solve instead (noted). 0: half of the machine's physical memory.
    Scalar factor_budget_mb = 0;
    //! Shorten the steps of vertices whose steps would turn a face of their star over
    //! (FlipGuard); off: the steps as the energy gives them, bit for bit.
    bool prevent_flips = false;

    std::optional<Region> region;
    std::optional<HardVertices> hard;
    std::optional<SoftVertices> soft;
    std::optional<CentroidConstraints> centroid;
    std::optional<NormalConstraints> normal;
    std::optional<NormalSmoothing> normal_smoothing;
    std::optional<Joint> joint;
    std::optional<Bending> bending;
    std::optional<KeepVolume> volume;
    std::optional<Falloff> falloff;
};

//! \brief Checks a recipe against a mesh: indices in range and not repeated (nor in two
//! sets of a list), target, normal and weight counts matching their sets, hard and soft
//! vertex (normal face) sets disjoint, weights finite and >= 0 (mu * weights[k] too),
//! sections that need another one, mesh and target coordinates within +-kMaxCoordinate.
//! \throw RecipeError naming the offending key ("soft.vertices[3]", "soft[1].weights[0]");
//! InvalidInputError naming the vertex when a mesh coordinate is out of range, or when the
//! mesh has vertices but no face (a point cloud: no surface to smooth).
void check_recipe(const Recipe& recipe, const Mesh& mesh);

//! \brief The same recipe for the mesh renumbered so that file vertex i is vertex
//! new_vertex[i] and file face f is face new_face[f] (see LocalityOrder): every index is
//! mapped, every list keeps its order, so per-element targets, normals and weights still
//! match (with "all" they are permuted with the elements).
//! \pre check_recipe(recipe, mesh) holds for the file's mesh.
Recipe renumber_recipe(const Recipe& recipe, std::span<const Index> new_vertex,
                       std::span<const Index> new_face);

} // namespace meshfair
