// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// The OBJ reader's parse in line ranges against its serial parse: on every OBJ the tests
// hold, and on files that put each case whose meaning depends on the lines before it
// (negative indices, collapsed faces, notes naming a line, errors, a byte-order mark) at
// every line, so that the cuts fall before, on and after it.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/io.h"
#include "core/io/read_obj.h"
#include "tests/helpers.h"

using namespace meshfair;

namespace {

struct Outcome
{
    bool accepted = false;
    std::uint64_t hash = 0;
    io::MeshAttributes attributes;
    std::vector<std::string> notes;
    std::string error;
    int parts = 0;
    bool operator==(const Outcome& o) const
    {
        return accepted == o.accepted && hash == o.hash && attributes == o.attributes &&
               notes == o.notes && error == o.error;
    }
};

Outcome read_in(std::string_view data, int ranges)
{
    Outcome o;
    io::ReadReport report;
    try
    {
        const Mesh m =
            io::read_obj_in_ranges(data, "t.obj", report, o.attributes, ranges, &o.parts);
        o.accepted = true;
        o.hash = content_hash(m);
        o.notes = report.notes;
    }
    catch (const FormatError& e)
    {
        o.error = e.what();
    }
    return o;
}

// Checks every range count from 2 to 7 against the serial parse; returns how many of
// them were parsed in more than one part.
int check_every_split(const std::string& data)
{
    const Outcome serial = read_in(data, 1);
    int split = 0;
    for (int ranges = 2; ranges <= 7; ++ranges)
    {
        const Outcome o = read_in(data, ranges);
        CHECK_MESSAGE(o == serial,
                      "ranges " << ranges << ": " << o.error << " vs " << serial.error);
        split += o.parts > 1;
    }
    return split;
}

// A 6 x 4 grid of quads: 35 coloured vertex lines, texture coordinates and normals, then
// 24 face lines (half with texture coordinates and normals), with group and material
// lines among them.
std::vector<std::string> grid_lines()
{
    std::vector<std::string> lines{"# grid", "mtllib grid.mtl", "o grid"};
    for (int y = 0; y <= 4; ++y)
        for (int x = 0; x <= 6; ++x)
        {
            lines.push_back("v " + std::to_string(x) + " " + std::to_string(y) + " 0.125 " +
                            std::to_string(x % 2) + " 0.5 1");
            lines.push_back("vt " + std::to_string(x) + " " + std::to_string(y));
            if (x == 0)
                lines.push_back("vn 0 0 " + std::to_string(y + 1));
        }
    lines.push_back("s 1");
    for (int y = 0; y < 4; ++y)
    {
        lines.push_back("usemtl row" + std::to_string(y));
        for (int x = 0; x < 6; ++x)
        {
            // Texture coordinates and normals on some rows' faces only.
            const int a = y * 7 + x + 1;
            std::string face = "f";
            for (const int v : {a, a + 1, a + 8, a + 7})
                face += " " + std::to_string(v) +
                        (y % 2 == 0 ? "/" + std::to_string(v) + "/" + std::to_string(y + 1)
                                    : std::string());
            lines.push_back(face);
        }
    }
    return lines;
}

std::string joined(const std::vector<std::string>& lines, const std::string& eol)
{
    std::string s;
    for (const std::string& l : lines)
        s += l + eol;
    return s;
}

} // namespace

TEST_SUITE("ReadObj in ranges")
{
    TEST_CASE("the grid is parsed in ranges, with every line ending, and gives the serial result")
    {
        const std::vector<std::string> lines = grid_lines();
        CHECK(check_every_split(joined(lines, "\n")) == 6);
        CHECK(check_every_split(joined(lines, "\r\n")) == 6);
        // CR alone: no line feed to cut at, so one part.
        CHECK(check_every_split(joined(lines, "\r")) == 0);
    }

    TEST_CASE("a line whose meaning depends on the lines before it, at every line")
    {
        const std::vector<std::string> base = grid_lines();
        const std::vector<std::string> specials{
            "f -1 -2 -3",               // counts back from the vertices so far
            "f 1 2 2 3",                // collapsed: a note naming its line
            "v 1 2 3 0.5",              // extra value: a note naming its line
            "frobnicate 1",             // unknown keyword: a note naming its line
            "f 1 2 99",                 // forward reference past the last vertex
            "f 1 2 -99",                // before the first vertex
            "v 1 2",                    // an error, with its line number
            "f 1 2",                    // an error
            "f 1 2 1 3",                // pinched: an error
            std::string("v 1 \0 2", 7), // NUL byte
            "\xEF\xBB\xBFv 0 0 0",      // a byte-order mark that is not the file's start
            "v 1e400 0 0",              // out of range
            "f 0 1 2",                  // index 0
            "f 1/-1 2/-1 3/-1",         // a texture coordinate counted back
            "f 1//99 2//1 3//1",        // a normal past the last
            "f 1/1 2 3",                // texture coordinates at some corners: a note
            "v 1 2 3",                  // a vertex without the colour the others have
            "vt 0.5",                   // a texture coordinate of one value
            "vn 0 0",                   // an error: a normal needs three values
            "g part two",               // a group between faces
        };
        for (const std::string& special : specials)
            for (size_t at = 0; at <= base.size(); ++at)
            {
                std::vector<std::string> lines = base;
                lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), special);
                CAPTURE(special);
                CAPTURE(at);
                check_every_split(joined(lines, "\n"));
            }
    }

    TEST_CASE("faces before their vertices: forward references across the ranges")
    {
        std::vector<std::string> lines = grid_lines();
        std::vector<std::string> faces(lines.end() - 24, lines.end());
        lines.erase(lines.end() - 24, lines.end());
        lines.insert(lines.begin(), faces.begin(), faces.end());
        CHECK(check_every_split(joined(lines, "\n")) == 6);
    }

    TEST_CASE("every OBJ of the tests and the assets")
    {
        int files = 0;
        for (const auto& dir :
             {test::adversarial_dir() / "obj", test::adversarial_dir() / "../fuzz/corpus/fuzz_obj",
              test::assets_dir()})
            for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
            {
                if (entry.path().extension() != ".obj")
                    continue;
                CAPTURE(entry.path().string());
                check_every_split(io::read_file(entry.path().string()));
                ++files;
            }
        CHECK(files > 30);
    }
}
