#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The editor's threads under ThreadSanitizer: a clang build with -fsanitize=thread of the
# app tests and the CLI (build-tsan), then the app tests, among them those that run the
# live solver's worker thread (the "Live solving" and "Smoothing brush" suites: a solver
# playing while the frame takes positions, restarts, pin drags, undo) and the autosave and
# recovery files ("Recovery"). (A session killed mid-run and recovered, which needs a
# killed process, runs in the release build of the test command.) Any report fails the
# run; nothing is suppressed. The solver's OpenMP loops run under LLVM's OpenMP runtime with its
# ThreadSanitizer tool (Archer, libomp-14-dev), so TSan sees OpenMP's synchronization
# instead of reporting it. Usage: .ci/tsan.sh [build|test]: builds, runs the tests, or
# (without an argument) both.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# shellcheck source=.ci/clang_build.sh
source .ci/clang_build.sh
clang_build_step "$@"
build=build-tsan
if [ "$step" != test ]; then
    clang_build "$build" -DMESHFAIR_TSAN=ON -- meshfair_app_tests
fi
[ "$step" != build ] || exit 0
archer=$(ls /usr/lib/llvm-14/lib/libarcher.so 2>/dev/null || true)
[ -n "$archer" ] || {
    echo "tsan: libarcher.so not found (apt-get install libomp-14-dev)" >&2
    exit 1
}
# ignore_noninstrumented_modules: what Archer requires (it says so when it is missing):
# the OpenMP runtime's own, uninstrumented spin-waits order its internal mutexes, which
# TSan cannot see; every access of MeshFair's instrumented code is still checked.
export TSAN_OPTIONS="halt_on_error=1 abort_on_error=1 second_deadlock_stack=1 history_size=4 ignore_noninstrumented_modules=1"
export OMP_TOOL_LIBRARIES=$archer
export XDG_STATE_HOME=$PWD/$build/state
(cd "$build/tests" && ./meshfair_app_tests)
echo "ThreadSanitizer: the live solver, the autosave and the app tests ran without a report."
