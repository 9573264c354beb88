// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <cstddef>
#include <memory>

namespace meshfair::bench {

//! \brief STREAM's triad a[i] = b[i] + s c[i] over arrays far larger than the caches,
//! with the threads of the benchmark (OpenMP, static schedule, so each thread touches the
//! pages it first wrote). Bandwidth is counted the STREAM way: 24 bytes per element
//! (two reads and one write; the write-allocate read is not counted), so it compares
//! directly with step byte counts made the same way.
class TriadBandwidth
{
public:
    //! \param elements per array; 3 arrays of doubles are allocated and first-touched.
    explicit TriadBandwidth(std::size_t elements);
    //! The best of `trials` timed triads (STREAM's rule: on a shared machine the best
    //! run is the one least disturbed), in bytes per second.
    double measure(int trials = 5);

private:
    double triad();

    std::size_t n_;
    std::unique_ptr<double[]> a_, b_, c_; // not value-initialized: first touch below
};

} // namespace meshfair::bench
