// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/topology/vertex_order.h"

namespace meshfair {

std::vector<Index> breadth_first_order(const Topology& topology)
{
    const Index n = topology.vertex_count;
    std::vector<Index> order;
    order.reserve(static_cast<size_t>(n));
    std::vector<char> seen(static_cast<size_t>(n), 0);
    for (Index root = 0; root < n; ++root)
    {
        if (seen[root])
            continue;
        // `order` itself is the queue: the vertices after `head` are discovered but not
        // yet expanded.
        seen[root] = 1;
        size_t head = order.size();
        order.push_back(root);
        for (; head < order.size(); ++head)
            for (const Index j : topology.neighbors(order[head]))
                if (!seen[j])
                {
                    seen[j] = 1;
                    order.push_back(j);
                }
    }
    return order;
}

std::vector<Index> inverse_permutation(std::span<const Index> order)
{
    std::vector<Index> inverse(order.size());
    for (size_t k = 0; k < order.size(); ++k)
        inverse[static_cast<size_t>(order[k])] = static_cast<Index>(k);
    return inverse;
}

Mesh renumber_vertices(const Mesh& mesh, std::span<const Index> order)
{
    const std::vector<Index> new_index = inverse_permutation(order);
    Mesh out;
    out.positions.resize(mesh.positions.size());
    for (size_t k = 0; k < order.size(); ++k)
        for (size_t a = 0; a < 3; ++a)
            out.positions[3 * k + a] = mesh.positions[3 * static_cast<size_t>(order[k]) + a];
    out.face_offsets = mesh.face_offsets;
    out.face_vertices.resize(mesh.face_vertices.size());
    for (size_t c = 0; c < mesh.face_vertices.size(); ++c)
        out.face_vertices[c] = new_index[static_cast<size_t>(mesh.face_vertices[c])];
    return out;
}

} // namespace meshfair
