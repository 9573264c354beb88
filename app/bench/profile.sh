#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Where a step's time goes, counted rather than timed: instructions, simulated cache misses
# and simulated branch mispredictions per vertex of MeshFair's plain and combined steps and
# of OpenMesh's smoother, from callgrind (valgrind) running `meshfair-bench --profile`.
#
#   app/bench/profile.sh BUILD [SIZE [STEPS]]     (defaults: 1000000 vertices, 2 steps)
#
# Counts are exact for instructions; caches and branches are callgrind's models (D1 48 KiB
# 12-way, LL 32 MiB 16-way, 64-byte lines: a Zen core's L1 data cache and its L3), not
# hardware counters. One thread: the counts per vertex do not depend on the thread count.
# With the step times of meshfair-bench and its core clock they give instructions per
# cycle. About 10 minutes for 1M vertices. Needs valgrind (apt-get install valgrind).
set -euo pipefail

build=${1:?usage: app/bench/profile.sh BUILD [SIZE [STEPS]]}
size=${2:-1000000}
steps=${3:-2}
bench="$build/app/meshfair-bench"
[ -x "$bench" ] || {
    echo "profile: $bench not built" >&2
    exit 1
}
command -v valgrind >/dev/null || {
    echo "profile: valgrind not found (apt-get install valgrind)" >&2
    exit 1
}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

valgrind --tool=callgrind --callgrind-out-file="$out/callgrind.out" \
    --cache-sim=yes --branch-sim=yes \
    --D1=49152,12,64 --LL=33554432,16,64 \
    --toggle-collect='*profiled_meshfair_plain_steps*' \
    --toggle-collect='*profiled_meshfair_combined_steps*' \
    --toggle-collect='*profiled_openmesh_plain_steps*' \
    "$bench" --profile --sizes "$size" --steps "$steps" --threads 1 >"$out/bench.log" 2>"$out/valgrind.log" || {
    cat "$out/valgrind.log" >&2
    exit 1
}
vertices=$(sed -n 's/^profiled: \([0-9]*\) vertices.*/\1/p' "$out/bench.log")

# Inclusive costs of the three profiled functions, per vertex per step.
callgrind_annotate --inclusive=yes --threshold=100 "$out/callgrind.out" >"$out/annotate.txt"
events=$(sed -n 's/^Events shown: *//p' "$out/annotate.txt")
echo "$vertices vertices, $steps steps each; per vertex per step:"
awk -v events="$events" -v n="$vertices" -v steps="$steps" '
    BEGIN {
        k = split(events, name, " ")
        printf "%-18s", "per vertex"
        for (e = 1; e <= k; ++e) if (keep(name[e])) printf " %8s", name[e]
        printf "\n"
    }
    function keep(event) { return event != "I1mr" && event != "ILmr" && event != "Bi" && event != "Bim" }
    /profiled_(meshfair_plain|meshfair_combined|openmesh_plain)_steps/ {
        match($0, /profiled_[a-z_]*_steps/)
        label = substr($0, RSTART + 9, RLENGTH - 15)
        # The counts, without callgrind_annotate'"'"'s "(12.3%)" shares; "." is zero.
        e = 0
        for (f = 1; f <= NF && e < k; ++f) {
            if ($f ~ /^\(/ || $f ~ /%\)$/) continue
            v = $f
            gsub(",", "", v)
            if (v == ".") v = 0
            value[++e] = v
        }
        printf "%-18s", label
        for (e = 1; e <= k; ++e) if (keep(name[e])) printf " %8.2f", value[e] / n / steps
        printf "\n"
    }' "$out/annotate.txt"
echo "(Ir instructions, Dr/Dw data reads/writes, D1mr/D1mw and DLmr/DLmw first- and last-level"
echo " data cache misses on read/write, Bc/Bcm conditional branches and their mispredictions)"
