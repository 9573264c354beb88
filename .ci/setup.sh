#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# MeshFair setup on Debian 12: installs the Debian packages that are missing, builds,
# then runs the main job on the bundled bunny (`run`), every test once in the release
# build (`test`, the check before every commit), or the deep gate (`check`: sanitizers,
# fuzzing, ThreadSanitizer, clang-tidy; what .ci/run runs after `test`). Safe to run
# again: installed packages are skipped and the builds are incremental.
set -euo pipefail

mode=${1:-run}
case "$mode" in
    run | test | check) ;;
    *)
        echo "usage: $0 run|test|check" >&2
        exit 2
        ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

# libopenmesh-dev is the peer of meshfair-bench (docs/performance.md), and with
# libmeshsdfilter-dev (header-only) a reference filter of meshfair-quality, nothing else. The
# editor needs GLFW, OSMesa, GLM, Dear ImGui and stb; xvfb and xauth give it a display
# where there is none. pybind11 and NumPy build the Python module for Debian's own Python
# (/usr/bin/python3, for which python3-numpy and python3-pytest are). The builds use Ninja;
# make is for the fuzz campaigns' own build (tests/fuzz/campaign.sh). The direct method
# factors with CHOLMOD (libsuitesparse-dev), whose supernodal kernels call BLAS: with
# OpenBLAS installed Debian's alternatives choose it over the reference BLAS, several
# times slower.
packages=(cmake ninja-build make g++ pkg-config libtinyobjloader-dev nlohmann-json3-dev libcli11-dev
    doctest-dev libeigen3-dev libsuitesparse-dev libopenblas0-pthread libopenmesh-dev
    libmeshsdfilter-dev
    libglfw3-dev libosmesa6-dev libglm-dev libimgui-dev libstb-dev xvfb xauth pybind11-dev
    python3-dev python3-numpy)
# Tests also need: clang-format (style), strace (fault injection in the save tests and the
# files-opened check), xdotool, x11-apps, imagemagick and libx11-dev (the editor's
# real-window tests: synthetic keys, a screenshot taken from outside, its pixels, a close
# request sent as a window manager sends it), python3-pytest (the module's tests), munge
# and slurm-wlm (docs/batch.md's job array on a single-node cluster the test starts).
[ "$mode" = test ] && packages+=(clang-format strace xdotool x11-apps imagemagick libx11-dev
    python3-pytest munge slurm-wlm)
# The gate needs clang with its sanitizer runtimes and OpenMP library (ASan, UBSan,
# libFuzzer, TSan with Archer) and clang-tidy.
[ "$mode" = check ] && packages+=(clang clang-tidy libclang-rt-14-dev libomp-14-dev)

missing=()
for p in "${packages[@]}"; do
    [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" = "install ok installed" ] || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "Installing missing Debian packages: ${missing[*]}"
    sudo=()
    if [ "$(id -u)" != 0 ]; then
        command -v sudo >/dev/null || {
            echo "Run as root or install sudo: apt-get install ${missing[*]}" >&2
            exit 1
        }
        sudo=(sudo)
    fi
    export DEBIAN_FRONTEND=noninteractive
    "${sudo[@]}" apt-get update -qq
    "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# shellcheck source=.ci/phases.sh
source .ci/phases.sh
# Tests run two at a time on two cores, and many of them use OpenMP: threads that spin
# while they wait for work take the core that the other test needs. Beside a busy core,
# waiting passively took a preset test from 17 to 9 s of CPU and the quality smoke test
# from 17 to 5 s (GCC's libgomp; LLVM's libomp in the gate reads the same variable).
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE}
if [ "$mode" = check ]; then
    # The deep gate. What needs a window, a killed process or a cluster ran once, in the
    # release build (`test`); here the in-process suites, the fuzz corpora and the threads.
    phase "setup"
    failed=()
    # 1. The in-process suites (core, app, render, bench) built with clang, ASan + UBSan
    # and libstdc++ assertions, in one build with the fuzz targets.
    ./.ci/sanitize.sh build || failed+=("sanitizer build")
    phase "sanitizer build (tests and fuzz targets)"
    ./.ci/sanitize.sh test || failed+=("sanitizer tests")
    phase "sanitizer tests"
    # 2. Every fuzz target: its whole corpus replayed (tests/fuzz/corpus, tests/adversarial,
    # generated seeds), then fuzzed ${MESHFAIR_FUZZ_SECONDS:-20} s; beside them, where they
    # leave a core idle (the replays, the last target alone), clang-tidy on core/ and the
    # ThreadSanitizer build.
    start_beside clang-tidy ./.ci/tidy.sh
    start_beside thread-sanitizer-build ./.ci/tsan.sh build
    MESHFAIR_FUZZ_BUILD_DIR=build-asan MESHFAIR_FUZZ_SECONDS=${MESHFAIR_FUZZ_SECONDS:-20} \
        ./.ci/fuzz.sh || failed+=("fuzzing")
    phase "fuzz replay and campaigns"
    finish_beside clang-tidy || failed+=("clang-tidy")
    finish_beside thread-sanitizer-build || failed+=("thread-sanitizer build")
    phase "clang-tidy, ThreadSanitizer build (the rest)"
    # 3. The live solver, the autosave and the recovery under ThreadSanitizer.
    ./.ci/tsan.sh test || failed+=("thread sanitizer")
    phase "thread-sanitizer tests"
    print_phases
    if [ ${#failed[@]} -gt 0 ]; then
        echo "The deep gate FAILED: ${failed[*]}." >&2
        exit 1
    fi
    echo "The deep gate passed: the in-process suites under ASan + UBSan + assertions, every" \
        "fuzz corpus and campaign, the threads under ThreadSanitizer; core/ is lint-clean."
    exit 0
fi

build=build
# Unity translation units: each header is compiled once per batch of files, not once per
# file, which takes about 30 % off a clean build.
# shellcheck source=.ci/clang_build.sh
source .ci/clang_build.sh
ninja_configure "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
    -DMESHFAIR_WERROR=ON -DPython3_EXECUTABLE=/usr/bin/python3
if [ "$mode" = run ]; then
    cmake --build "$build" -j"$(nproc)" --target meshfair-cli meshfair meshfair_python
else
    cmake --build "$build" -j"$(nproc)"
fi

if [ "$mode" = run ]; then
    # The main job: noise on the bundled bunny, the denoising preset, a before / after
    # picture; a short summary here, everything else in report.json.
    cli="$build/app/meshfair-cli"
    out="$build/demo"
    mkdir -p "$out"
    job_start=$SECONDS
    mesh=assets/bunny.obj
    recipe=assets/recipes/denoise-organic.json # the bunny is curved everywhere
    counts=$("$cli" info "$mesh" | awk '/^(vertices|faces):/ {printf "%s%s %s", sep, $2, substr($1, 1, length($1) - 1); sep = ", "}')
    "$cli" noise "$mesh" -o "$out/bunny-noisy.obj" --sigma 0.3 --seed 1 >/dev/null
    smoothed=$("$cli" smooth "$out/bunny-noisy.obj" -o "$out/bunny-smoothed.obj" \
        --recipe "$recipe" --report "$out/report.json")
    "$build/app/meshfair" "$out/bunny-noisy.obj" --offscreen --size 640x480 \
        --screenshot "$out/before-after.png" --beside "$out/bunny-smoothed.obj"
    echo
    echo "MeshFair's main job on the bundled Stanford bunny ($mesh: $counts)"
    echo "  noise     Gaussian, sigma = 0.3 mean edge lengths, seed 1: $out/bunny-noisy.obj"
    echo "  smoothed  with the preset $recipe (guided normal smoothing, its iterations"
    echo "            from the noise found, integrated through face-normal and face-centroid"
    echo "            constraints, volume kept):"
    echo "            $out/bunny-smoothed.obj"
    echo "$smoothed" | sed -n 's/^smoothed [^:]*: /            /p; s/^seconds: /            seconds: /p'
    echo "  picture   $out/before-after.png (left: noisy, right: smoothed; one camera, offscreen)"
    echo "  report    $out/report.json (every term's energy at every iteration, timings, notes)"
    echo "  time      $((SECONDS - job_start)) s for the job"
    echo
    # Then the editor on the bunny: a window where there is a display, else its offscreen
    # frame (it says so).
    "$build/app/meshfair" "$mesh" --screenshot "$out/bunny.png"
    [ -f "$out/bunny.png" ] && echo "screenshot: $out/bunny.png"
    exit 0
fi

phase "setup and release build"
# Every test once, in the release build: unit, CLI, adversarial, saving with its killed
# processes, golden images, the real-window tests, the Python module, the Slurm job array.
# The longest start first (their COST), so that the run does not end on one of them alone.
ctest_log="$build/Testing/test-command.log"
mkdir -p "$(dirname "$ctest_log")"
status=0
(cd "$build" && ctest --output-on-failure -j"$(nproc)") 2>&1 | tee "$ctest_log" || status=$?
phase "tests (ctest, $(nproc) at a time)"
echo "Checking formatting (clang-format $(clang-format --version | grep -o '[0-9][0-9.]*' | awk 'NR == 1'))"
find app core tests -name '*.cpp' -o -name '*.h' | sort | xargs clang-format --dry-run -Werror ||
    status=1
phase "formatting"
echo "The ten slowest tests:"
# ctest's lines: "  3/415 Test  #12: NAME .......   Passed   35.21 sec"
awk '{
    if (!match($0, /Test +#[0-9]+: /)) next
    rest = substr($0, RSTART + RLENGTH)
    n = split(rest, field, " ")
    if (field[n] != "sec") next
    name = rest
    sub(/ \.+ .*$/, "", name)
    printf "%s\t%s\n", field[n - 1], name
}' "$ctest_log" | sort -t$'\t' -k1,1 -g -r | awk 'NR <= 10' |
    awk -F'\t' '{ printf "  %7.1f s  %s\n", $1, $2 }'
print_phases
if [ "$status" != 0 ]; then
    echo "The test command FAILED (see above)." >&2
    exit "$status"
fi
echo "All tests passed in the release build and every source file is formatted." \
    "The deep gate (sanitizers, fuzzing, ThreadSanitizer, clang-tidy): ./.ci/setup.sh check"
