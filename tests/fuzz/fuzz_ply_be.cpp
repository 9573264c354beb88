// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// PLY reader, binary big-endian bodies. Steering (steer_ply): input starting with "ply" keeps its
// header but its format line is rewritten to "format binary_big_endian 1.0", so mutations
// reach the body; any other input is a body behind a canned header whose vertex count,
// face count and property types are its first three bytes.

#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    using namespace meshfair;
    if (size > fuzz::kMaxInput)
        return 0;
    const std::string text =
        fuzz::steer_ply(fuzz::as_text(data, size), io::Encoding::BinaryBigEndian);
    io::ReadReport report;
    if (fuzz::read_or_refuse(text, io::Format::Ply, &report) &&
        report.encoding != io::Encoding::BinaryBigEndian)
        fuzz::fail("PLY read with another encoding than its format line");
    return 0;
}
