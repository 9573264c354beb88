// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>
#include <vector>

#include "core/energies/volume_constraint.h"
#include "core/mesh/mesh.h"
#include "core/topology/topology.h"

namespace meshfair {

//! \brief Keeps a solver step from turning faces over. A face f is turned over at x when its
//! Newell vector n_f(x) points away (n_f . r <= 0: more than 90 degrees) from
//!  - o_f, its own input Newell vector, unless the input face is more than 60 degrees from
//!    the input surface around it (a scan's noise, or a fold of the input: smoothing may
//!    turn it, and turning it back is what smoothing is for), or from
//!  - a_f(x), the surface around it where the step starts: the sum of the Newell vectors
//!    of the faces sharing a vertex with it (each once per vertex it shares), so that no
//!    step folds a face over its neighbours, on a noisy scan as on a clean model.
//! After a step from x to y (begin_step(x) first), each face that the step turned over (that
//! breaks a reference it kept at x) has the step of its free vertex that moves the farthest
//! shortened, y_i = x_i + t_i (y_i - x_i) with t_i = 1/2, 1/4, 1/8, 1/16 and then 0, and
//! the faces around the shortened vertices are checked again, until none is turned over: a
//! per-vertex backtracking line search on the orientation of the vertex's star
//! (docs/math.md, "Faces never turned over"). It ends: each round shortens a vertex of
//! every face still turned over, and with all its vertices' t_i = 0 a face is where it was
//! at x.
class FlipGuard
{
public:
    //! \pre the topology has TopologyParts::Corners; x0: 3 #V input positions (o_f);
    //! fixed: #V flags of the vertices no step moves.
    FlipGuard(const Mesh& mesh, const Topology& topology, std::span<const Scalar> x0,
              std::span<const char> fixed);

    //! The surface around each face at x, the step's start (a_f): once per step, before
    //! limit() (which may run several times on the step).
    void begin_step(std::span<const Scalar> x);
    //! \brief Shortens the step x -> y where it turns faces over (y written at free
    //! vertices only). Returns how many vertices' steps were shortened. The same bits for
    //! any thread count; allocates only while its lists grow past their largest so far.
    Index limit(std::span<const Scalar> x, std::span<Scalar> y);
    //! \brief For a jump to a solve's result (the direct method), not a step: notes which
    //! faces are turned over at x, where the jump starts (once, before turned_after_jump).
    void begin_jump(std::span<const Scalar> x);
    //! \brief How many faces with a free vertex are turned over at y but were not at the
    //! jump's start, each judged against its own input normal (where it is held to it) and
    //! against the surface around it at the same shape (folded over its neighbours there),
    //! not at the jump's start, which a noisy scan's faces would break on their way to a
    //! smooth result. Allocates nothing.
    Index turned_after_jump(std::span<const Scalar> y);
    //! The vertices whose steps the last limit() shortened, in the order it shortened them.
    std::span<const Index> shortened() const { return shortened_; }

private:
    //! A vertex whose step limit() shortened: its full step and how many times it halved it.
    struct Shortened
    {
        Index vertex;
        Scalar step[3];
        int halvings;
        int round; //!< the last round that shortened it
    };

    //! Each face's Newell vector at x (own) and the sum around it (around), 3 #F each.
    void face_vectors(std::span<const Scalar> x, std::vector<Scalar>& own,
                      std::vector<Scalar>& around);
    //! For the Newell vector n of face f: bit 0, n points away from o_f; bit 1, from a_f.
    int violations(const Scalar* n, Index f) const;
    //! The step to y breaks a reference that face f kept at the step's start (begin_step).
    bool turned_by_step(std::span<const Scalar> y, Index f) const;

    const Mesh* mesh_;
    const Topology* topology_;
    std::vector<Scalar> own_;       //!< 3 #F: o_f (0 where the face is not held to it)
    std::vector<Scalar> around_;    //!< 3 #F: a_f at the step's start
    std::vector<Scalar> now_;       //!< 3 #F: the Newell vectors at the step's start
    std::vector<Scalar> at_vertex_; //!< 3 #V scratch: the Newell vectors' sum at each vertex
    std::vector<Index> faces_;      //!< the faces with a free vertex, ascending
    std::vector<char> fixed_;       //!< #V
    std::vector<char> flagged_;     //!< per entry of faces_: turned over by this step
    std::vector<char> jump_start_;  //!< per entry of faces_: turned over where a jump starts
    std::vector<Index> shortened_;  //!< the last limit()'s shortened vertices
    // limit()'s scratch, kept from call to call (it runs at every step): each vertex's place
    // in steps_ (#V, kInvalidIndex between calls), the faces turned over, the vertices
    // moved back and the faces checked again in a round.
    std::vector<Index> slot_, bad_, moved_, rechecked_;
    std::vector<Shortened> steps_;
};

//! \brief The guard on a Jacobi step start -> x with the volume's correction after it:
//! shortens the steps that turn faces over, restores the volumes, and checks that
//! correction in turn (the vertices shortened then stay, the others restore the volumes:
//! VolumeConstraint::project with `hold`), up to 3 rounds. Returns the count of shortened
//! vertex steps. Without a guard (nullptr), the volume's correction alone (volume may be
//! nullptr too: nothing).
Index guard_step(FlipGuard* guard, VolumeConstraint* volume, std::span<const Scalar> start,
                 std::span<Scalar> x);
//! \brief The guard on a jump start -> x to a solve's result (the direct and implicit
//! methods): the whole jump shortened by the largest factor 2^-k (k <= 20, else 0) at
//! which no face is turned over that was not at `start` (FlipGuard::turned_after_jump).
//! Returns how many vertex steps it shortened (every free vertex's, or none).
Index guard_jump(FlipGuard& guard, std::span<const Index> free, std::span<const Scalar> start,
                 std::span<Scalar> x);

} // namespace meshfair
