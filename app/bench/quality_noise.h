// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace meshfair::bench {

//! The noise models of the mesh-denoising literature (Zheng et al. 2011, Zhang et al. 2015:
//! offsets scaled by the mean edge length).
enum class NoiseModel
{
    GaussianNormal, //!< Gaussian offset N(0, sigma^2) along the clean vertex normal
    GaussianRandom, //!< Gaussian offset N(0, sigma^2) along a uniformly random direction
    Impulsive,      //!< kImpulsiveFraction of the vertices moved by +-sigma along the normal
    //! Gaussian offset N(0, sigma^2) along one direction for every vertex, kScanDirection:
    //! a range scanner's error, along its line of sight whatever the surface's normal
    GaussianScan
};

//! The line of sight of GaussianScan: (0.2, -0.3, -1) normalized, a scanner looking down
//! and a little aside.
inline constexpr Vec3 kScanDirection{0.18814417367671948, -0.2822162605150792, -0.9407208683835974};

//! Share of the vertices the impulsive model moves.
inline constexpr Scalar kImpulsiveFraction = 0.1;

//! \brief One noise configuration: sigma = level x the clean mesh's mean edge length.
struct NoiseCase
{
    NoiseModel model = NoiseModel::GaussianNormal;
    Scalar level = 0.4;
};

//! "gaussian-normal", "gaussian-random", "impulsive" or "gaussian-scan".
std::string noise_name(NoiseModel model);

//! \brief The benchmark's ten cases: Gaussian along the normals, in random directions and
//! along the scanning direction at levels 0.2, 0.4 and 0.7, and impulsive at 0.7 (10% of the
//! vertices moved by exactly +-0.7 mean edge lengths, random signs).
std::vector<NoiseCase> standard_noise_cases();

//! \brief Area-weighted unit vertex normals (3 #V): the normalized sum of the incident faces'
//! area vectors (Newell's, so polygons count with their area); 0 for a vertex without faces.
std::vector<Scalar> vertex_normals(const Mesh& mesh, std::span<const Scalar> x);

//! \brief The positions of `clean` with the case's noise added; sigma = level x
//! mean_edge_length of the clean mesh. Deterministic per seed on every platform: a
//! std::mt19937_64 stream read in vertex order, with Box-Muller normal deviates and
//! rejection-sampled bounded integers written here (not std::normal_distribution nor
//! std::uniform_int_distribution, whose algorithms each standard library chooses).
//! - GaussianNormal: x_i + sigma g_i n_i, g_i ~ N(0, 1), n_i the clean vertex normal.
//! - GaussianRandom: x_i + sigma g_i d_i, d_i uniform on the unit sphere: each vertex's
//!   offset has the same root-mean-square length sigma as along the normals.
//! - Impulsive: round(kImpulsiveFraction #V) vertices drawn without replacement, each moved
//!   by s_i sigma n_i with a random sign s_i = +-1; the others stay.
//! - GaussianScan: x_i + sigma g_i d, d = kScanDirection for every vertex.
//! \pre level >= 0. \throw std::invalid_argument for a negative or non-finite level.
std::vector<Scalar> noisy_positions(const Mesh& clean, const NoiseCase& noise, std::uint64_t seed);

} // namespace meshfair::bench
