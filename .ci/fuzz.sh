#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fuzzing CI job: builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan) in
# build-fuzz/ (incremental; MESHFAIR_FUZZ_BUILD_DIR names another, such as the gate's
# build-asan, configured by .ci/sanitize.sh), then for every target replays its whole seed corpus (the
# committed tests/fuzz/corpus/<target>/, tests/adversarial/ and library-generated seeds)
# and fuzzes it for MESHFAIR_FUZZ_SECONDS (default 30) seconds into the scratch corpus
# build-fuzz/corpus/<target>/ (seeds that crashed in the replay are left out). Fails on any
# crash, leak, timeout or out-of-memory, in the replay or while fuzzing, and prints the
# reproducer. The targets run as many at a time as there are cores. Usage: .ci/fuzz.sh
# [TARGET...]   (default: all targets), or .ci/fuzz.sh --build (the build and the
# generated seeds only).
set -euo pipefail

# shellcheck source-path=SCRIPTDIR/.. source=tests/fuzz/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../tests/fuzz/common.sh"
cd "$fuzz_root"

seconds=${MESHFAIR_FUZZ_SECONDS:-30}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${FUZZ_TARGETS[@]}")

echo "== building the fuzz targets in $fuzz_build"
fuzz_build_libfuzzer
fuzz_generate
if [ "${targets[0]}" = --build ]; then
    exit 0
fi

logs="$fuzz_build/logs"
mkdir -p "$logs"
summaries=()
reproducers=()
status=0

# One target: its seeds replayed, then fuzzed; its summary line and reproducers go to
# $logs/<target>.summary and .reproducers, its output to $logs/<target>.out.
fuzz_one() {
    local t=$1 failed=0 bin seeds corpus artifacts files replay crashed log result artifact cov line
    rm -f "$logs/$t.summary" "$logs/$t.reproducers"
    bin=$(fuzz_binary "$fuzz_build" "$t")
    [ -x "$bin" ] || {
        echo "fuzz: unknown target $t (known: ${FUZZ_TARGETS[*]})" >&2
        return 2
    }
    seeds="$fuzz_build/seeds/$t"
    corpus="$fuzz_build/corpus/$t"
    artifacts="$fuzz_build/artifacts/$t"
    mkdir -p "$corpus" "$artifacts"
    fuzz_seeds "$t" "$seeds"
    mapfile -t files < <(find "$seeds" -type f | sort)

    echo "== $t: replaying ${#files[@]} seeds"
    replay="ok"
    if ! crashed=$(fuzz_replay "$bin" "$logs/$t.replay.log" "${files[@]}"); then
        failed=1
        fuzz_crash_summary "$logs/$t.replay.log"
        while IFS= read -r f; do
            echo "REPRODUCER ($t replay): $f"
            echo "$t: $f" >>"$logs/$t.reproducers"
            # Fuzz on without it, so one known bug does not hide the others.
            rm -f "$f"
        done <<<"$crashed"
        replay="$(echo "$crashed" | wc -l) CRASHED"
    fi

    echo "== $t: fuzzing for ${seconds}s"
    log="$logs/$t.fuzz.log"
    result=ok
    timeout -k 10 $((seconds + 120)) "$bin" "${FUZZ_OPTIONS[@]}" -max_total_time="$seconds" \
        -dict="$(fuzz_dict "$t")" -print_final_stats=1 -artifact_prefix="$artifacts/" \
        "$corpus" "$seeds" >"$log" 2>&1 || result=failed
    artifact=$(fuzz_artifact "$log")
    if [ "$result" != ok ]; then
        failed=1
        case $(basename "${artifact:-none}") in
            crash-*) result=crash ;;
            leak-*) result=leak ;;
            timeout-*) result=timeout ;;
            oom-*) result=oom ;;
        esac
        fuzz_crash_summary "$log"
        echo "REPRODUCER ($t): ${artifact:-none written, see $log}"
        echo "$t: ${artifact:-see $log}" >>"$logs/$t.reproducers"
    fi
    cov=$(grep -a -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2 || true)
    line=$(printf '%-16s replay %4d seeds: %s | fuzz %ss: %10s execs %7s exec/s %5s new units cov %5s: %s' \
        "$t" "${#files[@]}" "$replay" "$seconds" "$(fuzz_stat "$log" number_of_executed_units)" \
        "$(fuzz_stat "$log" average_exec_per_sec)" "$(fuzz_stat "$log" new_units_added)" \
        "${cov:-?}" "$result")
    echo "$line" >"$logs/$t.summary"
    echo "$line"
    return "$failed"
}

# The targets two at a time on two cores (each libFuzzer process is one thread): the
# campaigns are as long as before, the job takes half the time. Outputs in target order.
jobs=$(nproc)
for t in "${targets[@]}"; do
    rm -f "$logs/$t.status"
    (
        fuzz_one "$t" && rc=0 || rc=$?
        echo "$rc" >"$logs/$t.status"
    ) >"$logs/$t.out" 2>&1 &
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do
        wait -n || true
    done
done
wait
for t in "${targets[@]}"; do
    rc=$(cat "$logs/$t.status" 2>/dev/null || echo 1)
    if [ "$rc" = 2 ]; then
        cat "$logs/$t.out" >&2
        exit 2
    fi
    [ "$rc" = 0 ] || status=1
    cat "$logs/$t.out"
    [ -f "$logs/$t.summary" ] && summaries+=("$(cat "$logs/$t.summary")")
    if [ -f "$logs/$t.reproducers" ]; then
        mapfile -t found <"$logs/$t.reproducers"
        reproducers+=("${found[@]}")
    fi
done

echo
echo "== fuzzing summary (logs in $logs)"
printf '%s\n' "${summaries[@]}"
if [ "$status" -ne 0 ]; then
    echo
    echo "FAILED; reproducers (run: $(fuzz_binary "$fuzz_build" TARGET) FILE):"
    printf '  %s\n' "${reproducers[@]}"
fi
exit "$status"
