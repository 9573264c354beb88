// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cmath>
#include <vector>

#include "core/types.h"

namespace meshfair {

//! \brief The per-vertex linear systems of one generalized Jacobi step \cite taubin_2012
//! ("The Jacobi Iteration"): for every free vertex i, A_i dx_i = r_i, where
//! E(x + dx e_i) = E(x) - 2 r_i^T dx + dx^T A_i dx. So r_i = -1/2 dE/dx_i and A_i is
//! half the Hessian block of x_i (or, for the paper's centroid denominator, a
//! majorizer of it; see FaceCentroidTerm).
//!
//! A_i = diagonal[i] I + block_i, where every isotropic term adds to the scalar
//! `diagonal` and the face-normal term adds the symmetric 3x3 `block` (stored as xx xy
//! xz yy yz zz). With blocks present, A_i is inverted once per precomputation (or per
//! step when the normals move, in joint mode), through its Cholesky factor: a step then
//! multiplies r_i by the inverse, nine independent products where the two triangular
//! solves were a chain of dependent ones.
struct JacobiSystem
{
    std::vector<Scalar> diagonal; //!< #V; empty once inverted into `inverse` for good
    //! 6 #V; empty when no term adds one, and once inverted (in place, becoming `inverse`)
    //! when the normals never move
    std::vector<Scalar> block;
    std::vector<Scalar> inverse; //!< 6 #V: A_i^-1 (xx xy xz yy yz zz); empty without blocks
    std::vector<Scalar> rhs;     //!< 3 #V
};

//! Cholesky factor L of the SPD matrix (d I + B), B given as xx xy xz yy yz zz, stored
//! as 1/l00 l10 1/l11 l20 l21 1/l22 (row-major lower triangle with the diagonal inverted:
//! cholesky3_solve then multiplies where it would divide). False when not positive
//! definite. B and L may be the same six values (factoring in place): B is read whole
//! before L is written.
inline bool cholesky3(Scalar d, const Scalar* B, Scalar* L)
{
    const Scalar a00 = d + B[0], a10 = B[1], a20 = B[2], a11 = d + B[3], a21 = B[4], a22 = d + B[5];
    if (!(a00 > 0))
        return false;
    const Scalar l00 = std::sqrt(a00);
    const Scalar l10 = a10 / l00, l20 = a20 / l00;
    const Scalar s11 = a11 - l10 * l10;
    if (!(s11 > 0))
        return false;
    const Scalar l11 = std::sqrt(s11);
    const Scalar l21 = (a21 - l20 * l10) / l11;
    const Scalar s22 = a22 - l20 * l20 - l21 * l21;
    if (!(s22 > 0))
        return false;
    L[0] = 1 / l00;
    L[1] = l10;
    L[2] = 1 / l11;
    L[3] = l20;
    L[4] = l21;
    L[5] = 1 / std::sqrt(s22);
    return true;
}

//! Solves L L^T x = r with a factor from cholesky3.
inline void cholesky3_solve(const Scalar* L, const Scalar* r, Scalar* x)
{
    const Scalar y0 = r[0] * L[0];
    const Scalar y1 = (r[1] - L[1] * y0) * L[2];
    const Scalar y2 = (r[2] - L[3] * y0 - L[4] * y1) * L[5];
    x[2] = y2 * L[5];
    x[1] = (y1 - L[4] * x[2]) * L[2];
    x[0] = (y0 - L[1] * x[1] - L[3] * x[2]) * L[0];
}

//! \brief The inverse of the SPD matrix d I + B (B as xx xy xz yy yz zz), as the same
//! six entries, from cholesky3's factor: (L L^T)^-1 = L^-T L^-1. False when not positive
//! definite. B and the inverse may be the same six values.
inline bool spd_inverse3(Scalar d, const Scalar* B, Scalar* inverse)
{
    Scalar L[6];
    if (!cholesky3(d, B, L))
        return false;
    // M = L^-1, lower triangular; L holds 1/l00 l10 1/l11 l20 l21 1/l22.
    const Scalar m00 = L[0], m11 = L[2], m22 = L[5];
    const Scalar m10 = -L[1] * m00 * m11;
    const Scalar m21 = -L[4] * m11 * m22;
    const Scalar m20 = -(L[3] * m00 + L[4] * m10) * m22;
    inverse[0] = m00 * m00 + m10 * m10 + m20 * m20;
    inverse[1] = m10 * m11 + m20 * m21;
    inverse[2] = m20 * m22;
    inverse[3] = m11 * m11 + m21 * m21;
    inverse[4] = m21 * m22;
    inverse[5] = m22 * m22;
    return true;
}

//! x = M r for a symmetric 3x3 M given as xx xy xz yy yz zz.
inline void symmetric3_apply(const Scalar* M, const Scalar* r, Scalar* x)
{
    x[0] = M[0] * r[0] + M[1] * r[1] + M[2] * r[2];
    x[1] = M[1] * r[0] + M[3] * r[1] + M[4] * r[2];
    x[2] = M[2] * r[0] + M[4] * r[1] + M[5] * r[2];
}

//! The inverse of a symmetric positive definite 3x3 matrix M (xx xy xz yy yz zz), by its
//! adjugate: the fused step's way back from A_i^-1 to A_i (for |A_i dx_i|, the gradient).
inline void symmetric3_inverse(const Scalar* M, Scalar* inverse)
{
    const Scalar c00 = M[3] * M[5] - M[4] * M[4], c01 = M[2] * M[4] - M[1] * M[5],
                 c02 = M[1] * M[4] - M[2] * M[3], c11 = M[0] * M[5] - M[2] * M[2],
                 c12 = M[1] * M[2] - M[0] * M[4], c22 = M[0] * M[3] - M[1] * M[1];
    const Scalar inv_det = Scalar(1) / (M[0] * c00 + M[1] * c01 + M[2] * c02);
    inverse[0] = c00 * inv_det;
    inverse[1] = c01 * inv_det;
    inverse[2] = c02 * inv_det;
    inverse[3] = c11 * inv_det;
    inverse[4] = c12 * inv_det;
    inverse[5] = c22 * inv_det;
}

//! \brief Solves (d I + B) dx = r - (3/2) B e with the inverse of d I + B
//! (spd_inverse3), without B: B e = (d I + B) e - d e, so dx = (d I + B)^-1 (r + (3/2) d e) -
//! (3/2) e. The fused step's normal term on triangles leaves its -(3/2) B e to this
//! (FaceNormalTerm::face_share), e being x_i - c, c near the mesh: the rounding is then
//! about 1e-16 of the mesh's size. r is overwritten.
inline void solve_less_block(const Scalar* inverse, Scalar d, const Scalar* e, Scalar* r,
                             Scalar* dx)
{
    const Scalar h = Scalar(1.5) * d;
    for (int a = 0; a < 3; ++a)
        r[a] += h * e[a];
    symmetric3_apply(inverse, r, dx);
    for (int a = 0; a < 3; ++a)
        dx[a] -= Scalar(1.5) * e[a];
}

} // namespace meshfair
