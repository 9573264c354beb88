# shellcheck shell=bash
# SPDX-License-Identifier: MIT
# Shared by .ci/setup.sh, .ci/sanitize.sh and .ci/tsan.sh (source it from the project's
# root): the step their argument names, Ninja configurations, and the clang build of the
# sanitizers in unity translation units.

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

# ninja_configure DIR CMAKE_ARGUMENT...: configures DIR with Ninja, which compiles the
# objects of every target at once where Make waits for each target's dependencies to be
# linked first (a sixth off a clean build on two cores). A directory configured with
# another generator before loses its cache (cmake refuses to switch), not its outputs.
ninja_configure() {
    local dir=$1
    shift
    if [ -f "$dir/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$dir/CMakeCache.txt"; then
        rm -rf "$dir/CMakeCache.txt" "$dir/CMakeFiles"
    fi
    cmake -G Ninja -S . -B "$dir" "$@" >/dev/null
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
    ninja_configure "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
        -DCMAKE_UNITY_BUILD=ON -DMESHFAIR_WERROR=ON -DMESHFAIR_EDITOR_BENCH=OFF \
        -DMESHFAIR_BUILD_PYTHON=OFF "${options[@]}"
    if [ ${#targets[@]} -gt 0 ]; then
        cmake --build "$dir" -j"$(nproc)" --target "${targets[@]}"
    else
        cmake --build "$dir" -j"$(nproc)"
    fi
}
