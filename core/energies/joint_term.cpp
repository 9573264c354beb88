// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/joint_term.h"

#include <algorithm>

#include "core/parallel/parallel.h"
#include "core/solver/jacobi_system.h"

namespace meshfair {

JointTerm::JointTerm(const FaceNormalTerm& normal_term, const NormalSmoothingTerm& smoothing,
                     const Topology& topology, Scalar gamma)
    : normal_term_(&normal_term), smoothing_(&smoothing), topology_(&topology), gamma_(gamma)
{
}

void JointTerm::normal_rhs(std::span<const Scalar> x, std::span<const Scalar> u, Index f,
                           Scalar* r) const
{
    const Scalar* uf = &u[3 * f];
    Scalar M[6] = {0, 0, 0, 0, 0, 0};
    if (normal_term_->constrains(f))
        normal_term_->edge_scatter(x, f, M);
    const Scalar mu = normal_term_->face_weight(f);
    const Scalar Mu[3] = {M[0] * uf[0] + M[1] * uf[1] + M[2] * uf[2],
                          M[1] * uf[0] + M[3] * uf[1] + M[4] * uf[2],
                          M[2] * uf[0] + M[4] * uf[1] + M[5] * uf[2]};
    const Scalar ws = smoothing_->soft_weight(f);
    const Scalar* u0 = smoothing_->soft_target(f);
    for (int a = 0; a < 3; ++a)
        r[a] = -mu * Mu[a] + ws * (u0[a] - uf[a]);
    smoothing_->for_each_neighbor(f, [&](Index g, Scalar w) {
        for (int a = 0; a < 3; ++a)
            r[a] += gamma_ * w * (u[3 * g + a] - uf[a]);
    });
}

bool JointTerm::minimizer(std::span<const Scalar> x, std::span<const Scalar> u, Index f,
                          Scalar* out) const
{
    Scalar M[6] = {0, 0, 0, 0, 0, 0};
    if (normal_term_->constrains(f))
    {
        normal_term_->edge_scatter(x, f, M);
        for (Scalar& m : M)
            m *= normal_term_->face_weight(f);
    }
    const Scalar ws = smoothing_->soft_weight(f);
    const Scalar d = gamma_ * smoothing_->neighbor_weight_sum(f) + ws;
    Scalar L[6];
    if (!cholesky3(d, M, L))
        return false;
    Scalar b[3];
    const Scalar* u0 = smoothing_->soft_target(f);
    for (int a = 0; a < 3; ++a)
        b[a] = ws * u0[a];
    smoothing_->for_each_neighbor(f, [&](Index g, Scalar w) {
        for (int a = 0; a < 3; ++a)
            b[a] += gamma_ * w * u[3 * g + a];
    });
    cholesky3_solve(L, b, out);
    return true;
}

void JointTerm::update_normals(std::span<const Scalar> x, std::span<Scalar> u, Scalar lambda,
                               std::span<Scalar> scratch) const
{
    const Index faces = topology_->face_count;
    // All minimizers from the old normals first (Jacobi), then the updates; each face's
    // own work, the same bits on any thread count.
    parallel_for(faces, [&](Index f) {
        Scalar* target = &scratch[3 * f];
        if (smoothing_->is_hard(f) || !minimizer(x, u, f, target))
            std::copy_n(&u[3 * f], 3, target);
    });
    parallel_for(faces, [&](Index f) {
        if (smoothing_->is_hard(f))
            return;
        Scalar next[3];
        for (int a = 0; a < 3; ++a)
            next[a] = u[3 * f + a] + lambda * (scratch[3 * f + a] - u[3 * f + a]);
        if (normalize3(next))
            std::copy_n(next, 3, &u[3 * f]);
    });
}

} // namespace meshfair
