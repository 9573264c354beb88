// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/flip_guard.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/face_geometry.h"
#include "core/parallel/parallel.h"

namespace meshfair {

namespace {

//! Halvings before a vertex's step is given up (t = 0): 1/2, 1/4, 1/8, 1/16.
constexpr int kHalvings = 4;
//! cos 60 degrees: a face within 60 degrees of the input surface around it is held to its
//! own input normal too. (Further out it is the noise of a scan, which smoothing turns.)
constexpr Scalar kAgreeCos = 0.5;

Scalar dot3(const Scalar* a, const Scalar* b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

} // namespace

void FlipGuard::face_vectors(std::span<const Scalar> x, std::vector<Scalar>& own,
                             std::vector<Scalar>& around)
{
    const Index nf = mesh_->face_count();
    parallel_for(nf, [&](Index f) {
        const Vec3 n = face_area_vector(*mesh_, x, f);
        std::copy(n.begin(), n.end(), &own[3 * static_cast<size_t>(f)]);
    });
    // The surface around f: the Newell vectors of the faces sharing a vertex with it, each
    // once per vertex it shares (f itself once per corner): the sums at its vertices, summed.
    parallel_for(topology_->vertex_count, [&](Index v) {
        Scalar r[3] = {0, 0, 0};
        for (const Index corner : topology_->corners_of_vertex(v))
        {
            const Scalar* n = &own[3 * static_cast<size_t>(topology_->face_of_corner(corner))];
            for (int a = 0; a < 3; ++a)
                r[a] += n[a];
        }
        std::copy_n(r, 3, &at_vertex_[3 * static_cast<size_t>(v)]);
    });
    parallel_for(nf, [&](Index f) {
        Scalar r[3] = {0, 0, 0};
        for (const Index v : mesh_->face(f))
            for (int a = 0; a < 3; ++a)
                r[a] += at_vertex_[3 * static_cast<size_t>(v) + a];
        std::copy_n(r, 3, &around[3 * static_cast<size_t>(f)]);
    });
}

FlipGuard::FlipGuard(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x0,
                     std::span<const char> fixed)
    : mesh_(&mesh), topology_(&topology), fixed_(fixed.begin(), fixed.end())
{
    const Index nf = mesh.face_count();
    own_.assign(3 * static_cast<size_t>(nf), 0);
    around_.assign(3 * static_cast<size_t>(nf), 0);
    at_vertex_.assign(3 * static_cast<size_t>(topology.vertex_count), 0);
    face_vectors(x0, own_, around_);
    // A face more than 60 degrees from the input surface around it is not held to its own
    // normal (o_f = 0): a scan's noise, or a fold of the input, which smoothing may turn.
    for (Index f = 0; f < nf; ++f)
    {
        Scalar* o = &own_[3 * static_cast<size_t>(f)];
        const Scalar* a = &around_[3 * static_cast<size_t>(f)];
        if (!(dot3(o, a) > kAgreeCos * std::sqrt(dot3(o, o) * dot3(a, a))))
            std::fill_n(o, 3, Scalar(0));
        if (std::ranges::any_of(mesh.face(f), [&](Index v) { return !fixed[v]; }))
            faces_.push_back(f);
    }
    flagged_.assign(faces_.size(), 0);
    now_.assign(3 * static_cast<size_t>(nf), 0);
    slot_.assign(static_cast<size_t>(topology.vertex_count), kInvalidIndex);
}

void FlipGuard::begin_step(std::span<const Scalar> x)
{
    face_vectors(x, now_, around_);
}

int FlipGuard::violations(const Scalar* n, Index f) const
{
    const Scalar* own = &own_[3 * static_cast<size_t>(f)];
    const Scalar* around = &around_[3 * static_cast<size_t>(f)];
    const auto away = [&](const Scalar* r) {
        return (r[0] != 0 || r[1] != 0 || r[2] != 0) && dot3(n, r) <= 0;
    };
    return (away(own) ? 1 : 0) | (away(around) ? 2 : 0);
}

bool FlipGuard::turned_by_step(std::span<const Scalar> y, Index f) const
{
    const Vec3 n = face_area_vector(*mesh_, y, f);
    const int after = violations(n.data(), f);
    // At the step's start its Newell vector is in now_ (begin_step).
    return after != 0 && (after & ~violations(&now_[3 * static_cast<size_t>(f)], f)) != 0;
}

void FlipGuard::begin_jump(std::span<const Scalar> x)
{
    face_vectors(x, now_, around_);
    jump_start_.resize(faces_.size());
    parallel_for(static_cast<Index>(faces_.size()), [&](Index k) {
        const Index f = faces_[k];
        jump_start_[k] = static_cast<char>(violations(&now_[3 * static_cast<size_t>(f)], f) != 0);
    });
}

Index FlipGuard::turned_after_jump(std::span<const Scalar> y)
{
    face_vectors(y, now_, around_);
    const Index count = static_cast<Index>(faces_.size());
    parallel_for(count, [&](Index k) {
        const Index f = faces_[k];
        flagged_[k] = static_cast<char>(!jump_start_[k] &&
                                        violations(&now_[3 * static_cast<size_t>(f)], f) != 0);
    });
    // (limit() writes every flag again before it reads one.)
    return static_cast<Index>(std::count(flagged_.begin(), flagged_.end(), 1));
}

Index FlipGuard::limit(std::span<const Scalar> x, std::span<Scalar> y)
{
    shortened_.clear();
    // The faces this step turned over, each flag written by its own face.
    const Index count = static_cast<Index>(faces_.size());
    parallel_for(count,
                 [&](Index k) { flagged_[k] = static_cast<char>(turned_by_step(y, faces_[k])); });
    std::vector<Index>& bad = bad_;
    bad.clear();
    for (Index k = 0; k < count; ++k)
        if (flagged_[k])
            bad.push_back(faces_[k]);
    if (bad.empty())
        return 0;
    // Per shortened vertex (slot_ its place in steps_): its full step and its halvings.
    std::vector<Shortened>& shortened = steps_;
    shortened.clear();
    std::vector<Index>& slot = slot_;
    std::vector<Index>& moved = moved_;
    std::vector<Index>& faces = rechecked_;
    for (int round = 0; !bad.empty(); ++round)
    {
        moved.clear();
        for (const Index f : bad)
        {
            // The face's free vertex that moves the farthest, and is not back at x yet: the
            // one whose step most likely turned it (the others keep theirs this round).
            Index v = kInvalidIndex;
            Scalar farthest = -1;
            for (const Index w : mesh_->face(f))
            {
                if (fixed_[w] ||
                    (slot[w] != kInvalidIndex && shortened[slot[w]].halvings > kHalvings))
                    continue;
                Scalar d2 = 0;
                for (int a = 0; a < 3; ++a)
                {
                    const Scalar d =
                        y[3 * static_cast<size_t>(w) + a] - x[3 * static_cast<size_t>(w) + a];
                    d2 += d * d;
                }
                if (d2 > farthest)
                    farthest = d2, v = w;
            }
            if (v == kInvalidIndex)
                continue; // every vertex back at x: the face is where it was
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
            if (s.round == round)
                continue; // already shortened this round (for another face)
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
            if (turned_by_step(y, f))
                bad.push_back(f);
        if (moved.empty())
            break; // every vertex of the faces left is back at x: they were there already
    }
    for (const Shortened& s : shortened)
    {
        shortened_.push_back(s.vertex);
        slot[s.vertex] = kInvalidIndex; // the scratch as it was, for the next call
    }
    return static_cast<Index>(shortened.size());
}

Index guard_step(FlipGuard* guard_or_none, VolumeConstraint* volume, std::span<const Scalar> start,
                 std::span<Scalar> x)
{
    if (guard_or_none == nullptr)
    {
        if (volume != nullptr)
            volume->project(x);
        return 0;
    }
    // The guard on the step first, then the volume's correction (usually too small to turn
    // a face), checked in turn; when the guard shortens that too, the vertices it shortened
    // stay where it left them and the others restore the volume, a few rounds at most.
    FlipGuard& guard = *guard_or_none;
    guard.begin_step(start);
    Index shortened = guard.limit(start, x);
    if (volume == nullptr)
        return shortened;
    volume->project(x);
    std::vector<Index> held;
    for (int round = 0;; ++round)
    {
        const Index again = guard.limit(start, x);
        shortened += again;
        if (again == 0 || round == 3)
            break; // (the last check's shortening leaves the volume to the next step)
        held.insert(held.end(), guard.shortened().begin(), guard.shortened().end());
        volume->project(x, held);
    }
    return shortened;
}

Index guard_jump(FlipGuard& guard, std::span<const Index> free, std::span<const Scalar> start,
                 std::span<Scalar> x)
{
    // The whole step shortened by one factor, t = 1, 1/2, ..., 1/2^20, then 0: the energy is
    // a convex quadratic along the step to its minimizer, so it falls for every t in (0, 1]
    // (the per-vertex shortening, right for Jacobi steps, could raise it here). The shape
    // is judged as it stands (FlipGuard::turned_after_jump), not against the noisy
    // surroundings the jump starts from.
    guard.begin_jump(start);
    if (guard.turned_after_jump(x) == 0)
        return 0;
    const std::vector<Scalar> full(x.begin(), x.end()); // the whole step, rarely needed
    Scalar t = 1;
    for (int halving = 1; halving <= 20; ++halving)
    {
        t *= 0.5;
        parallel_for(static_cast<Index>(free.size()), [&](Index k) {
            const size_t i = 3 * static_cast<size_t>(free[k]);
            for (int a = 0; a < 3; ++a)
                x[i + a] = start[i + a] + t * (full[i + a] - start[i + a]);
        });
        if (guard.turned_after_jump(x) == 0)
            return static_cast<Index>(free.size());
    }
    std::copy(start.begin(), start.end(), x.begin());
    return static_cast<Index>(free.size());
}

} // namespace meshfair
