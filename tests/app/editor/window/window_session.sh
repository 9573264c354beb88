#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A person's whole session in a real window under Xvfb, driven by synthetic input (xdotool):
# open a noisy mesh; brush a patch and grow it; make it a region; pins dragged with M (which
# takes the thin plate and the direct method: Jacobi steps and no thin plate chosen again in
# the solver panel, the shape reset to the base); a normal set aimed with D; anchors with their own weight; Play until the energy settles, at
# 200 steps a frame; the lambda slider moved; Play again; undo back to the shape at the
# slider's change; save; export the recipe through the File menu's dialog; reopen the mesh;
# import the recipe. The files must agree: meshfair-cli smooth of the mesh with the
# exported recipe gives the saved file byte for byte, and the imported recipe exports the
# same sets and settings again.
#   window_session.sh MESHFAIR MESHFAIR_CLI BUNNY.obj WORK_DIR
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    # A display and an X authority of its own (from :130 up), so that the window tests can
    # run at the same time.
    exec xvfb-run -a -n 130 -f "${4%/}.Xauthority" -s "-screen 0 1280x1024x24" "$0" "$@"
fi
meshfair=$1 cli=$2 bunny=$3 work=$4
name=session
. "$(dirname "$0")/window_support.sh"
fresh_work_dir "$work"
"$cli" noise "$bunny" -o "$work/scan.obj" --sigma 0.3 --seed 4 >/dev/null
cp "$work/scan.obj" "$work/base.obj"
start_editor "$meshfair" "$work/scan.obj" "$work/editor.log" "$work/widgets.tsv"
key 1
key Home

# A patch brushed over the body and grown by a ring: the region.
key c
drag 340 360 470 430 10
wait_line "gesture brush stroke"
key ctrl+equal
key shift+r
# Pins in it, dragged with M.
key r
drag 390 380 410 400 2
key shift+p
key m
drag 400 390 408 380 4
wait_line "gesture move pins"
# The drag took the thin plate and the direct method (a dome); this session runs Jacobi
# steps: the method's menu and the thin plate's box in the solver panel take them back.
settings=$(count_lines "command solver settings: ok")
click_widget "method"
click_widget "method/Jacobi steps"
click_widget "thin plate (a dome under pins)"
wait_line "command solver settings: ok" $((settings + 2))
# The runs start from the base (Reset), so that the command line gives their shape.
click_widget "Reset"
wait_line "command reset: ok"
# A normal set of a few faces, aimed with D.
key v
key r
drag 440 400 455 415 2
key shift+n
key v
key d
# The arrow under the cursor is highlighted, its tip marked ("grab/tip" in the widget map):
# pressed at its tip, away from its base, D takes the whole arrow (never the view).
move_to 447 407
next_frame
read -r bx by < <(widget_centre "grab/base")
read -r tx ty < <(widget_centre "grab/tip")
[ -n "${tx:-}" ] || fail "no arrow highlighted under the D tool at 447 407"
reach=$(awk -v a="$bx" -v b="$by" -v c="$tx" -v d="$ty" 'BEGIN { printf "%d", sqrt((a-c)^2 + (b-d)^2) }')
[ "$reach" -gt 14 ] || fail "the arrow's tip is $reach px from its base: a press there cannot tell them apart"
drag "$tx" "$ty" $((tx + 23)) $((ty + 5)) 4
wait_line "gesture normal direction"
# Anchors, with a weight of their own: their row's slider dragged.
key r
drag 360 420 380 440 2
key shift+a
wait_line "command create set: ok" 4
read -r mx my < <(widget_at "sets/anchor 1/mu")
drag "$mx" "$my" $((mx + 30)) "$my" 3
wait_line "command set weight: ok"
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "$(grep failed "$log" | head -3)"

# Play until the energy settles (the run stops by itself); the lambda slider moved; Play
# again until it settles. Each run is waited for to its end, never guessed at; the slider
# moves between the two runs, not during one: the live solver's pace is not to be relied
# on (at a step a frame the first run lasts its 299 frames, but it has been seen to take
# many steps a frame and settle within three frames, before a hand can take the slider).
# The steps/frame slider dragged to its right end (200): either way a run of a few frames.
settings=$(count_lines "command solver settings: ok")
click_widget "until converged"
read -r px py < <(widget_at "steps/frame")
drag "$px" "$py" $((px + 150)) "$py" 4
wait_line "command solver settings: ok" $((settings + 2))
key space
# (Runs to the minimizer: thousands of Jacobi steps; a longer guard against a hang, on a
# machine that runs other window tests beside this one.)
wait_limit=$((3 * wait_limit)) wait_line "run stopped"
read -r lx ly < <(widget_at "lambda")
settings=$(count_lines "command solver settings: ok")
drag "$lx" "$ly" $((lx - 40)) "$ly" 1
wait_line "command solver settings: ok" $((settings + 1))
key space
wait_limit=$((3 * wait_limit)) wait_line "run stopped" 2
wait_line "command play/pause: ok" 2
stopped() { sed -n 's/^run stopped: \([0-9]*\) steps.*/\1/p' "$log" | sed -n "$1p"; }
first=$(stopped 1) second=$(stopped 2)
# "Until converged" stops on the gradient: at 1e-6 of the run's start (the rule of the
# command line's tolerance), not where the energy's decrease slows.
gradient=$(sed -n 's/^run stopped: .*gradient \([0-9.e+-]*\) of the start.s, converged$/\1/p' "$log" | head -1)
[ -n "$gradient" ] || fail "the first run did not stop converged: $(grep 'run stopped' "$log" | head -1)"
awk -v g="$gradient" 'BEGIN { exit !(g <= 1e-6) }' ||
    fail "the run stopped at a relative gradient of $gradient, above 1e-6"
[ "$second" -gt "$first" ] ||
    fail "the run after the slider's change made no step ($first, then $second steps from the base)"
# The plot of a region's run: the energy of what moves falls by far more of itself than the
# whole mesh's, whose fixed rest is most of it (the trace says what the plot shows).
python3 - "$log" <<'PY' || fail "the plot's energy of what moves is not the region's: $(grep 'energy of what moves' "$log" | head -1)"
import re, sys
line = next(l for l in open(sys.argv[1]) if l.startswith("energy of what moves"))
a, b, c, d = map(float, re.findall(r"[-+0-9.e]+(?= ->|;|$)|(?<=-> )[-+0-9.e]+", line)[:4])
assert 0 < b < a and 0 < d < c and b < d, line
assert (a - b) / a > 5 * (c - d) / c, line
PY
xwd -root -silent | convert xwd:- "$work/plot-moves.png"
click_widget "whole mesh"
wait_line "command toggle: ok"
next_frame
xwd -root -silent | convert xwd:- "$work/plot-whole.png"
click_widget "whole mesh"
wait_line "command toggle: ok" 2
# The heat map of the total: the region coloured, the fixed rest grey.
click_widget "heat map"
click_widget "heat map/total"
wait_line "command heat map: ok"
next_frame
next_frame
xwd -root -silent | convert xwd:- "$work/heat-total.png"
click_widget "heat map"
click_widget "heat map/off"
wait_line "command heat map: ok" 2
# Undo the run after the change and the change: the shape the slider moved on.
key ctrl+z
key ctrl+z
wait_line "command undo: ok" 2
key ctrl+s
wait_line "command save: ok"
# The scan lies on its back: -Z up, which the exported recipe carries.
click_widget "View"
click_widget "View/Up axis -Z"
wait_line "command up axis: ok"
export_recipe "session-recipe.json"
python3 - "$work/session-recipe.json" <<'PY' || fail "the exported recipe lacks the editor's sets or the up axis, or lists no run"
import json, sys
r = json.load(open(sys.argv[1]))
e = r["editor"]
assert e["up"] == "-z", e["up"]
names = [s["name"] for s in e["sets"]]
assert names[:2] == ["region 1", "pin 1"], names
assert any(isinstance(i, list) for i in r["region"]["vertices"]), "no run in the region's list"
PY
grep -q reproduces "$log" || true

# Reopen the mesh as it was read (a copy of the base), import the recipe, export it again.
key ctrl+o
wait_dialog
key ctrl+a
type_text "base.obj"
key Return
wait_line "command open: ok"
# +Y up again before the import, which brings back the recipe's -Z.
click_widget "View"
click_widget "View/Up axis +Y"
wait_line "command up axis: ok" 2
click_widget "File"
click_widget "File/Import recipe..."
wait_dialog
key ctrl+a
type_text "session-recipe.json"
key Return
wait_line "command import recipe: ok"
export_recipe "reimported.json" 2
# Escape closes an open menu; Ctrl+Q quits with one open.
click_widget "File"
[ -n "$(widget_centre "File/Open...")" ] || fail "the File menu did not open"
key Escape
next_frame
next_frame
[ -z "$(widget_centre "File/Open...")" ] || fail "Escape did not close the File menu"
click_widget "File"
[ -n "$(widget_centre "File/Open...")" ] || fail "the File menu did not open again"
key ctrl+q # the imported pins moved to their targets: unsaved changes, it asks
click_widget "Discard and quit"
wait_exit "$pid" "$log" "$name" "Discard and quit after the import"

# The command line reproduces the saved shape from the base and the exported recipe.
"$cli" smooth "$work/base.obj" -o "$work/cli.obj" --recipe "$work/session-recipe.json" -q
cmp "$work/cli.obj" "$work/scan.obj" ||
    fail "meshfair-cli smooth with the exported recipe does not give the saved file"
cmp -s "$work/base.obj" "$work/scan.obj" && fail "the saved file is the base: nothing was smoothed"
steps=$(grep -o '"iterations": [0-9]*' "$work/session-recipe.json" | awk 'NR == 1' | grep -o '[0-9]*$')
[ "$steps" -gt 0 ] || fail "the exported recipe runs no step"
# The imported recipe gives the same sets and settings (its steps: none since the reopen).
[ -f "$work/reimported.json" ] || fail "no reimported.json written: $(ls "$work")"
diff <(grep -v '"iterations"' "$work/session-recipe.json") \
    <(grep -v '"iterations"' "$work/reimported.json") >/dev/null ||
    fail "the imported recipe exports other sets or settings"
echo "ok: a whole session (region, pins moved, normals aimed, anchors, a run, the lambda slider moved, a run again, undo to the change, save, export, reopen, import) reproduced by meshfair-cli after $steps steps"
