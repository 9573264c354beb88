// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/document.h"

#include <atomic>

namespace meshfair::app {

Document load_document(const std::string& path)
{
    io::ReadReport report;
    io::MeshAttributes attributes;
    Mesh mesh = io::read_mesh(path, &report, &attributes);
    LocalityOrder order = locality_order(mesh);
    Document d = make_document(reorder_mesh(mesh, order), path);
    d.order = std::move(order);
    d.report = std::move(report);
    d.attributes = std::move(attributes);
    return d;
}

LocalityOrder identity_order(Index vertices, Index faces)
{
    LocalityOrder o;
    for (std::vector<Index>* v : {&o.vertex_order, &o.vertex_index})
        for (Index i = 0; i < vertices; ++i)
            v->push_back(i);
    for (std::vector<Index>* f : {&o.face_order, &o.face_index})
        for (Index i = 0; i < faces; ++i)
            f->push_back(i);
    return o;
}

Mesh file_order_mesh(const Document& d)
{
    return reorder_mesh(d.mesh, inverse_order(d.order));
}

Document make_document(Mesh mesh, std::string path)
{
    static std::atomic<std::uint64_t> documents_made{0};
    Document d;
    d.id = ++documents_made;
    d.path = std::move(path);
    d.mesh = std::move(mesh);
    d.order = identity_order(d.mesh.vertex_count(), d.mesh.face_count());
    d.topology = build_topology(
        d.mesh, TopologyParts::Neighbors | TopologyParts::Edges | TopologyParts::Corners);
    d.draw_data = mesh_draw_data(d.mesh, d.topology);
    d.box = bounding_box(d.mesh.positions);
    d.base_positions = d.mesh.positions;
    d.selected_vertices.assign(static_cast<size_t>(d.mesh.vertex_count()), 0);
    d.selected_faces.assign(static_cast<size_t>(d.mesh.face_count()), 0);
    return d;
}

Box3 selection_box(const Document& d)
{
    SelectionMask vertices = vertices_of_faces(d.mesh, d.selected_faces);
    for (size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = vertices[i] || d.selected_vertices[i];
    Box3 box;
    for (size_t i = 0; i < vertices.size(); ++i)
        if (vertices[i])
            box.add({d.mesh.positions[3 * i], d.mesh.positions[3 * i + 1],
                     d.mesh.positions[3 * i + 2]});
    return box.empty() ? d.box : box;
}

Box3 bounding_box(std::span<const Scalar> x)
{
    Box3 box;
    for (size_t k = 0; k + 2 < x.size(); k += 3)
        box.add({x[k], x[k + 1], x[k + 2]});
    return box;
}

std::string with_separators(std::int64_t n)
{
    std::string digits = std::to_string(n < 0 ? -n : n);
    for (int k = static_cast<int>(digits.size()) - 3; k > 0; k -= 3)
        digits.insert(static_cast<size_t>(k), ",");
    return (n < 0 ? "-" : "") + digits;
}

} // namespace meshfair::app
