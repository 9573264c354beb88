#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A long preparation in a person's hands, in a real window under Xvfb driven by xdotool: a
# noisy grid of 490,000 vertices, its interior a region (Ctrl+B, Ctrl+I, Shift+R) and pins in
# its middle. Enter (Solve) prepares the direct method: a box over the view shows the phase
# while it orders and factors, with a bar and Cancel (a screenshot), and the minimizer is
# shown. The thin
# plate ticked prepares a new system; Esc cancels it: no factorization after the ordering
# under way, the shape stays (a screenshot), the trace says so. Enter prepares it again and
# shows its minimizer; "keep volume" ticked then shows the minimizer under the volume.
#   window_prepare.sh MESHFAIR MESHFAIR_CLI WORK_DIR
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    exec xvfb-run -a -n 160 -f "${3%/}.Xauthority" -s "-screen 0 1280x1024x24" "$0" "$@"
fi
meshfair=$1 cli=$2 work=$3
name=prepare
. "$(dirname "$0")/window_support.sh"
fresh_work_dir "$work"
python3 - "$work/grid.obj" <<'PY'
import sys
n = 700  # 490,000 vertices, 488,601 quads
with open(sys.argv[1], "w") as f:
    f.write("".join(f"v {i / (n - 1):.6f} {j / (n - 1):.6f} 0\n" for j in range(n) for i in range(n)))
    f.write("".join(f"f {j * n + i + 1} {j * n + i + 2} {(j + 1) * n + i + 2} {(j + 1) * n + i + 1}\n"
                    for j in range(n - 1) for i in range(n - 1)))
PY
"$cli" noise "$work/grid.obj" -o "$work/scan.obj" --sigma 0.3 --seed 3 >/dev/null
start_editor "$meshfair" "$work/scan.obj" "$work/editor.log" "$work/widgets.tsv"
key 1
key Home

# The interior a region (the border stays), pins in the middle.
key ctrl+b
key ctrl+i
key shift+r
wait_line "command create set: ok"
key alt+a
key r
drag 320 340 340 360 2
key shift+p
wait_line "command create set: ok" 2

# Enter: the direct method prepared, its phases shown, then the minimizer.
key Return
wait_line "command solve: ok"
wait_line "solver: preparing: ordering"
widget_at "cancel preparation" >/dev/null # the box over the view, in a frame shown
xwd -root -silent | convert xwd:- "$work/preparing.png"
wait_line "solver: preparing: factoring"
wait_line "solved: the minimizer"
[ "$(count_lines 'solver: factored')" = 1 ] || fail "the first preparation was not factored once"

# The thin plate: a new system, analysed afresh; Esc while it orders cancels it.
click_widget "thin plate (a dome under pins)"
wait_line "command solver settings: ok"
wait_line "solver: preparing: ordering" 2
key Escape
wait_line "command cancel preparation: ok"
wait_line "solver: preparation cancelled"
xwd -root -silent | convert xwd:- "$work/cancelled.png"
[ "$(count_lines 'solver: factored')" = 1 ] || fail "the cancelled preparation was factored"
[ "$(count_lines 'solved: the minimizer')" = 1 ] || fail "the cancelled preparation was solved"
[ "$(count_lines 'solver: preparing: factoring')" = 1 ] ||
    echo "note: the cancel came after the ordering (the factorization's result dropped)" >&2

# Enter prepares it again: the thin plate's minimizer is shown.
key Return
wait_line "command solve: ok" 2
wait_line "solved: the minimizer" 2
[ "$(count_lines 'solver: factored')" = 2 ] || fail "Solve after the cancel did not factor"
# "keep volume" ticked: the minimizer under the volume (the same pattern: factored on the
# analysis kept), its recipe "direct" with the volume.
click_widget "keep volume"
wait_line "command solver settings: ok" 2
wait_line "solver: factored on the analysis kept"
wait_line "solved: the minimizer" 3
export_recipe "volume-recipe.json"
python3 - "$work/volume-recipe.json" <<'PY' || fail "the exported recipe is not the direct method with the volume"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["method"] == "direct" and "volume" in r and "bending" in r, r.keys()
PY
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "$(grep failed "$log" | head -3)"
key ctrl+q
click_widget "Discard and quit"
wait_exit "$pid" "$log" "$name" "Discard and quit after the solve"
echo "ok $name"
