// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/types.h"

namespace meshfair {

//! \brief The paper's indexed face set P = (V, X, F) \cite taubin_2012 ("Representing
//! Polygon Meshes").
//!
//! Positions are one flat array of 3 #V doubles (x0 y0 z0 x1 ...). Faces are polygons
//! of any size >= 3 stored as offsets into one flat index array (CSR): face f is
//! face_vertices[face_offsets[f] .. face_offsets[f+1]). The paper's -1-terminated
//! array holds the same information in the same memory (one marker per face versus
//! one offset per face); offsets give n_f and random access to face f in O(1) and keep
//! sentinel tests out of the solver's inner loops. A position k in face_vertices is a
//! *corner*: corner k belongs to one face and names one vertex.
//!
//! Vertex i and face f are the i-th vertex and f-th face of the file the mesh came
//! from; nothing in MeshFair reorders them. Polygons are never triangulated here.
struct Mesh
{
    std::vector<Scalar> positions;      //!< 3 #V coordinates
    std::vector<Index> face_offsets{0}; //!< #F + 1 offsets, face_offsets[0] = 0
    std::vector<Index> face_vertices;   //!< concatenated faces (corners)

    Index vertex_count() const { return static_cast<Index>(positions.size() / 3); }
    Index face_count() const { return static_cast<Index>(face_offsets.size() - 1); }
    Index corner_count() const { return static_cast<Index>(face_vertices.size()); }
    Index face_size(Index f) const { return face_offsets[f + 1] - face_offsets[f]; }
    std::span<const Index> face(Index f) const
    {
        return {face_vertices.data() + face_offsets[f], static_cast<size_t>(face_size(f))};
    }
    Vec3 position(Index i) const
    {
        return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    }

    //! Appends a vertex and returns its index.
    Index add_vertex(Scalar x, Scalar y, Scalar z);
    //! Appends a face (no validation; see validate_mesh) and returns its index.
    Index add_face(std::span<const Index> vertices);

    friend bool operator==(const Mesh&, const Mesh&) = default;
};

//! \brief Checks the invariants every accepted mesh satisfies: finite coordinates, vertex
//! indices in [0, #V), faces of >= 3 vertices without repetition, consistent offsets.
//! \throw InvalidInputError naming the first offending vertex or face.
void validate_mesh(const Mesh& mesh);

//! \brief FNV-1a (64 bit) of the mesh's content: the vertex count, every coordinate's
//! IEEE-754 bit pattern, the face offsets and the corners, in order. Two meshes have the
//! same hash when they are equal (operator==), bit for bit; the adversarial test suite
//! records it for every file MeshFair accepts, so a change in what a reader produces
//! cannot go unnoticed. Not a cryptographic digest.
std::uint64_t content_hash(const Mesh& mesh);

//! \brief The first vertex repeated in `face`, or kInvalidIndex if all are distinct.
//! Linear expected time; faces are usually tiny so small ones use a quadratic scan.
Index repeated_vertex(std::span<const Index> face);

} // namespace meshfair
