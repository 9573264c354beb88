// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// ASCII STL reader. Steering: input whose first word is not "solid" gets "solid fuzz\n"
// in front, so the reader does not refuse it as neither ASCII nor binary; a text whose
// size happens to match the binary layout (84 + 50 n bytes with n at byte 80) gets a
// trailing newline, so it stays on the text path.

#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    using namespace meshfair;
    if (size > fuzz::kMaxInput)
        return 0;
    std::string text(fuzz::as_text(data, size));
    if (fuzz::sniff_format(text) != io::Format::Stl)
        text.insert(0, "solid fuzz\n");
    if (text.size() >= 84 && (text.size() - 84) % 50 == 0)
        text += '\n';
    io::ReadReport report;
    if (fuzz::read_or_refuse(text, io::Format::Stl, &report) &&
        report.encoding != io::Encoding::Ascii)
        fuzz::fail("text STL read as binary");
    return 0;
}
