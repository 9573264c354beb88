#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The real-window tests under load, to find their flakes before a busy CI machine does.
#
#   stress.sh BUILD_DIR [RUNS=20] [TESTS...]
#
# Starts two CPU-bound busy loops (killed when it ends or is interrupted), then runs each test
# RUNS times, one run after another, through `ctest --test-dir BUILD_DIR -R '^NAME$'` (so
# that its arguments are CMake's, as in the test command). TESTS are ctest names; by
# default the five window tests: editor_window_smoke, editor_window_tools,
# editor_window_session, editor_window_paint, editor_window_open_scan. BUILD_DIR must hold
# a built meshfair, meshfair-cli and send_close.
#
# Each failed run's ctest output goes to BUILD_DIR/window-stress/NAME-RUN.log, and the
# test's work folder (the editor's log with its trace, the widget map, the screenshots) is
# copied to BUILD_DIR/window-stress/NAME-RUN/ before the next run empties it. At the end a
# table: each test, its passes of its runs, the median and the longest run in seconds. The
# exit status is 1 if any run failed (or matched no test), 0 otherwise.
set -euo pipefail
if [ $# -lt 1 ] || [ ! -d "$1" ]; then
    sed -n '3,18p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
build=$(cd "$1" && pwd)
runs=${2:-20}
shift $(($# >= 2 ? 2 : 1))
tests=("$@")
[ ${#tests[@]} -gt 0 ] || tests=(editor_window_smoke editor_window_tools editor_window_session
    editor_window_paint editor_window_open_scan)
out=$build/window-stress
mkdir -p "$out"

burners=()
# shellcheck disable=SC2317 # called by the trap
stop_burners() {
    [ ${#burners[@]} -eq 0 ] || kill "${burners[@]}" 2>/dev/null || true
}
trap stop_burners EXIT
trap 'exit 130' INT TERM
for _ in 1 2; do
    sh -c 'while :; do :; done' &
    burners+=($!)
done
echo "stress: ${tests[*]}, $runs runs each, beside two busy loops (pids ${burners[*]}); failures in $out"

# The work folder a test's add_test gives it: editor_window_open_scan -> tests/window-open-scan.
work_of() {
    local short=${1#editor_}
    echo "$build/tests/${short//_/-}"
}

failed=0
table=()
for t in "${tests[@]}"; do
    times=() passes=0
    for r in $(seq 1 "$runs"); do
        log=$out/$t-$r.log
        start=$EPOCHREALTIME
        rc=0
        ctest --test-dir "$build" -R "^$t\$" --output-on-failure >"$log" 2>&1 || rc=$?
        end=$EPOCHREALTIME
        seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')
        times+=("$seconds")
        # Passed: ctest's exit status 0 and one test run (a name that matches none is no pass).
        if [ "$rc" = 0 ] && grep -q "tests passed, 0 tests failed out of 1$" "$log"; then
            passes=$((passes + 1))
            rm -f "$log"
            echo "  $t run $r/$runs: ok, $seconds s"
        else
            failed=1
            work=$(work_of "$t")
            [ -d "$work" ] && cp -r "$work" "$out/$t-$r"
            echo "  $t run $r/$runs: FAILED after $seconds s (exit $rc): $log"
            grep -m 3 "FAIL" "$log" | sed 's/^/    /' || true
        fi
    done
    stats=$(printf '%s\n' "${times[@]}" | sort -g | awk '{ v[NR] = $1 }
        END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
              printf "%.1f %.1f", m, v[NR] }')
    table+=("$t $passes/$runs ${stats% *} ${stats#* }")
done

echo
printf '%-26s %8s %9s %8s\n' test passes median_s max_s
for row in "${table[@]}"; do
    # shellcheck disable=SC2086
    printf '%-26s %8s %9s %8s\n' $row
done
exit "$failed"
