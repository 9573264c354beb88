#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# clang-tidy (the checks in .clang-tidy: bugprone-*, two stated exceptions) on every
# source file of core/, with the compile commands of the clang build (build-asan).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=build-asan
[ -f "$build/compile_commands.json" ] || {
    echo "run .ci/sanitize.sh first (it configures $build)" >&2
    exit 2
}
find core -name '*.cpp' | sort | xargs -P"$(nproc)" -n4 clang-tidy -p "$build" --quiet
echo "clang-tidy: no findings in core/."
