// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/mesh/mesh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "core/errors.h"

namespace meshfair {

Index Mesh::add_vertex(Scalar x, Scalar y, Scalar z)
{
    positions.push_back(x);
    positions.push_back(y);
    positions.push_back(z);
    return vertex_count() - 1;
}

Index Mesh::add_face(std::span<const Index> vertices)
{
    face_vertices.insert(face_vertices.end(), vertices.begin(), vertices.end());
    face_offsets.push_back(static_cast<Index>(face_vertices.size()));
    return face_count() - 1;
}

Index repeated_vertex(std::span<const Index> face)
{
    if (face.size() <= 32)
    {
        for (size_t a = 1; a < face.size(); ++a)
            for (size_t b = 0; b < a; ++b)
                if (face[a] == face[b])
                    return face[a];
        return kInvalidIndex;
    }
    std::vector<Index> sorted(face.begin(), face.end());
    std::sort(sorted.begin(), sorted.end());
    auto it = std::adjacent_find(sorted.begin(), sorted.end());
    return it == sorted.end() ? kInvalidIndex : *it;
}

namespace {

// FNV-1a over the little-endian bytes of one 64-bit word.
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

void mix(std::uint64_t& h, std::uint64_t word)
{
    for (int byte = 0; byte < 8; ++byte)
    {
        h ^= (word >> (8 * byte)) & 0xffu;
        h *= kFnvPrime;
    }
}

} // namespace

std::uint64_t content_hash(const Mesh& mesh)
{
    std::uint64_t h = kFnvOffset;
    mix(h, static_cast<std::uint64_t>(mesh.vertex_count()));
    for (const Scalar x : mesh.positions)
        mix(h, std::bit_cast<std::uint64_t>(x));
    mix(h, static_cast<std::uint64_t>(mesh.face_count()));
    for (const Index o : mesh.face_offsets)
        mix(h, static_cast<std::uint64_t>(o));
    for (const Index v : mesh.face_vertices)
        mix(h, static_cast<std::uint64_t>(v));
    return h;
}

void validate_mesh(const Mesh& mesh)
{
    if (mesh.positions.size() % 3 != 0)
        throw InvalidInputError("validate_mesh: positions hold " +
                                std::to_string(mesh.positions.size()) +
                                " values, not a multiple of 3");
    if (mesh.positions.size() / 3 > static_cast<size_t>(kMaxVertices))
        throw InvalidInputError("validate_mesh: more than " + std::to_string(kMaxVertices) +
                                " vertices");
    for (size_t k = 0; k < mesh.positions.size(); ++k)
        if (!std::isfinite(mesh.positions[k]))
            throw InvalidInputError("validate_mesh: vertex " + std::to_string(k / 3) +
                                    " has a non-finite coordinate");
    if (mesh.face_offsets.empty() || mesh.face_offsets.front() != 0 ||
        static_cast<size_t>(mesh.face_offsets.back()) != mesh.face_vertices.size())
        throw InvalidInputError("validate_mesh: face offsets do not cover the face indices");
    const Index nv = mesh.vertex_count();
    for (Index f = 0; f < mesh.face_count(); ++f)
    {
        if (mesh.face_offsets[f + 1] < mesh.face_offsets[f])
            throw InvalidInputError("validate_mesh: face offsets decrease at face " +
                                    std::to_string(f));
        auto face = mesh.face(f);
        if (face.size() < 3)
            throw InvalidInputError("validate_mesh: face " + std::to_string(f) + " has " +
                                    std::to_string(face.size()) + " vertices (needs >= 3)");
        for (Index v : face)
            if (v < 0 || v >= nv)
                throw InvalidInputError("validate_mesh: face " + std::to_string(f) +
                                        " uses vertex " + std::to_string(v) + " but the mesh has " +
                                        std::to_string(nv) + " vertices");
        if (Index r = repeated_vertex(face); r != kInvalidIndex)
            throw InvalidInputError("validate_mesh: face " + std::to_string(f) +
                                    " repeats vertex " + std::to_string(r));
    }
}

} // namespace meshfair
