// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <cstring>
#include <span>

#include "core/energies/position_term.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief The sum of squared edge lengths \cite taubin_2012 ("Laplacian Smoothing"):
//!
//!     E_L(x) = sum_{(i,j) in E} |x_j - x_i|^2,          x of size 3 #V
//!
//! Quadratic, homogeneous, positive semi-definite; its minimum 0 is reached when all
//! connected vertices coincide (the "shrinkage" of Laplacian smoothing).
//! Gradient: dE_L/dx_i = 2 sum_{j in V(i)} (x_i - x_j) (the paper omits the factor 2,
//! which no Jacobi displacement depends on). Generalized Jacobi: diagonal n_i,
//! right-hand side sum_{j in V(i)} (x_j - x_i), so dx_i is the paper's Laplacian
//! smoothing displacement (1/n_i) sum_j (x_j - x_i). Vertices with n_i = 0 get no
//! contribution (and do not move unless another term moves them).
class EdgeTerm final : public PositionTerm
{
public:
    explicit EdgeTerm(const Topology& topology) : topology_(&topology) {}
    //! \brief Scales the term by w >= 0: w E_L (1, the paper's, by default; the bending
    //! section's "membrane" weight). Every method below scales with it, except the fused
    //! step's add_vertex_rhs and vertex_part, which are the paper's w = 1 (the session does
    //! not fuse a step with another weight). w = 1 gives the same bits as no weight.
    void set_weight(Scalar w) { weight_ = w; }
    Scalar weight() const { return weight_; }

    EnergyTerm kind() const override { return EnergyTerm::Edge; }
    Scalar energy(std::span<const Scalar> x) const override;
    //! \brief Adds each vertex's share of energy(x) to per_vertex (#V): half of each
    //! edge's |x_j - x_i|^2 to each end, so the shares sum to the energy.
    void add_vertex_energy(std::span<const Scalar> x, std::span<Scalar> per_vertex) const override;
    //! The edges with neither end free.
    Scalar held_energy(std::span<const Scalar> x, std::span<const char> is_free) const override;
    //! E_L(dx): the quadratic part, so E_L(x + dx) = E_L(x) - 2 r^T dx + quadratic(dx).
    Scalar quadratic(std::span<const Scalar> dx) const override { return energy(dx); }
    //! diagonal[i] += n_i for every vertex.
    void add_diagonal(std::span<Scalar> diagonal) const override;
    //! Column i of the half Hessian (the graph Laplacian L, E_L = sum_a x_a^T L x_a over
    //! the coordinates a): n_i at i, -1 at each neighbour. The direct method's matrix.
    void add_hessian_column(Index i, HessianColumn& column) const override
    {
        const std::span<const Index> neighbors = topology_->neighbors(i);
        column.add(i, weight_ * static_cast<Scalar>(neighbors.size()));
        for (const Index j : neighbors)
            column.add(j, -weight_);
    }
    //! rhs_i += w sum_{j in V(i)} (x_j - x_i) for each i in `vertices` (gathered, no scatter).
    void add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                 std::span<Scalar> rhs) const override;
    //! The same for one vertex: r[0..2] += sum_{j in V(i)} (x_j - x_i). Inline, for the
    //! fused step, which adds every term's part of r_i in one sweep.
    void add_vertex_rhs(Index i, const Scalar* x, Scalar* r) const
    {
        // Differences first, then the sum: meshes far from the origin (scans in
        // millimetres at 10^3) would lose digits to sum_j x_j - n_i x_i.
        // x and y as one pair: the sweep's cost is its instruction count per neighbour.
        using Pair = Scalar __attribute__((vector_size(2 * sizeof(Scalar))));
        const Scalar* xi = x + 3 * static_cast<std::ptrdiff_t>(i);
        Pair x01;
        std::memcpy(&x01, xi, sizeof x01);
        const Scalar x2 = xi[2];
        const Index* neighbors = topology_->vertex_neighbors.data();
        Pair s01 = {0, 0};
        Scalar s2 = 0;
        for (Index n = topology_->vertex_offsets[i]; n < topology_->vertex_offsets[i + 1]; ++n)
        {
            // 64-bit before the multiplication: the address is then one addressing mode.
            const Scalar* q = x + 3 * static_cast<std::ptrdiff_t>(neighbors[n]);
            Pair q01;
            std::memcpy(&q01, q, sizeof q01);
            s01 += q01 - x01;
            s2 += q[2] - x2;
        }
        r[0] += s01[0];
        r[1] += s01[1];
        r[2] += s2;
    }
    //! \brief Vertex i's part of energy(x) by the identity E_L = -sum_i (x_i - c)^T r_i
    //! (E_L is a homogeneous quadratic, x^T L x with r = -L x, and sum_i r_i = 0 makes any
    //! constant c exact; c near the mesh keeps the products small): the fused step adds
    //! it from the r_i it computes anyway, 6 flops a vertex instead of 6 a neighbour.
    static Scalar vertex_part(const Scalar* xi, const Scalar* r, const Scalar* centre)
    {
        return -((xi[0] - centre[0]) * r[0] + (xi[1] - centre[1]) * r[1] +
                 (xi[2] - centre[2]) * r[2]);
    }
    //! vertex_part with r_i computed here (the vertices the fused sweep does not visit).
    Scalar vertex_part(Index i, const Scalar* x, const Scalar* centre) const
    {
        Scalar r[3] = {0, 0, 0};
        add_vertex_rhs(i, x, r);
        return vertex_part(x + 3 * static_cast<std::ptrdiff_t>(i), r, centre);
    }

private:
    const Topology* topology_;
    Scalar weight_ = 1;
};

} // namespace meshfair
