// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <span>

#include "core/mesh/mesh.h"

namespace meshfair::bench {

//! Settings of sdfilter_denoise: its authors' mesh-denoising defaults (the SDFilter
//! repository's DenoisingOptions.txt).
struct SdFilterSettings
{
    double lambda = 2;              //!< regularization weight
    double eta = 1.5;               //!< spatial kernel, times the mean distance between the
                                    //!< centroids of neighbouring faces (rescaled inside)
    double mu = 1.5;                //!< guidance kernel
    double nu = 0.3;                //!< signal kernel
    int outer_iterations = 5;       //!< filter passes, each on the mesh the last one gave
    double closeness_weight = 1e-3; //!< the mesh update's closeness to the input
    int update_iterations = 20;     //!< mesh update iterations
};

//! \brief The static/dynamic filter's mesh denoising (Zhang, Deng, Zhang, Bouaziz, Liu,
//! "Static/Dynamic Filtering for Mesh Geometry", IEEE TVCG 2019 / arXiv 2017), a third
//! reference of meshfair-quality, through Debian's libmeshsdfilter-dev (BSD-3) on an
//! OpenMesh triangle mesh; x (3 #V) is modified in place. Its input must be triangles:
//! polygons are fan-triangulated from their first corner for it (the same vertices, so
//! the positions come back one to one). Its progress messages are kept off stdout.
//! \return false when the library reports a failure (x is then unchanged).
bool sdfilter_denoise(const Mesh& mesh, std::span<Scalar> x, const SdFilterSettings& settings = {});

} // namespace meshfair::bench
