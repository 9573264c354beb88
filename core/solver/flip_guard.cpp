// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/flip_guard.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/face_geometry.h"
#include "core/solver/parallel.h"

namespace meshfair {

namespace {

//! Halvings before a vertex's step is given up (t = 0): 1/2, 1/4, 1/8, 1/16.
constexpr int kHalvings = 4;

} // namespace

FlipGuard::FlipGuard(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x0,
                     std::span<const char> fixed)
    : mesh_(&mesh), topology_(&topology), fixed_(fixed.begin(), fixed.end())
{
    const Index nf = mesh.face_count();
    reference_.assign(3 * static_cast<size_t>(nf), 0);
    parallel_for(nf, [&](Index f) {
        const Vec3 n = face_area_vector(mesh, x0, f);
        std::copy(n.begin(), n.end(), &reference_[3 * static_cast<size_t>(f)]);
    });
    for (Index f = 0; f < nf; ++f)
    {
        const Scalar* r = &reference_[3 * static_cast<size_t>(f)];
        const bool has_area = r[0] != 0 || r[1] != 0 || r[2] != 0;
        if (has_area && std::ranges::any_of(mesh.face(f), [&](Index v) { return !fixed[v]; }))
            faces_.push_back(f);
    }
    flagged_.assign(faces_.size(), 0);
}

bool FlipGuard::turned_over(std::span<const Scalar> x, Index f) const
{
    const Scalar* r = &reference_[3 * static_cast<size_t>(f)];
    if (r[0] == 0 && r[1] == 0 && r[2] == 0)
        return false;
    const Vec3 n = face_area_vector(*mesh_, x, f);
    return n[0] * r[0] + n[1] * r[1] + n[2] * r[2] <= 0;
}

Index FlipGuard::limit(std::span<const Scalar> x, std::span<Scalar> y)
{
    shortened_.clear();
    // The faces this step turned over, each flag written by its own face.
    const Index count = static_cast<Index>(faces_.size());
    parallel_for(count, [&](Index k) {
        flagged_[k] = static_cast<char>(turned_over(y, faces_[k]) && !turned_over(x, faces_[k]));
    });
    std::vector<Index> bad;
    for (Index k = 0; k < count; ++k)
        if (flagged_[k])
            bad.push_back(faces_[k]);
    if (bad.empty())
        return 0;
    // Per shortened vertex: its full step and how many times it was halved.
    struct Shortened
    {
        Index vertex;
        Scalar step[3];
        int halvings;
        int round; //!< the last round that shortened it
    };
    std::vector<Shortened> shortened;
    // #V from the topology: the mesh's positions may have been handed to the session.
    std::vector<Index> slot(static_cast<size_t>(topology_->vertex_count), kInvalidIndex);
    std::vector<Index> moved, faces;
    for (int round = 0; !bad.empty(); ++round)
    {
        moved.clear();
        for (const Index f : bad)
            for (const Index v : mesh_->face(f))
            {
                if (fixed_[v])
                    continue;
                if (slot[v] == kInvalidIndex)
                {
                    slot[v] = static_cast<Index>(shortened.size());
                    Shortened s{v, {}, 0, -1};
                    for (int a = 0; a < 3; ++a)
                        s.step[a] =
                            y[3 * static_cast<size_t>(v) + a] - x[3 * static_cast<size_t>(v) + a];
                    shortened.push_back(s);
                }
                Shortened& s = shortened[slot[v]];
                if (s.halvings > kHalvings || s.round == round)
                    continue; // already at x, or already shortened this round
                ++s.halvings;
                s.round = round;
                const Scalar t = s.halvings > kHalvings ? 0 : std::ldexp(Scalar(1), -s.halvings);
                for (int a = 0; a < 3; ++a)
                    y[3 * static_cast<size_t>(v) + a] =
                        x[3 * static_cast<size_t>(v) + a] + t * s.step[a];
                moved.push_back(v);
            }
        // The faces around the vertices moved back, checked again (each once, ascending).
        faces.clear();
        for (const Index v : moved)
            for (const Index corner : topology_->corners_of_vertex(v))
                faces.push_back(topology_->face_of_corner(corner));
        std::ranges::sort(faces);
        faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
        bad.clear();
        for (const Index f : faces)
            if (turned_over(y, f) && !turned_over(x, f))
                bad.push_back(f);
        if (moved.empty())
            break; // every vertex of the faces left is back at x: they were there already
    }
    for (const Shortened& s : shortened)
        shortened_.push_back(s.vertex);
    return static_cast<Index>(shortened.size());
}

} // namespace meshfair
