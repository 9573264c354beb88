#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Long fuzzing campaigns over the targets of tests/fuzz, and their coverage.
#
#   tests/fuzz/campaign.sh [--target T]... [--runs N | --seconds S] [--jobs J] [--max-len B] [--no-build]
#   tests/fuzz/campaign.sh --coverage [--target T]...   |   tests/fuzz/campaign.sh --summary
#
# Campaign: for each target (default: all, in turn) libFuzzer runs for N executions or S
# seconds (default 600) into the persistent corpus build-fuzz/campaign/<target>/ (seeded as
# .ci/fuzz.sh does), with inputs of at most B bytes (default 4096; CI fuzzes up to 64 KiB,
# the adversarial suite covers the large files). One job (the default) is one libFuzzer
# process, which stops at its first finding; J > 1 jobs use fork mode, which continues past
# findings (-ignore_crashes/-ignore_timeouts/-ignore_ooms) but spends about two thirds of
# its time forking and merging. Reproducers go to build-fuzz/campaign/artifacts/<target>/;
# each run appends "target<TAB>executions<TAB>seconds<TAB>findings<TAB>max_len" to
# build-fuzz/campaign/campaign.tsv. --summary prints each target's totals from it.
#
# --coverage: builds the targets with clang's source-based coverage and plain drivers in
# build-cov/, replays every corpus there is (campaign, .ci/fuzz.sh's scratch corpus,
# seeds) through them and prints line and branch coverage of core/io/ per file with
# llvm-cov report. The merged profile is build-cov/coverage.profdata.
set -euo pipefail

# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$fuzz_root"

usage() {
    sed -n '4,5s/^#   //p' "${BASH_SOURCE[0]}" >&2
    exit 2
}

targets=()
runs=""
seconds=600
jobs=1
max_len=4096
coverage=0
summary=0
build=1
while [ $# -gt 0 ]; do
    case $1 in
        --target) targets+=("${2:?}") && shift ;;
        --runs) runs=${2:?} && shift ;;
        --seconds) seconds=${2:?} && shift ;;
        --jobs) jobs=${2:?} && shift ;;
        --max-len) max_len=${2:?} && shift ;;
        --summary) summary=1 ;;
        --coverage) coverage=1 ;;
        --no-build) build=0 ;;
        -h | --help) usage ;;
        *)
            echo "campaign: unknown argument $1" >&2
            usage
            ;;
    esac
    shift
done
[ ${#targets[@]} -gt 0 ] || targets=("${FUZZ_TARGETS[@]}")
for t in "${targets[@]}"; do
    case " ${FUZZ_TARGETS[*]} " in
        *" $t "*) ;;
        *)
            echo "campaign: unknown target $t (known: ${FUZZ_TARGETS[*]})" >&2
            exit 2
            ;;
    esac
done

campaign="$fuzz_build/campaign"
tsv="$campaign/campaign.tsv"

if [ "$summary" = 1 ]; then
    [ -s "$tsv" ] || {
        echo "campaign: no campaign log $tsv yet" >&2
        exit 1
    }
    printf '%-16s %5s %14s %9s %9s\n' target runs executions hours findings
    awk -F'\t' 'NR > 1 { runs[$1]++; execs[$1] += $2; secs[$1] += $3; found[$1] += $4 }
        END { for (t in runs) printf "%-16s %5d %14d %9.2f %9d\n", t, runs[t], execs[t],
                                     secs[t] / 3600, found[t] }' "$tsv" | sort
    exit 0
fi

# The inputs of every corpus of a target, for the coverage replay.
corpus_files() {
    local d
    for d in "$campaign/$1" "$fuzz_build/corpus/$1" "$fuzz_build/seeds/$1"; do
        [ -d "$d" ] && find "$d" -type f
    done | sort
}

if [ "$coverage" = 1 ]; then
    for tool in llvm-profdata-14 llvm-cov-14; do
        command -v "$tool" >/dev/null || {
            echo "campaign: $tool not found (apt-get install llvm-14)" >&2
            exit 1
        }
    done
    if [ "$build" = 1 ]; then
        echo "== building the coverage drivers in $fuzz_cov_build"
        fuzz_build_coverage
        # Seeds need the libFuzzer build's generator; skip them if it is not built.
        if [ -x "$(fuzz_binary "$fuzz_build" fuzz_seedgen)" ]; then
            fuzz_generate
            for t in "${targets[@]}"; do fuzz_seeds "$t" "$fuzz_build/seeds/$t"; done
        fi
    fi
    profiles="$fuzz_cov_build/profiles"
    rm -rf "$profiles"
    mkdir -p "$profiles"
    objects=()
    for t in "${targets[@]}"; do
        bin=$(fuzz_binary "$fuzz_cov_build" "$t")
        mapfile -t files < <(corpus_files "$t")
        objects+=(-object "$bin")
        [ ${#files[@]} -gt 0 ] || continue
        export LLVM_PROFILE_FILE="$profiles/$t-%p.profraw"
        crashed=$(fuzz_replay "$bin" "$profiles/$t.log" "${files[@]}") ||
            echo "$t: crashing inputs (replayed around them):" "$crashed"
        echo "$t: replayed ${#files[@]} inputs"
    done
    shopt -s nullglob
    raw=("$profiles"/*.profraw)
    [ ${#raw[@]} -gt 0 ] || {
        echo "campaign: no profile written (no corpus? run a campaign or .ci/fuzz.sh first)" >&2
        exit 1
    }
    llvm-profdata-14 merge -sparse "${raw[@]}" -o "$fuzz_cov_build/coverage.profdata"
    echo
    echo "== coverage of core/io/ (lines and branches; all targets' corpora)"
    # The first -object is the main binary; report takes the others as -object too.
    llvm-cov-14 report "${objects[1]}" "${objects[@]:2}" \
        -instr-profile="$fuzz_cov_build/coverage.profdata" \
        -show-region-summary=false -show-instantiation-summary=false \
        "$fuzz_root/core/io/"
    exit 0
fi

if [ "$build" = 1 ]; then
    echo "== building the fuzz targets in $fuzz_build"
    fuzz_build_libfuzzer
fi
fuzz_generate
mkdir -p "$campaign"
[ -s "$tsv" ] || printf 'target\texecutions\tseconds\tfindings\tmax_len\n' >"$tsv"

count_findings() {
    find "$1" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' \
        -o -name 'oom-*' \) | wc -l
}

for t in "${targets[@]}"; do
    bin=$(fuzz_binary "$fuzz_build" "$t")
    seeds="$fuzz_build/seeds/$t"
    corpus="$campaign/$t"
    artifacts="$campaign/artifacts/$t"
    log="$campaign/$t.log"
    mkdir -p "$corpus" "$artifacts"
    fuzz_seeds "$t" "$seeds"
    if [ -n "$runs" ]; then limit=(-runs="$runs"); else limit=(-max_total_time="$seconds"); fi
    before=$(count_findings "$artifacts")
    start=$(date +%s)
    if [ "$jobs" -gt 1 ]; then
        mode=(-fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
    else
        mode=()
    fi
    echo "== $t: ${limit[*]#-}, inputs up to $max_len bytes, $jobs job(s), into $corpus"
    # No periodic purge of ASan's allocator: with the 32 MB quarantine the peak stays near
    # 140 MB anyway, and re-faulting the purged pages cost a quarter of the run (measured
    # with perf on fuzz_ply_ascii: 150 k executions in 28 s instead of 35-38 s).
    "$bin" "${FUZZ_REPLAY_OPTIONS[@]}" -purge_allocator_interval=-1 -max_len="$max_len" \
        "${limit[@]}" "${mode[@]}" \
        -dict="$(fuzz_dict "$t")" -artifact_prefix="$artifacts/" "$corpus" "$seeds" \
        >"$log" 2>&1 || true
    elapsed=$(($(date +%s) - start))
    # A finished run ends with "Done <executions> runs in <s> second(s)"; otherwise take
    # the last status line, "#<executions> ..." (fork mode: "#<executions>: cov: ...").
    execs=$(sed -n 's/^Done \([0-9]*\) runs in .*/\1/p' "$log" | tail -1)
    [ -n "$execs" ] || execs=$(sed -n 's/^#\([0-9]*\):\{0,1\}[[:space:]].*/\1/p' "$log" | tail -1)
    findings=$(($(count_findings "$artifacts") - before))
    printf '%s\t%s\t%s\t%s\t%s\n' "$t" "${execs:-0}" "$elapsed" "$findings" "$max_len" >>"$tsv"
    printf '%-16s %12s execs %6ss %4s findings  corpus %s files\n' "$t" "${execs:-0}" \
        "$elapsed" "$findings" "$(find "$corpus" -type f | wc -l)"
    if [ "$findings" -gt 0 ]; then
        find "$artifacts" -maxdepth 1 -type f -newermt "@$start" -printf '  reproducer: %p\n'
    fi
done
echo "campaign log: $tsv"
