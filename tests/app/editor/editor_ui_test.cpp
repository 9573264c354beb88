// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "app/editor/editor_ui.h"
#include "app/editor/user_files.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "app/editor/document.h"
#include "app/editor/file_browser.h"
#include "app/editor/key_map.h"
#include "core/io/io.h"
#include "tests/helpers.h"

using namespace meshfair;
using namespace meshfair::app;
namespace fs = std::filesystem;

TEST_SUITE("EditorUi")
{
    TEST_CASE("docs/editor.md lists every binding of the help overlay")
    {
        const std::string doc =
            io::read_file((test::assets_dir() / ".." / "docs" / "editor.md").string());
        REQUIRE(key_bindings().size() > 15);
        for (const KeyBinding& b : key_bindings())
            CHECK_MESSAGE(doc.find("| " + std::string(b.input) + " | " + b.action + " |") !=
                              std::string::npos,
                          b.input);
    }

    TEST_CASE("recent files: newest first, once each, ten at most, kept between runs")
    {
        const fs::path dir = test::temp_dir();
        std::vector<std::string> recent;
        for (int k = 0; k < 12; ++k)
            remember_recent(recent, (dir / ("m" + std::to_string(k) + ".obj")).string());
        remember_recent(recent, (dir / "m5.obj").string());
        REQUIRE(recent.size() == 10);
        CHECK(recent[0] == (dir / "m5.obj").string());
        CHECK(recent[1] == (dir / "m11.obj").string());
        CHECK(std::count(recent.begin(), recent.end(), (dir / "m5.obj").string()) == 1);
        remember_recent(recent, "relative.obj"); // stored absolute
        CHECK(fs::path(recent[0]).is_absolute());

        const std::string file = (dir / "config" / "meshfair" / "recent.txt").string();
        REQUIRE(save_recent(file, recent));
        CHECK(load_recent(file) == recent);
        CHECK(load_recent((dir / "none.txt").string()).empty());
        CHECK_FALSE(save_recent("", recent));
        CHECK_FALSE(save_recent("/proc/no/such/recent.txt", recent));
    }

    TEST_CASE("the selection's box: selected vertices and the vertices of selected faces")
    {
        Document d = make_document(test::open_grid(4, 4), "grid.obj");
        CHECK(glm::length(selection_box(d).hi - d.box.hi) == 0); // nothing selected: all
        d.selected_vertices[0] = 1;                              // (0, 0)
        d.selected_faces[5] = 1;                                 // the quad (1, 1) - (2, 2)
        const Box3 b = selection_box(d);
        CHECK(glm::length(b.lo - glm::dvec3(0, 0, 0)) == 0);
        CHECK(glm::length(b.hi - glm::dvec3(2, 2, 0)) == 0);
    }

    TEST_CASE("the file browser lists folders first, then mesh files, by name")
    {
        const fs::path dir = test::temp_dir();
        fs::create_directories(dir / "scans");
        fs::create_directories(dir / ".hidden");
        for (const char* name : {"b.ply", "a.OBJ", "notes.txt", "c.stl", "d.off"})
            test::write_bytes(dir / name, "x");
        std::vector<std::string> names;
        for (const fs::directory_entry& e : FileBrowser::listing(dir))
            names.push_back(e.path().filename().string());
        CHECK(names == std::vector<std::string>{"scans", "a.OBJ", "b.ply", "c.stl", "d.off"});
        CHECK(FileBrowser::listing(dir / "missing").empty());
    }
}

TEST_SUITE("EditorUi")
{
    TEST_CASE("each mesh's up axis is remembered beside the recent files")
    {
        const fs::path dir = test::temp_dir();
        const std::string file = (dir / "config" / "meshfair" / "up-axes.txt").string();
        const std::string a = (dir / "scan.ply").string(), b = (dir / "cad.stl").string();
        CHECK_FALSE(load_up_axis(file, a).has_value());
        REQUIRE(save_up_axis(file, a, UpAxis::Z));
        REQUIRE(save_up_axis(file, b, UpAxis::Y));
        CHECK(load_up_axis(file, a) == UpAxis::Z);
        CHECK(load_up_axis(file, b) == UpAxis::Y);
        REQUIRE(save_up_axis(file, a, UpAxis::Y)); // replaced, not added
        CHECK(load_up_axis(file, a) == UpAxis::Y);
        CHECK(io::read_file(file).find(a) == io::read_file(file).rfind(a));
        CHECK_FALSE(save_up_axis("", a, UpAxis::Z));
    }
}
