#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# clang-tidy (the checks in .clang-tidy: bugprone-*, two stated exceptions) on every
# source file of core/, with the compile commands of a clang configuration of its own
# (build-tidy, configured only, never built: the builds of .ci/ compile in unity
# translation units, whose compile commands name no source file of core/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=build-tidy
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_UNITY_BUILD=OFF -DMESHFAIR_BUILD_TESTS=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    -DMESHFAIR_BUILD_PYTHON=OFF \
    >/dev/null
find core -name '*.cpp' | sort | xargs -P"$(nproc)" -n4 clang-tidy -p "$build" --quiet
echo "clang-tidy: no findings in core/."
