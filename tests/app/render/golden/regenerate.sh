#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Rewrites the golden images of tests/app/render/golden/ from the current renderer, on purpose:
#   tests/app/render/golden/regenerate.sh [BUILD_DIR]   (default: build)
# Look at every changed image before committing it (git diff --stat tests/app/render/golden).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../../.." && pwd)
build=${1:-build}
cmake --build "$root/$build" --target meshfair_render_tests -j"$(nproc)"
GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=2 MESHFAIR_UPDATE_GOLDEN=1 \
    "$root/$build/tests/meshfair_render_tests" -ts="Golden images"
