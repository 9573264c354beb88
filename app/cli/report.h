// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "core/io/io.h"
#include "core/recipe/session.h"
#include "core/topology/topology.h"

namespace meshfair::cli {

//! `info`: counts, edge classes, face-size histogram, components, isolated vertices,
//! bounding box, the attributes the file holds, and what the reader normalized.
nlohmann::json info_json(const Mesh& mesh, const Topology& topology,
                         const io::ReadReport& read_report, const io::MeshAttributes& attributes);
//! The same as aligned text lines.
std::string info_text(const nlohmann::json& info);

//! `smooth --report`: the mesh counts, iterations, the energy trace (total, then per active
//! term), the step lengths and the normal-smoothing trace. Timings are added by the caller.
nlohmann::json smooth_report(const Mesh& mesh, const Topology& topology, const Session& session,
                             const SmoothResult& result, const io::ReadReport& read_report);
//! The process's peak resident set in bytes (VmHWM of /proc/self/status), or -1 where the
//! system does not say. Unlike getrusage's ru_maxrss it is the high-water mark of this
//! program's own memory only, not of the parent it was forked from.
long long peak_resident_bytes();
//! A few human-readable lines from a report.
std::string smooth_summary(const nlohmann::json& report, const std::string& output);

} // namespace meshfair::cli
