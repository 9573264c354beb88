// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// OBJ reader: the input is the file, unchanged. Besides the front door's checks, the
// parse in 2 to 5 line ranges (the last byte picks how many) must give what the serial
// parse gives: the same mesh bit for bit, the same attributes (texture coordinates,
// normals, colours, groups) and notes, or the same error message.
// The ranges are parsed one after another (one thread): what is fuzzed is how the file is
// cut and the parts joined; the threads themselves are obj_ranges_test's (an OpenMP team
// per input would also cost more than the parse).

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/errors.h"
#include "core/io/read_obj.h"
#include "core/parallel/parallel.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

struct Outcome
{
    bool accepted = false;
    meshfair::Mesh mesh;
    meshfair::io::MeshAttributes attributes;
    std::vector<std::string> notes;
    std::string error;
};

Outcome parse(std::string_view data, int ranges)
{
    Outcome o;
    meshfair::io::ReadReport report;
    try
    {
        o.mesh = meshfair::io::read_obj_in_ranges(data, "fuzz.obj", report, o.attributes, ranges);
        o.accepted = true;
        o.notes = report.notes;
    }
    catch (const meshfair::FormatError& e)
    {
        o.error = e.what();
    }
    return o;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size)
{
    static const bool one_thread = (meshfair::set_thread_count(1), true);
    (void)one_thread;
    if (size > meshfair::fuzz::kMaxInput)
        return 0;
    const std::string_view text = meshfair::fuzz::as_text(data, size);
    meshfair::fuzz::read_or_refuse(text, meshfair::io::Format::Obj);
    if (size == 0)
        return 0;
    const Outcome serial = parse(text, 1);
    const Outcome ranged = parse(text, 2 + data[size - 1] % 4);
    if (serial.accepted != ranged.accepted || serial.error != ranged.error ||
        serial.notes != ranged.notes ||
        (serial.accepted && (!meshfair::fuzz::identical(serial.mesh, ranged.mesh) ||
                             serial.attributes != ranged.attributes)))
        meshfair::fuzz::fail("the parse in ranges differs from the serial parse: '" + ranged.error +
                             "' vs '" + serial.error + "'");
    return 0;
}
