// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/energies/bending_term.h"

#include <algorithm>

#include "core/errors.h"
#include "core/parallel/parallel.h"

namespace meshfair {

BendingTerm::BendingTerm(const Topology& topology, Scalar mu) : topology_(&topology), mu_(mu)
{
    const Index nv = topology.vertex_count;
    if (!has_parts(topology.parts, TopologyParts::Neighbors | TopologyParts::Edges))
        throw SolverError("BendingTerm: the topology lacks its neighbours or edges");
    // Boundary edges (n_e = 1): each end's count, and its first two neighbours along them.
    std::vector<Index> boundary_degree(nv, 0);
    for (Index e = 0; e < topology.edge_count(); ++e)
        if (topology.edge_face_count(e) == 1)
        {
            const Index ends[2] = {topology.edge_vertices[2 * e],
                                   topology.edge_vertices[2 * e + 1]};
            if (curve_.empty())
                curve_.assign(2 * static_cast<size_t>(nv), kInvalidIndex);
            for (int s = 0; s < 2; ++s)
            {
                const Index v = ends[s];
                if (boundary_degree[v] < 2)
                    curve_[2 * v + boundary_degree[v]] = ends[1 - s];
                ++boundary_degree[v];
            }
        }
    row_size_.assign(nv, 0);
    for (Index v = 0; v < nv; ++v)
    {
        if (boundary_degree[v] == 0)
            row_size_[v] = topology.valence(v);
        else if (boundary_degree[v] == 2)
            row_size_[v] = 2;
        else // where holes touch: no curve to follow
        {
            curve_[2 * v] = curve_[2 * v + 1] = kInvalidIndex;
            row_size_[v] = 0;
        }
        if (boundary_degree[v] == 1)
            curve_[2 * v] = kInvalidIndex;
    }
}

void BendingTerm::set_free(std::span<const Index> free)
{
    const Index nv = topology_->vertex_count;
    free_.assign(free.begin(), free.end());
    needed_.clear();
    // u_k is read at each free vertex and its neighbours.
    std::vector<char> needed(nv, 0);
    for (const Index i : free_)
    {
        needed[i] = 1;
        for (const Index k : topology_->neighbors(i))
            needed[k] = 1;
    }
    for (Index v = 0; v < nv; ++v)
        if (needed[v] && has_row(v))
            needed_.push_back(v);
}

void BendingTerm::umbrella(Index k, const Scalar* x, Scalar* u) const
{
    const Scalar* xk = x + 3 * static_cast<std::ptrdiff_t>(k);
    // Differences first: meshes far from the origin would lose digits to the plain sum.
    Scalar s[3] = {0, 0, 0};
    const auto add = [&](Index j) {
        const Scalar* xj = x + 3 * static_cast<std::ptrdiff_t>(j);
        for (int a = 0; a < 3; ++a)
            s[a] += xj[a] - xk[a];
    };
    if (!curve_.empty() && curve_[2 * k] != kInvalidIndex)
    {
        add(curve_[2 * k]);
        add(curve_[2 * k + 1]);
    }
    else
        for (const Index j : topology_->neighbors(k))
            add(j);
    const Scalar inv = Scalar(1) / static_cast<Scalar>(row_size_[k]);
    for (int a = 0; a < 3; ++a)
        u[a] = s[a] * inv;
}

Scalar BendingTerm::energy(std::span<const Scalar> x) const
{
    return mu_ * deterministic_sum(topology_->vertex_count, [&](Index k) {
               if (!has_row(k))
                   return Scalar(0);
               Scalar u[3];
               umbrella(k, x.data(), u);
               return u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
           });
}

void BendingTerm::add_vertex_energy(std::span<const Scalar> x, std::span<Scalar> per_vertex) const
{
    parallel_for(topology_->vertex_count, [&](Index k) {
        if (!has_row(k))
            return;
        Scalar u[3];
        umbrella(k, x.data(), u);
        per_vertex[k] += mu_ * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    });
}

void BendingTerm::add_diagonal(std::span<Scalar> diagonal) const
{
    for (Index i = 0; i < topology_->vertex_count; ++i)
    {
        Scalar d = has_row(i) ? Scalar(1) : Scalar(0);
        for (const Index k : topology_->neighbors(i))
            if (in_umbrella(k, i))
                d += Scalar(1) / (static_cast<Scalar>(row_size_[k]) * row_size_[k]);
        diagonal[i] += mu_ * d;
    }
}

void BendingTerm::add_hessian_column(Index i, HessianColumn& column) const
{
    // A_B = mu sum_k l_k^T l_k over the rows l_k of L: row k adds mu L_kj L_ki at every j
    // of row k, for each row k that holds i (its own, and its neighbours' that take it).
    const auto add_row = [&](Index k, Scalar lki) {
        const Scalar inv = Scalar(1) / static_cast<Scalar>(row_size_[k]);
        column.add(k, -mu_ * lki);
        if (!curve_.empty() && curve_[2 * k] != kInvalidIndex)
        {
            column.add(curve_[2 * k], mu_ * lki * inv);
            column.add(curve_[2 * k + 1], mu_ * lki * inv);
        }
        else
            for (const Index j : topology_->neighbors(k))
                column.add(j, mu_ * lki * inv);
    };
    if (has_row(i))
        add_row(i, -1);
    for (const Index k : topology_->neighbors(i))
        if (in_umbrella(k, i))
            add_row(k, Scalar(1) / static_cast<Scalar>(row_size_[k]));
}

void BendingTerm::add_rhs(std::span<const Scalar> x, std::span<const Index> vertices,
                          std::span<Scalar> rhs) const
{
    if (vertices.size() != free_.size())
        throw SolverError("BendingTerm::add_rhs: the vertices are not those given to set_free");
    if (u_.size() != 3 * static_cast<size_t>(topology_->vertex_count))
        u_.assign(3 * static_cast<size_t>(topology_->vertex_count), 0);
    parallel_for(static_cast<Index>(needed_.size()), [&](Index n) {
        const Index k = needed_[n];
        umbrella(k, x.data(), &u_[3 * static_cast<size_t>(k)]);
    });
    parallel_for(static_cast<Index>(free_.size()), [&](Index n) {
        const Index i = free_[n];
        Scalar r[3] = {0, 0, 0};
        if (has_row(i))
            for (int a = 0; a < 3; ++a)
                r[a] = u_[3 * static_cast<size_t>(i) + a];
        for (const Index k : topology_->neighbors(i))
            if (in_umbrella(k, i))
            {
                const Scalar inv = Scalar(1) / static_cast<Scalar>(row_size_[k]);
                for (int a = 0; a < 3; ++a)
                    r[a] -= u_[3 * static_cast<size_t>(k) + a] * inv;
            }
        for (int a = 0; a < 3; ++a)
            rhs[3 * static_cast<size_t>(i) + a] += mu_ * r[a];
    });
}

Scalar BendingTerm::held_energy(std::span<const Scalar> x, std::span<const char> is_free) const
{
    Scalar sum = 0;
    for (Index k = 0; k < topology_->vertex_count; ++k)
    {
        if (!has_row(k) || is_free[k])
            continue;
        bool held = true;
        for (const Index j : topology_->neighbors(k))
            held = held && !(is_free[j] && in_umbrella(k, j));
        if (!held)
            continue;
        Scalar u[3];
        umbrella(k, x.data(), u);
        sum += u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    }
    return mu_ * sum;
}

} // namespace meshfair
