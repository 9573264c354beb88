#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# MeshFair setup on Debian 12: installs the Debian packages that are missing, builds,
# then either runs the main job on the bundled bunny (`run`) or every test (`test`).
# Safe to run again: installed packages are skipped and the build is incremental.
set -euo pipefail

mode=${1:-run}
case "$mode" in
    run | test) ;;
    *)
        echo "usage: $0 run|test" >&2
        exit 2
        ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

# libopenmesh-dev is the peer of meshfair-bench (docs/performance.md), nothing else. The
# editor needs GLFW, OSMesa, GLM, Dear ImGui and stb; xvfb and xauth give it a display
# where there is none. pybind11 and NumPy build the Python module for Debian's own Python
# (/usr/bin/python3, for which python3-numpy and python3-pytest are).
packages=(cmake g++ make pkg-config libtinyobjloader-dev nlohmann-json3-dev libcli11-dev
    doctest-dev libeigen3-dev libopenmesh-dev libglfw3-dev libosmesa6-dev libglm-dev
    libimgui-dev libstb-dev xvfb xauth pybind11-dev python3-dev python3-numpy)
# Tests also need: clang-format and clang-tidy (style and lint), clang with its runtime
# and OpenMP library (the sanitizer build and libFuzzer), strace (fault injection in the
# save tests and the files-opened check), xdotool, x11-apps, imagemagick and libx11-dev (the
# editor's real-window test: synthetic keys, a screenshot taken from outside, its pixels,
# a close request sent as a window manager sends it), python3-pytest (the module's tests),
# munge and slurm-wlm (docs/batch.md's job array on a single-node cluster the test starts).
[ "$mode" = test ] && packages+=(clang-format clang-tidy clang libclang-rt-14-dev libomp-14-dev
    strace xdotool x11-apps imagemagick libx11-dev python3-pytest munge slurm-wlm)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
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

build=build
# Unity translation units: each header is compiled once per batch of files, not once per
# file, which takes about 30 % off a clean build.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
    -DMESHFAIR_WERROR=ON -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
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
    recipe=assets/recipes/denoise.json
    counts=$("$cli" info "$mesh" | awk '/^(vertices|faces):/ {printf "%s%s %s", sep, $2, substr($1, 1, length($1) - 1); sep = ", "}')
    "$cli" noise "$mesh" -o "$out/bunny-noisy.obj" --sigma 0.3 --seed 1 >/dev/null
    smoothed=$("$cli" smooth "$out/bunny-noisy.obj" -o "$out/bunny-smoothed.obj" \
        --recipe "$recipe" --report "$out/report.json")
    "$build/app/meshfair" "$out/bunny-noisy.obj" --offscreen --size 640x480 \
        --screenshot "$out/before-after.png" --beside "$out/bunny-smoothed.obj"
    echo
    echo "MeshFair's main job on the bundled Stanford bunny ($mesh: $counts)"
    echo "  noise     Gaussian, sigma = 0.3 mean edge lengths, seed 1: $out/bunny-noisy.obj"
    echo "  smoothed  with the preset $recipe (bilateral normal smoothing integrated"
    echo "            through face-normal and face-centroid constraints, volume kept):"
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

# Where the test command's time goes, phase by phase (printed at the end; the first phase
# from the script's start).
times=()
phase_start=0
phase() {
    times+=("$(printf '%-28s %5d s' "$1" $((SECONDS - phase_start)))")
    phase_start=$SECONDS
}
phase "setup and release build"
# Each build after the first starts beside the tests before it, at the lowest priority:
# those tests wait for windows, for the processes they kill and for each other, and leave
# idle a quarter of both cores (release) or a tenth (sanitizers), which the build takes
# without taking a core a test wants;
# clang-tidy takes the core the last round of fuzzing leaves idle. Each runs in a process
# group of its own (stopped if the script stops) with its output in a log, printed when it
# ends (and when it fails).
logs="$build/ci-logs"
mkdir -p "$logs"
declare -A beside=()
start_beside() { # start_beside NAME COMMAND...
    local name=$1
    shift
    # A session of its own is also a scheduling group of its own where the kernel groups
    # sessions (autogroup), which would share the cores equally with the tests whatever
    # its nice value: the group is niced too, from inside the session.
    # shellcheck disable=SC2016 # expanded by the inner shell
    setsid bash -c 'echo 19 2>/dev/null >/proc/self/autogroup || true; exec nice -n 19 "$@"' \
        "$name" "$@" >"$logs/$name.log" 2>&1 &
    beside[$name]=$!
}
finish_beside() { # finish_beside NAME: waits for it, prints its log, fails with it
    local name=$1 status=0
    wait "${beside[$name]}" || status=$?
    unset "beside[$name]"
    cat "$logs/$name.log"
    if [ "$status" != 0 ]; then
        echo "$name failed (exit $status)" >&2
        exit "$status"
    fi
}
stop_beside() {
    local pid
    for pid in "${beside[@]}"; do
        kill -- "-$pid" 2>/dev/null || true
    done
}
trap stop_beside EXIT
# 1. Unit, adversarial and save tests in the release build (the sanitizer build beside).
start_beside sanitizer-build ./.ci/sanitize.sh build
(cd "$build" && ctest --output-on-failure -j"$(nproc)")
phase "release tests"
echo "Checking formatting (clang-format $(clang-format --version | grep -o '[0-9][0-9.]*' | head -1))"
find app core tests -name '*.cpp' -o -name '*.h' | sort | xargs clang-format --dry-run -Werror
phase "formatting"
# 2. The same tests built with clang, ASan + UBSan and libstdc++ assertions (the fuzz
# targets' build beside them).
finish_beside sanitizer-build
phase "sanitizer build (the rest)"
start_beside fuzz-build ./.ci/fuzz.sh --build
./.ci/sanitize.sh test
phase "sanitizer tests"
finish_beside fuzz-build
phase "fuzz build (the rest)"
# 3. Every fuzz target: replay the whole corpus, then fuzz ${MESHFAIR_FUZZ_SECONDS:-30} s each
# (as many targets at a time as there are cores); 4. clang-tidy (bugprone-*) on core/, with
# clang's compile commands, beside them.
start_beside clang-tidy ./.ci/tidy.sh
./.ci/fuzz.sh
phase "fuzz campaigns"
finish_beside clang-tidy
phase "clang-tidy (the rest)"
# 5. The editor's threads under ThreadSanitizer, after the fuzzing: its build beside the
# fuzz targets would take time from their 2 s timeouts.
./.ci/tsan.sh
phase "thread-sanitizer build, tests"
echo "Time by phase:"
printf '  %s\n' "${times[@]}"
echo "All tests passed (release, address and thread sanitizers, fuzzing), core/ is lint-clean and every source file is formatted."
