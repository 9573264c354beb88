#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The in-process test suites (the ctest labels core, app, render and bench: doctest
# executables) in a release build with AddressSanitizer, UndefinedBehaviorSanitizer (any
# report is fatal) and libstdc++ assertions, built with clang in unity translation units.
# The same build links the libFuzzer targets of tests/fuzz (MESHFAIR_FUZZ_ENGINE=shared:
# libFuzzer's edge counters in every object), which .ci/fuzz.sh runs from it in the gate.
# What needs a window, a killed process or a cluster (labels window, save, cluster), the
# adversarial files (replayed by the fuzz targets instead) and the Python module run once,
# in the release build of `.ci/setup.sh test`. Usage: .ci/sanitize.sh [build|test]:
# builds, runs the tests, or (without an argument) both.
# Needs: clang, libclang-rt-14-dev, ninja-build (installed by .ci/setup.sh check).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=.ci/clang_build.sh
source .ci/clang_build.sh
clang_build_step "$@"
build=build-asan
if [ "$step" != test ]; then
    clang_build "$build" -DMESHFAIR_SANITIZE=ON -DMESHFAIR_FUZZ=ON \
        -DMESHFAIR_FUZZ_ENGINE=shared -- meshfair_core_tests meshfair_app_tests \
        meshfair_render_tests meshfair_bench_tests fuzz_all
fi
[ "$step" != build ] || exit 0
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/.ci/lsan.supp:print_suppressions=0
(cd "$build" && ctest --output-on-failure -j"$(nproc)" -L '^(core|app|render|bench)$')
echo "Sanitizer build: every in-process test passed under ASan + UBSan + _GLIBCXX_ASSERTIONS."
