// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <algorithm>
#include <vector>

namespace meshfair::bench {

//! The median of the samples (the mean of the two middle ones for an even count; 0 for
//! none): what every benchmark of the project reports.
inline double median(std::vector<double> samples)
{
    if (samples.empty())
        return 0;
    std::sort(samples.begin(), samples.end());
    const size_t n = samples.size();
    return n % 2 ? samples[n / 2] : (samples[n / 2 - 1] + samples[n / 2]) / 2;
}

} // namespace meshfair::bench
