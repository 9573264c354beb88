// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// Binary STL reader. Steering: the input is padded with NUL bytes to the 84-byte header,
// cut to a whole number n of 50-byte triangles and its count field (bytes 80-83) set to
// n, so 84 + 50 n == size and the reader takes the binary path. Input whose first byte
// is '!' is passed unchanged, so the size-mismatch and text-fallback paths stay reachable.

#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    using namespace meshfair;
    if (size > fuzz::kMaxInput)
        return 0;
    std::string bytes(fuzz::as_text(data, size));
    const bool steer = bytes.empty() || bytes[0] != '!';
    if (steer)
    {
        if (bytes.size() < 84)
            bytes.resize(84, '\0');
        const size_t triangles = (bytes.size() - 84) / 50;
        bytes.resize(84 + 50 * triangles);
        for (size_t k = 0; k < 4; ++k)
            bytes[80 + k] = static_cast<char>((triangles >> (8 * k)) & 0xFF);
    }
    io::ReadReport report;
    const auto mesh = fuzz::read_or_refuse(bytes, io::Format::Stl, &report);
    if (mesh && steer && report.encoding != io::Encoding::BinaryLittleEndian)
        fuzz::fail("binary STL of a matching size read as text");
    if (mesh && steer && mesh->face_count() != static_cast<Index>((bytes.size() - 84) / 50))
        fuzz::fail("binary STL read with another triangle count");
    return 0;
}
