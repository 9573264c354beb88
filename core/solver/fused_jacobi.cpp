// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/fused_jacobi.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/parallel/parallel.h"

namespace meshfair {

FusedJacobi::FusedJacobi(const Mesh& mesh, const Topology& topology, FusedTerms terms,
                         std::span<const Index> free, const std::vector<char>& fixed,
                         const JacobiSystem& system, bool normal_shares, const Vec3& centre)
    : mesh_(&mesh),
      topology_(&topology),
      terms_(terms),
      free_(free),
      system_(&system),
      vertex_count_(topology.vertex_count),
      normal_shares_(normal_shares),
      centre_(centre)
{
    const Index nf = mesh.face_count();
    // Each constrained face's centroid residual is computed once per step, for the faces
    // with a free vertex (when that is not all of them, they are listed). A face's vertex
    // is free exactly when it is not fixed: it has n_i >= 2 > 0.
    const auto has_free_vertex = [&](Index f) {
        return std::ranges::any_of(mesh.face(f), [&](Index v) { return fixed[v] == 0; });
    };
    // In the mesh's order: a list given in another numbering (a file's, renumbered for
    // locality) would read faces, corners and positions all over memory, which made the
    // pass slower than the whole sweep. A face's residual does not depend on the order;
    // the energy's sum does, by rounding only. Empty when the term's own list is that list
    // already.
    const auto active_faces = [&](const IndexList& listed, std::vector<Index>& inactive) {
        std::vector<Index> active;
        for (const Index f : listed)
            if (has_free_vertex(f))
                active.push_back(f);
            else
                inactive.push_back(f);
        std::ranges::sort(active);
        std::ranges::sort(inactive);
        if (active.size() == listed.size() &&
            (listed.identity() || std::is_sorted(listed.data(), listed.data() + listed.size())))
            active = {};
        return active;
    };
    if (terms_.centroid)
    {
        centroid_active_ = active_faces(terms_.centroid->faces(), centroid_inactive_);
        share_flag_ = terms_.centroid->flags();
    }
    if (normal_shares_)
    {
        normal_active_ = active_faces(terms_.normal->faces(), normal_inactive_);
        // A corner takes its face's share where either term constrains the face.
        const char* normal_flags = terms_.normal->flags();
        if (!terms_.centroid || normal_flags == nullptr)
            share_flag_ = normal_flags;
        else if (share_flag_ != nullptr)
        {
            share_flag_own_.assign(share_flag_, share_flag_ + nf);
            for (Index f = 0; f < nf; ++f)
                share_flag_own_[f] = static_cast<char>(share_flag_own_[f] | normal_flags[f]);
            share_flag_ = share_flag_own_.data();
        }
    }
    if (terms_.centroid || normal_shares_)
        face_share_.assign(3 * static_cast<size_t>(nf), 0);
    if (terms_.centroid && normal_shares_)
    {
        const FacePass c = centroid_pass(), n = normal_pass();
        shared_face_pass_ =
            c.count == n.count && (c.faces == nullptr || n.faces == nullptr
                                       ? c.faces == n.faces
                                       : std::equal(c.faces, c.faces + c.count, n.faces));
    }
    // The fixed vertices whose parts of the energy move with the free ones.
    if (free_.size() < static_cast<size_t>(vertex_count_))
    {
        std::vector<char> is_free(vertex_count_, 0);
        for (const Index v : free_)
            is_free[v] = 1;
        for (Index v = 0; v < vertex_count_; ++v)
            if (!is_free[v] &&
                std::ranges::any_of(topology.neighbors(v), [&](Index j) { return is_free[j]; }))
                energy_border_.push_back(v);
    }
}

FusedJacobi::FacePass FusedJacobi::face_pass(const std::vector<Index>& active,
                                             const IndexList& listed)
{
    // faces nullptr: every face, in order (IndexList keeps no list of them).
    if (active.empty())
        return {listed.data(), static_cast<Index>(listed.size())};
    return {active.data(), static_cast<Index>(active.size())};
}

template <bool Soft, bool Centroid, bool Normal, bool Energy>
FusedJacobi::Sums FusedJacobi::sweep(const Scalar* x, Scalar* y, Scalar step, bool gradient)
{
    Sums sums;
    TermEnergies& energy = sums.energy;
    // Each constrained face's centroid residual and, on triangles, the normal term's
    // share (FaceNormalTerm::face_share) once per step, summed per face, for the faces a
    // free vertex reads; their corners then add that sum. The normal term's energy is
    // then summed by faces here (fixed_energy adds the faces without a free vertex).
    Scalar* share = face_share_.data();
    const Scalar* normals = terms_.normals.data();
    const FaceCentroidTerm* centroid = terms_.centroid;
    const FaceNormalTerm* normal = terms_.normal;
    if constexpr (Centroid && Normal)
        if (shared_face_pass_) // one walk over the faces for both terms
        {
            const FacePass faces = centroid_pass();
            const auto both = [&](Index begin, Index end) {
                Scalar normal_sum = 0;
                TermEnergies part;
                part.centroid = centroid->face_residuals(
                    x, faces.faces, begin, end, share, [&](Index f) __attribute__((always_inline)) {
                        normal_sum += normal->face_share<Energy>(x, normals, f, share, true);
                    });
                part.normal = normal->energy_of_sum(normal_sum);
                return part;
            };
            energy = block_sums_if<Energy, TermEnergies>(faces.count, both);
        }
    if constexpr (Centroid)
        if (!(Normal && shared_face_pass_))
        {
            const FacePass faces = centroid_pass();
            const auto residuals = [&](Index begin, Index end) {
                return centroid->face_residuals(x, faces.faces, begin, end, share);
            };
            energy.centroid = block_sums_if<Energy, Scalar>(faces.count, residuals);
        }
    if constexpr (Normal)
        if (normal_shares_ && !(Centroid && shared_face_pass_))
        {
            // After the residuals: added to them on the faces the centroid term constrains.
            const FacePass faces = normal_pass();
            const bool add_all = Centroid && centroid->flags() == nullptr;
            const char* add = Centroid ? centroid->flags() : nullptr;
            const auto shares = [&](Index begin, Index end) {
                return normal->face_shares<Energy>(x, normals, faces.faces, begin, end, share,
                                                   add_all, add);
            };
            energy.normal = block_sums_if<Energy, Scalar>(faces.count, shares);
        }
    // The soft and centroid terms weigh their elements through per-vertex weights and
    // per-face residuals; only the normal term's sweep differs with weights.
    const bool all_free = free_.size() == static_cast<size_t>(vertex_count_);
    const bool weighted = Normal && normal->has_weights();
    const Index count = static_cast<Index>(free_.size());
    // Energy: the ranges are deterministic_block_sums' blocks, so that the sums are the
    // same for any thread count; otherwise one range per thread.
    const auto over_free = [&](auto part) { sums += block_sums_if<Energy, Sums>(count, part); };
    if (weighted && all_free)
        over_free([=, this](Index begin, Index end) {
            return range<Soft, Centroid, Normal, true, true, Energy>(x, y, step, gradient, begin,
                                                                     end);
        });
    else if (weighted)
        over_free([=, this](Index begin, Index end) {
            return range<Soft, Centroid, Normal, true, false, Energy>(x, y, step, gradient, begin,
                                                                      end);
        });
    else if (all_free)
        over_free([=, this](Index begin, Index end) {
            return range<Soft, Centroid, Normal, false, true, Energy>(x, y, step, gradient, begin,
                                                                      end);
        });
    else
        over_free([=, this](Index begin, Index end) {
            return range<Soft, Centroid, Normal, false, false, Energy>(x, y, step, gradient, begin,
                                                                       end);
        });
    return sums;
}

template <bool Soft, bool Centroid, bool Normal, bool NormalWeighted, bool AllFree, bool Energy>
FusedJacobi::Sums FusedJacobi::range(const Scalar* x, Scalar* y, Scalar step, bool gradient,
                                     Index begin, Index end) const
{
    // Locals: the loop keeps them in registers (the stores to y could change the object's
    // members for the compiler, which would then load them again).
    const Index* free = free_.data();
    const Scalar* normals = terms_.normals.data();
    const Scalar* inverse = system_->inverse.data();
    const Scalar* diagonal = system_->diagonal.data();
    const Scalar* share = face_share_.data();
    const char* share_flag = share_flag_;
    const bool normal_shares = normal_shares_;
    const CornerWalk walk(*mesh_, *topology_);
    const EdgeTerm& edge = *terms_.edge;
    const SoftVertexTerm* soft = terms_.soft;
    const FaceNormalTerm* normal = terms_.normal;
    const Scalar centre[3] = {centre_[0], centre_[1], centre_[2]};
    // The range's vertices' parts of the energy, each term summed vertex by vertex.
    Scalar e_edge = 0, e_soft = 0, e_normal = 0, r_squared = 0;
    for (Index k = begin; k < end; ++k)
    {
        // Every vertex free (no region, no pins): the free list is 0, 1, ... and is not
        // read (4 bytes per vertex less to stream).
        const Index i = AllFree ? k : free[k];
        // 64 bits before the multiplications: one addressing mode each.
        const std::ptrdiff_t at = 3 * static_cast<std::ptrdiff_t>(i);
        Scalar r[3] = {0, 0, 0};
        edge.add_vertex_rhs(i, x, r);
        if constexpr (Energy) // r holds the edge term's part only here
            e_edge += EdgeTerm::vertex_part(x + at, r, centre);
        if constexpr (Soft)
            soft->add_vertex_rhs<Energy>(i, x, r, &e_soft);
        if constexpr (Centroid || Normal)
            if (Centroid || normal_shares)
                add_corner_shares(*topology_, walk, share_flag, share, i, r);
        if constexpr (Normal)
            if (!normal_shares) // polygons: the corners' parts one by one
                normal->add_vertex_rhs<NormalWeighted, Energy>(i, x, normals, r, &e_normal);
        Scalar dx[3];
        if constexpr (Normal) // the Jacobi method has 3x3 blocks exactly when normals are on
        {
            if (normal_shares)
            {
                // The normal term's c is the energy's centre (the session gives it).
                const Scalar e[3] = {x[at] - centre[0], x[at + 1] - centre[1],
                                     x[at + 2] - centre[2]};
                solve_less_block(&inverse[2 * at], diagonal[i], e, r, dx);
            }
            else
                symmetric3_apply(&inverse[2 * at], r, dx);
        }
        else
        {
            const Scalar inv = Scalar(1) / diagonal[i];
            for (int a = 0; a < 3; ++a)
                dx[a] = r[a] * inv;
        }
        if constexpr (Energy)
            if (gradient)
            {
                // r_i = A_i dx_i: with the normal term's shares the solve took part of r_i
                // (solve_less_block), so it is taken back from the displacement.
                Scalar whole[3] = {r[0], r[1], r[2]};
                if constexpr (Normal)
                    if (normal_shares)
                    {
                        Scalar a[6];
                        symmetric3_inverse(&inverse[2 * at], a);
                        symmetric3_apply(a, dx, whole);
                    }
                r_squared += whole[0] * whole[0] + whole[1] * whole[1] + whole[2] * whole[2];
            }
        for (int a = 0; a < 3; ++a)
            y[at + a] = x[at + a] + step * dx[a];
    }
    Sums sums;
    sums.energy.edge = e_edge;
    sums.energy.soft = e_soft;
    sums.energy.normal = e_normal;
    sums.gradient_squared = r_squared;
    return sums;
}

void FusedJacobi::add_vertex_parts(const Scalar* x, Index i, TermEnergies& e) const
{
    e.edge += terms_.edge->vertex_part(i, x, centre_.data());
    if (terms_.soft)
        e.soft += terms_.soft->vertex_part(i, x);
    if (terms_.normal && !normal_shares_) // else counted by faces (sweep, fixed_energy)
        e.normal += terms_.normal->vertex_part(i, x, terms_.normals.data());
}

TermEnergies FusedJacobi::vertex_parts(const Scalar* x, std::span<const Index> vertices) const
{
    return deterministic_block_sums<TermEnergies>(static_cast<Index>(vertices.size()),
                                                  [&](Index begin, Index end) {
                                                      TermEnergies e;
                                                      for (Index k = begin; k < end; ++k)
                                                          add_vertex_parts(x, vertices[k], e);
                                                      return e;
                                                  });
}

TermEnergies FusedJacobi::fixed_energy(const Scalar* x)
{
    if (!fixed_constant_valid_)
    {
        // Every fixed vertex that is not on the border, in order: the free list and the
        // border are ascending.
        fixed_constant_ = {};
        size_t next_free = 0, next_border = 0;
        for (Index i = 0; i < vertex_count_; ++i)
        {
            if (next_free < free_.size() && free_[next_free] == i)
            {
                ++next_free;
                continue;
            }
            if (next_border < energy_border_.size() && energy_border_[next_border] == i)
            {
                ++next_border;
                continue;
            }
            add_vertex_parts(x, i, fixed_constant_);
        }
        if (!centroid_inactive_.empty())
            fixed_constant_.centroid = terms_.centroid->face_residuals(
                x, centroid_inactive_.data(), 0, static_cast<Index>(centroid_inactive_.size()),
                face_share_.data());
        if (!normal_inactive_.empty())
            fixed_constant_.normal =
                terms_.normal->face_energies(x, terms_.normals.data(), normal_inactive_.data(), 0,
                                             static_cast<Index>(normal_inactive_.size()));
        fixed_constant_valid_ = true;
    }
    TermEnergies energy = fixed_constant_;
    if (!energy_border_.empty())
        energy += vertex_parts(x, energy_border_);
    return energy;
}

TermEnergies FusedJacobi::step(std::span<const Scalar> x, std::span<Scalar> y, bool energy,
                               Scalar step, Scalar* gradient)
{
    // One instance per combination of terms: bit 0 soft, bit 1 centroid, bit 2 normal,
    // bit 3 the energy.
    using Sweep = Sums (FusedJacobi::*)(const Scalar*, Scalar*, Scalar, bool);
    static constexpr std::array<Sweep, 16> sweeps = []<size_t... I>(std::index_sequence<I...>)
    {
        return std::array<Sweep, 16>{
            &FusedJacobi::sweep<(I & 1) != 0, (I & 2) != 0, (I & 4) != 0, (I & 8) != 0>...};
    }
    (std::make_index_sequence<16>{});
    const size_t which = (terms_.soft ? 1 : 0) | (terms_.centroid ? 2 : 0) |
                         (terms_.normal ? 4 : 0) | (energy ? 8 : 0);
    const Sums sums =
        (this->*sweeps[which])(x.data(), y.data(), step, energy && gradient != nullptr);
    TermEnergies e = sums.energy;
    if (energy) // the fixed parts after the sweep's (a sum's order: free, then fixed)
        e += fixed_energy(x.data());
    if (energy && gradient != nullptr)
        *gradient = std::sqrt(sums.gradient_squared);
    return e;
}

} // namespace meshfair
