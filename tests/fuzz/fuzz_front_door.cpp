// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Any bytes into any reader, as the CLI does when a file's extension lies about its
// content. Steering: the first byte modulo 4 picks the reader ('0' OBJ, '1' OFF, '2' PLY,
// '3' STL, as the seeds are prefixed); the rest of the input is the file, unchanged.

#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    using namespace meshfair;
    if (size < 1 || size > fuzz::kMaxInput)
        return 0;
    static constexpr io::Format kFormats[] = {io::Format::Obj, io::Format::Off, io::Format::Ply,
                                              io::Format::Stl};
    fuzz::read_or_refuse(fuzz::as_text(data + 1, size - 1), kFormats[data[0] % 4]);
    return 0;
}
