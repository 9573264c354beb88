// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// The layout of fuzz_recovery's input, shared with the seed generator: state.json's text,
// a NUL byte, then the binary files back to back at the sizes a mesh of `vertices`
// gives them: positions.bin and base.bin 24 bytes a vertex, then selection.bin,
// the rest (a byte an element when whole). A short input leaves the last files short.

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

#include "app/editor/recovery.h"

namespace meshfair::fuzz {

inline app::RecoveryFiles recovery_files(std::string_view data, size_t vertices)
{
    app::RecoveryFiles files;
    files.dir = "/fuzz/recovery";
    const size_t nul = data.find('\0');
    files.state = std::string(data.substr(0, nul));
    std::string_view rest = nul == std::string_view::npos ? "" : data.substr(nul + 1);
    const auto take = [&](size_t n) {
        const std::string_view part = rest.substr(0, std::min(n, rest.size()));
        rest.remove_prefix(part.size());
        return std::string(part);
    };
    files.positions = take(24 * vertices);
    files.base = take(24 * vertices);
    files.selection = std::string(rest);
    return files;
}

inline std::string recovery_input(const app::RecoveryFiles& files)
{
    return files.state + '\0' + files.positions + files.base + files.selection;
}

} // namespace meshfair::fuzz
