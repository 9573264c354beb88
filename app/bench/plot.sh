#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Time per solver step against mesh size, from meshfair-bench's results (docs/performance.md).
#
#   app/bench/plot.sh RESULTS.tsv [OUT.png]
#   app/bench/plot.sh --run BUILD_DIR [OUT.png]
#
# The first form plots a TSV written by `meshfair-bench --out`. The second runs the bench
# of BUILD_DIR first, with the sizes and repetitions of docs/performance.md (this takes
# about half an hour and wants an otherwise idle machine), keeps its TSV beside OUT (same
# name, .tsv) and plots it. OUT defaults to docs/performance.png.
#
# One line per implementation and vertex order: median over the repetitions, with the
# fastest and slowest repetition as error bars; log-log axes. Needs gnuplot with the
# pngcairo terminal (Debian: apt-get install gnuplot-nox).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
usage() {
    sed -n '5,6s/^#   //p' "${BASH_SOURCE[0]}" >&2
    exit 2
}
[ $# -ge 1 ] || usage
command -v gnuplot >/dev/null || {
    echo "plot: gnuplot not found (apt-get install gnuplot-nox)" >&2
    exit 1
}

if [ "$1" = --run ]; then
    [ $# -ge 2 ] || usage
    build=$2
    out=${3:-$root/docs/performance.png}
    tsv=${out%.png}.tsv
    "$build/app/meshfair-bench" --sizes 100000 300000 1000000 4000000 --reps 5 \
        --cli "$build/app/meshfair-cli" --cache "$build/bench-meshes" --out "$tsv"
else
    tsv=$1
    out=${2:-$root/docs/performance.png}
fi
[ -s "$tsv" ] || {
    echo "plot: no results in '$tsv'" >&2
    exit 1
}

data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT

# series FIGURE IMPLEMENTATION ORDER: "vertices median min max" in milliseconds, by size.
series() {
    awk -F'\t' -v f="$1" -v i="$2" -v o="$3" \
        'NR > 1 && $1 == f && $4 == i && $3 == o { print $2, 1e3 * $6, 1e3 * $7, 1e3 * $8 }' \
        "$tsv" | sort -n
}

plots=()
add() { # FILE TITLE STYLE
    [ -s "$1" ] || return 0
    plots+=("'$1' using 1:2:3:4 with yerrorlines title '$2' $3")
}
orders=(natural bfs random)
points=(7 5 9)
for k in 0 1 2; do
    o=${orders[$k]}
    series "plain step" openmesh "$o" >"$data/openmesh-$o"
    series "combined step" meshfair "$o" >"$data/combined-$o"
    series "plain step" meshfair "$o" >"$data/plain-$o"
    add "$data/openmesh-$o" "OpenMesh smoother, plain ($o)" "lc rgb '#c0392b' pt ${points[$k]}"
    add "$data/combined-$o" "MeshFair, combined ($o)" "lc rgb '#8e44ad' pt ${points[$k]}"
    add "$data/plain-$o" "MeshFair, plain ($o)" "lc rgb '#2471a3' pt ${points[$k]}"
done
series "plain step bound" machine natural >"$data/bound"
add "$data/bound" "bandwidth bound of the plain step" "lc rgb '#7f8c8d' dt 2 pt 0"
[ ${#plots[@]} -gt 0 ] || {
    echo "plot: '$tsv' holds no step times" >&2
    exit 1
}

joined=$(printf '%s, ' "${plots[@]}")
gnuplot <<EOF
set terminal pngcairo size 1000,760 font "sans,11"
set output '$out.tmp'
set title "Time per solver step: median, min and max of the repetitions"
set logscale xy
set xlabel 'vertices'
set ylabel 'milliseconds per step'
set format x '%.0s%c'
set grid xtics ytics mytics
set key outside center bottom horizontal maxrows 4 width -2
plot ${joined%, }
EOF
mv "$out.tmp" "$out"
echo "wrote $out (from $tsv)"
