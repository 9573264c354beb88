// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include "core/types.h"

namespace meshfair {

//! What one range of the plain Laplacian sweep reads and writes (raw arrays: the sweep is
//! the innermost loop of the solver).
struct PlainSweep
{
    const Index* free = nullptr;      //!< the free vertices
    const Index* offsets = nullptr;   //!< V(i) of vertex i: neighbors[offsets[i] .. offsets[i+1])
    const Index* neighbors = nullptr; //!< concatenated V(i)
    const Scalar* diagonal = nullptr; //!< n_i (the Jacobi diagonal of E_L)
    Scalar lambda = 0;                //!< step length
    const Scalar* x = nullptr;        //!< positions, 3 #V
    Scalar* y = nullptr;              //!< output, 3 #V, written at free vertices only
};

//! \brief The fused plain Laplacian step \cite taubin_2012 ("Laplacian Smoothing") over
//! the free vertices free[begin .. end):
//!
//!     y_i = x_i + lambda (1 / n_i) sum_{j in V(i)} (x_j - x_i)
//!
//! the generalized Jacobi step of E_L alone, each vertex gathering its own sum (no
//! scatter). Differences first, then the sum, in V(i)'s order: the operations, and so the
//! bits, of EdgeTerm::add_vertex_rhs followed by the diagonal solve.
//!
//! On x86-64 processors with AVX2 (checked once, at run time) a vertex's three
//! coordinates travel as one 256-bit lane group: one masked load, one subtraction and one
//! addition per neighbour instead of five instructions for x and y as a pair and z alone.
//! The sweep is bound by its instruction count (docs/performance.md), and each lane does
//! exactly the scalar sweep's operations (no fused multiply-add), so both give the same
//! bits (tested).
//! \pre x and y do not overlap.
void plain_sweep(const PlainSweep& s, Index begin, Index end);

namespace detail {
//! The portable sweep.
void plain_sweep_scalar(const PlainSweep& s, Index begin, Index end);
//! The AVX2 sweep; false (and nothing written) where the processor lacks AVX2.
bool plain_sweep_avx2(const PlainSweep& s, Index begin, Index end);
} // namespace detail

} // namespace meshfair
