// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/bench/sdfilter_peer.h"

#include <MeshSDFilter/MeshNormalDenoising.h>

#include <iostream>
#include <sstream>
#include <vector>

namespace meshfair::bench {

namespace {

// std::cout and std::cerr sent to a buffer while it lives: the library reports its progress
// there, and meshfair-quality's own output is its tables.
class QuietStreams
{
public:
    QuietStreams() : out_(std::cout.rdbuf(sink_.rdbuf())), err_(std::cerr.rdbuf(sink_.rdbuf())) {}
    ~QuietStreams()
    {
        std::cout.rdbuf(out_);
        std::cerr.rdbuf(err_);
    }
    QuietStreams(const QuietStreams&) = delete;
    QuietStreams& operator=(const QuietStreams&) = delete;

private:
    std::ostringstream sink_;
    std::streambuf* out_;
    std::streambuf* err_;
};

} // namespace

bool sdfilter_denoise(const Mesh& mesh, std::span<Scalar> x, const SdFilterSettings& settings)
{
    TriMesh input;
    std::vector<TriMesh::VertexHandle> vertex;
    vertex.reserve(static_cast<size_t>(mesh.vertex_count()));
    for (Index v = 0; v < mesh.vertex_count(); ++v)
        vertex.push_back(input.add_vertex(TriMesh::Point(x[3 * static_cast<size_t>(v)],
                                                         x[3 * static_cast<size_t>(v) + 1],
                                                         x[3 * static_cast<size_t>(v) + 2])));
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        const std::span<const Index> corners = mesh.face(f);
        for (size_t k = 1; k + 1 < corners.size(); ++k)
            input.add_face(vertex[static_cast<size_t>(corners[0])],
                           vertex[static_cast<size_t>(corners[k])],
                           vertex[static_cast<size_t>(corners[k + 1])]);
    }
    SDFilter::MeshDenoisingParameters p;
    p.lambda = settings.lambda;
    p.eta = settings.eta;
    p.mu = settings.mu;
    p.nu = settings.nu;
    p.outer_iterations = settings.outer_iterations;
    p.mesh_update_closeness_weight = settings.closeness_weight;
    p.mesh_update_iter = settings.update_iterations;
    TriMesh output;
    {
        const QuietStreams quiet;
        SDFilter::MeshNormalDenoising denoiser(input);
        if (!denoiser.denoise(p, output))
            return false;
    }
    if (output.n_vertices() != static_cast<size_t>(mesh.vertex_count()))
        return false;
    for (Index v = 0; v < mesh.vertex_count(); ++v)
    {
        const TriMesh::Point q = output.point(vertex[static_cast<size_t>(v)]);
        for (int a = 0; a < 3; ++a)
            x[3 * static_cast<size_t>(v) + a] = q[a];
    }
    return true;
}

} // namespace meshfair::bench
