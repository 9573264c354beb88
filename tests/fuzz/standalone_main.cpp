// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
// A plain driver for the coverage build (MESHFAIR_FUZZ_ENGINE=coverage): runs the
// target's LLVMFuzzerTestOneInput once on each file named on the command line, in order
// (arguments starting with '-', libFuzzer's options, are ignored).
// A crash (trap, abort, segfault) still writes the coverage profile, prints
// "standalone: crashed on FILE" and exits with 1; campaign.sh resumes after that file.

#include <unistd.h>
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size);
// Provided by the profile runtime with -fprofile-instr-generate; null otherwise.
extern "C" int __llvm_profile_write_file(void) __attribute__((weak));

namespace {

const char* current = "";

void on_crash(int signal)
{
    if (__llvm_profile_write_file)
        __llvm_profile_write_file();
    std::fprintf(stderr, "standalone: crashed on %s (signal %d)\n", current, signal);
    _exit(1);
}

} // namespace

int main(int argc, char** argv)
{
    for (const int s : {SIGABRT, SIGILL, SIGSEGV, SIGBUS, SIGFPE, SIGTRAP})
        std::signal(s, on_crash);
    int ran = 0;
    for (int k = 1; k < argc; ++k)
    {
        if (argv[k][0] == '-')
            continue;
        current = argv[k];
        std::ifstream in(argv[k], std::ios::binary);
        if (!in)
        {
            std::fprintf(stderr, "standalone: cannot open %s\n", argv[k]);
            continue;
        }
        const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                      std::istreambuf_iterator<char>()};
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        ++ran;
    }
    std::fprintf(stderr, "standalone: ran %d inputs\n", ran);
    return 0;
}
