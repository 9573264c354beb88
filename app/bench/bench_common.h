// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// What the benchmarks share: their statistic, their figures' form, and where they find
// the programs they time beside them.
#pragma once

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
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

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline double ms_since(std::chrono::steady_clock::time_point start)
{
    return 1000 * seconds_since(start);
}

//! The largest sample (0 for none): what a benchmark reports beside the median.
inline double max_of(const std::vector<double>& samples)
{
    return samples.empty() ? 0 : *std::max_element(samples.begin(), samples.end());
}

//! n with thousands separated by commas ("1,250,000").
inline std::string human_count(long n)
{
    std::string digits = std::to_string(n);
    for (int k = static_cast<int>(digits.size()) - 3; k > 0; k -= 3)
        digits.insert(static_cast<size_t>(k), ",");
    return digits;
}

//! This program's path (/proc/self/exe), or empty where the system does not say.
inline std::string self_path()
{
    std::error_code error;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::string() : self.string();
}

//! A line of /proc/self/status in bytes ("VmHWM:" the peak resident set, "VmRSS:" the
//! current one), or -1 where the system does not say.
inline double status_bytes(const std::string& key)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.starts_with(key))
            return std::stod(line.substr(key.size())) * 1024; // "VmHWM:    1234 kB"
    return -1;
}

//! \brief Resets the peak resident set (VmHWM) to the current one (Linux's clear_refs "5"),
//! so that the next reading is the peak of what runs after; false where it is refused (the
//! peak is then the process's so far).
inline bool reset_peak_memory()
{
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.close();
    return static_cast<bool>(clear);
}

//! meshfair-cli beside this program (the build's app/ folder), or empty.
inline std::string default_cli()
{
    const std::filesystem::path self = self_path();
    if (self.empty())
        return {};
    const auto cli = self.parent_path() / "meshfair-cli";
    return std::filesystem::exists(cli) ? cli.string() : std::string();
}

} // namespace meshfair::bench
