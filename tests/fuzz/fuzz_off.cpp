// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// OFF reader: the input is the file, unchanged.

#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    if (size > meshfair::fuzz::kMaxInput)
        return 0;
    meshfair::fuzz::read_or_refuse(meshfair::fuzz::as_text(data, size), meshfair::io::Format::Off);
    return 0;
}
