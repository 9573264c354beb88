// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
//
// Small hostile files cost little: every file of tests/adversarial/ of at most 4 KiB is
// accepted or refused in-process with allocations in proportion to its size, whatever
// its header promises. Counted (tests/allocation_counter.h), not timed: a reader that
// trusts a count reserves for it, which shows here on any machine; a reader that loops
// is stopped by the adversarial suite's CPU limit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>

#include "core/errors.h"
#include "core/io/io.h"
#include "core/recipe/recipe_json.h"
#include "tests/allocation_counter.h"
#include "tests/helpers.h"

namespace fs = std::filesystem;

namespace meshfair {

TEST_SUITE("adversarial")
{
    TEST_CASE("every adversarial file of at most 4 KiB is read or refused in small allocations")
    {
        // Bounds: a request at most 64 KiB + 64 bytes per byte of the file, 1 MiB + 512
        // bytes per byte of the file in all (the largest seen: a few kilobytes). A count
        // taken on trust (1e9 vertices reserved) asks for gigabytes.
        int files = 0;
        std::size_t most = 0, largest = 0;
        std::string most_file;
        for (const auto& entry : fs::recursive_directory_iterator(test::adversarial_dir()))
        {
            const fs::path& path = entry.path();
            const std::string ext = path.extension().string();
            if (!entry.is_regular_file() || fs::file_size(path) > 4096 ||
                (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl" &&
                 ext != ".json"))
                continue;
            const std::size_t size = fs::file_size(path);
            const test::AllocationScope scope;
            try
            {
                if (ext == ".json")
                    (void)read_recipe(path.string());
                else
                    (void)io::read_mesh(path.string());
            }
            catch (const InvalidInputError&)
            {
                // refused: what it cost is what matters here
            }
            ++files;
            largest = std::max(largest, scope.largest());
            if (scope.bytes() > most)
            {
                most = scope.bytes();
                most_file = path.filename().string();
            }
            CHECK_MESSAGE(scope.largest() <= 65536 + 64 * size,
                          path.string() << ": a request of " << scope.largest() << " bytes");
            CHECK_MESSAGE(scope.bytes() <= 1048576 + 512 * size,
                          path.string() << ": " << scope.bytes() << " bytes allocated");
        }
        MESSAGE(files << " files; the most allocated: " << most_file << ", " << most
                      << " bytes; the largest request " << largest << " bytes");
        CHECK(files >= 60);
    }
}

} // namespace meshfair
