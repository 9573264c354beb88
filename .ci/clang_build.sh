# shellcheck shell=bash
# SPDX-License-Identifier: MIT
# Shared by .ci/sanitize.sh and .ci/tsan.sh (source it from the project's root): the step
# their argument names, and the clang build both make in unity translation units.

# The step: "build", "test" or, without an argument, "all"; anything else is refused.
clang_build_step() {
    step=${1:-all}
    case "$step" in
        build | test | all) ;;
        *)
            echo "usage: $0 [build|test]" >&2
            exit 2
            ;;
    esac
}

# clang_build DIR [CMAKE_OPTION...] [-- TARGET...]: configures DIR with clang (Release,
# unity, warnings as errors, no editor bench, no Python module) and builds the targets
# (all when none is named).
clang_build() {
    local dir=$1 options=() targets=()
    shift
    while [ $# -gt 0 ] && [ "$1" != -- ]; do
        options+=("$1")
        shift
    done
    [ $# -gt 0 ] && shift
    targets=("$@")
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
        -DCMAKE_UNITY_BUILD=ON -DMESHFAIR_WERROR=ON -DMESHFAIR_EDITOR_BENCH=OFF \
        -DMESHFAIR_BUILD_PYTHON=OFF "${options[@]}" >/dev/null
    if [ ${#targets[@]} -gt 0 ]; then
        cmake --build "$dir" -j"$(nproc)" --target "${targets[@]}"
    else
        cmake --build "$dir" -j"$(nproc)"
    fi
}
