#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The whole ctest suite in a release build with AddressSanitizer, UndefinedBehavior-
# Sanitizer (any report is fatal) and libstdc++ assertions, built with clang in unity
# translation units (everything the tests run; not the editor's bench, which none does). Usage: .ci/sanitize.sh [build|test]: builds, runs the tests, or
# (without an argument) both.
# Needs: clang, libclang-rt-14-dev (installed by .ci/setup.sh test).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=.ci/clang_build.sh
source .ci/clang_build.sh
clang_build_step "$@"
build=build-asan
if [ "$step" != test ]; then
    clang_build "$build" -DMESHFAIR_SANITIZE=ON
fi
[ "$step" != build ] || exit 0
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/.ci/lsan.supp:print_suppressions=0
(cd "$build" && ctest --output-on-failure -j"$(nproc)")
echo "Sanitizer build: every test passed under ASan + UBSan + _GLIBCXX_ASSERTIONS."
