// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/quality_noise.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/geometry/face_geometry.h"
#include "core/topology/topology.h"

namespace meshfair::bench {

namespace {

// The deviates of one noise stream, in a fixed order of engine draws.
class Deviates
{
public:
    explicit Deviates(std::uint64_t seed) : engine_(seed) {}

    // Uniform in (0, 1] from 53 random bits, so that log() never sees 0.
    double uniform() { return (static_cast<double>(engine_() >> 11) + 1.0) * 0x1p-53; }

    // Standard normal by Box-Muller, both deviates of a pair used.
    double normal()
    {
        if (has_spare_)
        {
            has_spare_ = false;
            return spare_;
        }
        const double radius = std::sqrt(-2.0 * std::log(uniform()));
        const double angle = 2.0 * std::numbers::pi * uniform();
        spare_ = radius * std::sin(angle);
        has_spare_ = true;
        return radius * std::cos(angle);
    }

    // Uniform in [0, range), without the modulo bias.
    std::uint64_t below(std::uint64_t range)
    {
        const std::uint64_t limit = UINT64_MAX - UINT64_MAX % range;
        std::uint64_t draw = engine_();
        while (draw >= limit)
            draw = engine_();
        return draw % range;
    }

private:
    std::mt19937_64 engine_;
    double spare_ = 0;
    bool has_spare_ = false;
};

} // namespace

std::string noise_name(NoiseModel model)
{
    switch (model)
    {
        case NoiseModel::GaussianNormal:
            return "gaussian-normal";
        case NoiseModel::GaussianRandom:
            return "gaussian-random";
        case NoiseModel::Impulsive:
            return "impulsive";
        case NoiseModel::GaussianScan:
            return "gaussian-scan";
    }
    return "?";
}

std::vector<NoiseCase> standard_noise_cases()
{
    std::vector<NoiseCase> cases;
    for (const NoiseModel model : {NoiseModel::GaussianNormal, NoiseModel::GaussianRandom})
        for (const Scalar level : {0.2, 0.4, 0.7})
            cases.push_back({model, level});
    cases.push_back({NoiseModel::Impulsive, 0.7});
    for (const Scalar level : {0.2, 0.4, 0.7})
        cases.push_back({NoiseModel::GaussianScan, level});
    return cases;
}

std::vector<Scalar> vertex_normals(const Mesh& mesh, std::span<const Scalar> x)
{
    std::vector<Scalar> normals(3 * static_cast<size_t>(mesh.vertex_count()), 0);
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        // Newell's area vector: the area times the unit normal (area weighting).
        const Vec3 n = face_area_vector(mesh, x, f);
        const auto face = mesh.face(f);
        for (const Index v : face)
            for (int a = 0; a < 3; ++a)
                normals[3 * v + a] += n[a];
    }
    for (size_t i = 0; i < normals.size(); i += 3)
    {
        const Scalar length = std::sqrt(normals[i] * normals[i] + normals[i + 1] * normals[i + 1] +
                                        normals[i + 2] * normals[i + 2]);
        if (length > 0)
            for (int a = 0; a < 3; ++a)
                normals[i + a] /= length;
    }
    return normals;
}

std::vector<Scalar> noisy_positions(const Mesh& clean, const NoiseCase& noise, std::uint64_t seed)
{
    if (!(noise.level >= 0) || !std::isfinite(noise.level))
        throw std::invalid_argument("noisy_positions: the level must be finite and >= 0");
    const Topology topology = build_topology(clean, TopologyParts::Edges);
    const Scalar sigma = noise.level * mean_edge_length(topology, clean.positions);
    const std::vector<Scalar> normals = vertex_normals(clean, clean.positions);
    std::vector<Scalar> x = clean.positions;
    Deviates random(seed);
    const Index nv = clean.vertex_count();
    switch (noise.model)
    {
        case NoiseModel::GaussianNormal:
            for (Index i = 0; i < nv; ++i)
            {
                const Scalar offset = sigma * random.normal();
                for (int a = 0; a < 3; ++a)
                    x[3 * i + a] += offset * normals[3 * i + a];
            }
            break;
        case NoiseModel::GaussianRandom:
            for (Index i = 0; i < nv; ++i)
            {
                // Uniform on the sphere (Archimedes: z uniform in [-1, 1]).
                const Scalar z = 2 * random.uniform() - 1;
                const Scalar phi = 2 * std::numbers::pi * random.uniform();
                const Scalar r = std::sqrt(std::max(Scalar(0), 1 - z * z));
                const Vec3 d{r * std::cos(phi), r * std::sin(phi), z};
                const Scalar offset = sigma * random.normal();
                for (int a = 0; a < 3; ++a)
                    x[3 * i + a] += offset * d[a];
            }
            break;
        case NoiseModel::Impulsive:
        {
            // A partial Fisher-Yates shuffle draws the moved vertices without replacement.
            std::vector<Index> order(static_cast<size_t>(nv));
            for (Index i = 0; i < nv; ++i)
                order[i] = i;
            const Index moved = static_cast<Index>(std::lround(kImpulsiveFraction * nv));
            for (Index k = 0; k < moved; ++k)
            {
                const Index pick = k + static_cast<Index>(random.below(nv - k));
                std::swap(order[k], order[pick]);
                const Index i = order[k];
                const Scalar offset = (random.below(2) ? sigma : -sigma);
                for (int a = 0; a < 3; ++a)
                    x[3 * i + a] += offset * normals[3 * i + a];
            }
            break;
        }
        case NoiseModel::GaussianScan:
            for (Index i = 0; i < nv; ++i)
            {
                const Scalar offset = sigma * random.normal();
                for (int a = 0; a < 3; ++a)
                    x[3 * i + a] += offset * kScanDirection[a];
            }
            break;
    }
    return x;
}

} // namespace meshfair::bench
