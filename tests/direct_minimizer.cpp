// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "tests/direct_minimizer.h"

#include <doctest/doctest.h>

#include <Eigen/Sparse>

#include <map>
#include <set>

#include "core/geometry/face_geometry.h"

namespace meshfair::test {

namespace {

// mu * weights[k], the weight of the k-th listed element.
Scalar element_weight(Scalar mu, const std::vector<Scalar>& weights, size_t k)
{
    return weights.empty() ? mu : mu * weights[k];
}

// mu L^T L of the squared umbrella operator, from the faces alone: each edge's face count
// (1: a boundary edge), each vertex's neighbours, then rows u_k = (1/m_k) sum_{U(k)} x_j -
// x_k with U(k) all neighbours inside, the two boundary neighbours on a boundary, and no
// row for other boundary vertices (BendingTerm's definition).
template <class Add>
void add_bending(const Mesh& m, double mu, Add& add)
{
    const Index nv = m.vertex_count();
    std::map<std::pair<Index, Index>, int> faces_at_edge;
    for (Index f = 0; f < m.face_count(); ++f)
    {
        const auto face = m.face(f);
        for (size_t c = 0; c < face.size(); ++c)
        {
            const Index i = face[c], j = face[(c + 1) % face.size()];
            ++faces_at_edge[{std::min(i, j), std::max(i, j)}];
        }
    }
    std::vector<std::set<Index>> neighbours(nv), boundary(nv);
    for (const auto& [edge, count] : faces_at_edge)
    {
        neighbours[edge.first].insert(edge.second);
        neighbours[edge.second].insert(edge.first);
        if (count == 1)
        {
            boundary[edge.first].insert(edge.second);
            boundary[edge.second].insert(edge.first);
        }
    }
    for (Index k = 0; k < nv; ++k)
    {
        const std::set<Index>& u = boundary[k].empty() ? neighbours[k] : boundary[k];
        if (u.empty() || (!boundary[k].empty() && boundary[k].size() != 2))
            continue;
        // Row l_k: -1 at k, 1/m at each j of U(k); A += mu l_k^T l_k.
        std::vector<std::pair<Index, double>> row{{k, -1.0}};
        for (const Index j : u)
            row.emplace_back(j, 1.0 / static_cast<double>(u.size()));
        for (const auto& [p, vp] : row)
            for (const auto& [q, vq] : row)
                for (int a = 0; a < 3; ++a)
                    add(3 * p + a, 3 * q + a, mu * vp * vq);
    }
}

} // namespace

std::vector<Scalar> direct_minimizer(const Mesh& m, const Topology& t, const Recipe& r,
                                     std::span<const Scalar> x_start,
                                     std::span<const Index> free_vertices)
{
    const Index n = 3 * m.vertex_count();
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    auto add = [&](Index p, Index q, double v) { entries.emplace_back(p, q, v); };
    const double membrane = r.bending ? r.bending->membrane : 1.0;
    for (Index e = 0; e < t.edge_count(); ++e)
    {
        const Index i = t.edge_vertices[2 * e], j = t.edge_vertices[2 * e + 1];
        for (int a = 0; a < 3; ++a)
        {
            add(3 * i + a, 3 * i + a, membrane);
            add(3 * j + a, 3 * j + a, membrane);
            add(3 * i + a, 3 * j + a, -membrane);
            add(3 * j + a, 3 * i + a, -membrane);
        }
    }
    if (r.bending)
        add_bending(m, r.bending->mu, add);
    const std::span<const Scalar> x0 = m.positions;
    if (r.soft)
        for (size_t k = 0; k < r.soft->vertices.indices.size(); ++k)
        {
            const Index i = r.soft->vertices.indices[k];
            const Scalar w = element_weight(r.soft->mu, r.soft->weights, k);
            for (int a = 0; a < 3; ++a)
            {
                add(3 * i + a, 3 * i + a, w);
                b[3 * i + a] +=
                    w * (r.soft->targets.empty() ? x0[3 * i + a] : r.soft->targets[k][a]);
            }
        }
    if (r.centroid)
        for (size_t k = 0; k < r.centroid->faces.indices.size(); ++k)
        {
            const Index f = r.centroid->faces.indices[k];
            const Scalar w = element_weight(r.centroid->mu, r.centroid->weights, k);
            const auto face = m.face(f);
            const double nf = static_cast<double>(face.size());
            const Vec3 c =
                r.centroid->targets.empty() ? face_centroid(m, x0, f) : r.centroid->targets[k];
            for (const Index p : face)
                for (int a = 0; a < 3; ++a)
                {
                    for (const Index q : face)
                        add(3 * p + a, 3 * q + a, w / (nf * nf));
                    b[3 * p + a] += w / nf * c[a];
                }
        }
    if (r.normal)
    {
        const std::vector<Scalar> u = face_normals(m, x0);
        for (size_t k = 0; k < r.normal->faces.indices.size(); ++k)
        {
            const Index f = r.normal->faces.indices[k];
            const Scalar mu = element_weight(r.normal->mu, r.normal->weights, k);
            const auto face = m.face(f);
            for (size_t c = 0; c < face.size(); ++c)
            {
                const Index i = face[c], j = face[(c + 1) % face.size()];
                for (int a = 0; a < 3; ++a)
                    for (int d = 0; d < 3; ++d)
                    {
                        const double w = mu * u[3 * f + a] * u[3 * f + d];
                        add(3 * i + a, 3 * i + d, w);
                        add(3 * j + a, 3 * j + d, w);
                        add(3 * i + a, 3 * j + d, -w);
                        add(3 * j + a, 3 * i + d, -w);
                    }
            }
        }
    }
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    // Restrict to free coordinates: A_FF x_F = b_F - A_FC x_C.
    std::vector<Index> slot(n, -1);
    Index nfree = 0;
    for (const Index v : free_vertices)
        for (int a = 0; a < 3; ++a)
            slot[3 * v + a] = nfree++;
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(x_start.data(), n);
    std::vector<Eigen::Triplet<double>> ff;
    Eigen::VectorXd rhs(nfree);
    for (Index p = 0; p < n; ++p)
        if (slot[p] >= 0)
            rhs[slot[p]] = b[p];
    for (int k = 0; k < A.outerSize(); ++k)
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
        {
            const Index p = static_cast<Index>(it.row()), q = static_cast<Index>(it.col());
            if (slot[p] < 0)
                continue;
            if (slot[q] >= 0)
                ff.emplace_back(slot[p], slot[q], it.value());
            else
                rhs[slot[p]] -= it.value() * x[q];
        }
    Eigen::SparseMatrix<double> Aff(nfree, nfree);
    Aff.setFromTriplets(ff.begin(), ff.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(Aff);
    REQUIRE(solver.info() == Eigen::Success);
    const Eigen::VectorXd xf = solver.solve(rhs);
    std::vector<Scalar> out(x_start.begin(), x_start.end());
    for (Index p = 0; p < n; ++p)
        if (slot[p] >= 0)
            out[p] = xf[slot[p]];
    return out;
}

} // namespace meshfair::test
