// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Small hostile files are dealt with at once: every file of tests/adversarial/ of at
// most 4 KiB is accepted or refused in-process within 50 ms (the median of three reads;
// in practice microseconds, so the bound holds on a loaded machine and under sanitizers).
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"
#include "tests/helpers.h"

namespace fs = std::filesystem;

namespace meshfair {

TEST_SUITE("adversarial")
{
    TEST_CASE("every adversarial file of at most 4 KiB is dealt with within 50 ms")
    {
        int files = 0;
        double slowest = 0;
        std::string slowest_file;
        for (const auto& entry : fs::recursive_directory_iterator(test::adversarial_dir()))
        {
            const fs::path& path = entry.path();
            const std::string ext = path.extension().string();
            if (!entry.is_regular_file() || fs::file_size(path) > 4096 ||
                (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl" &&
                 ext != ".json"))
                continue;
            std::vector<double> seconds;
            for (int k = 0; k < 3; ++k)
            {
                const auto start = std::chrono::steady_clock::now();
                try
                {
                    if (ext == ".json")
                        (void)read_recipe(path.string());
                    else
                        (void)io::read_mesh(path.string());
                }
                catch (const InvalidInputError&)
                {
                    // refused: the time is what matters here
                }
                seconds.push_back(
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                        .count());
            }
            std::sort(seconds.begin(), seconds.end());
            ++files;
            if (seconds[1] > slowest)
            {
                slowest = seconds[1];
                slowest_file = path.filename().string();
            }
            CHECK_MESSAGE(seconds[1] <= 0.050, path.string() << ": " << seconds[1] << " s");
        }
        MESSAGE(files << " files; slowest " << slowest_file << " in " << slowest * 1e3 << " ms");
        CHECK(files >= 60);
    }
}

} // namespace meshfair
