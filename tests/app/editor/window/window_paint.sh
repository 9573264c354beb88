#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Paint tool and the preset menu in a real window under Xvfb, driven by synthetic input
# (xdotool) as a person drives them:
#  1. O, then a stroke over the bunny's flank: one undo step; the brush's weight map shows
#     as a tint (green, weight 1/2 at the default strength, under the stroke, over the surface's own colour, in a
#     screenshot taken from outside the editor);
#  2. the recipe exported through the File menu reproduces the saved shape through
#     meshfair-cli, and the stroke the trace prints, played as a script offscreen, too; the
#     save (Ctrl+Shift+S, a name typed) keeps the scan's vertex colours, group and material;
#  3. "subtract weight" clicked in the Paint panel, a stroke, Ctrl+Z: one undo step each;
#     an anchor set made with the selection brush, picked from the "paint set" menu, its
#     map lowered with a curve from the menu and a dragged strength (red at weight 1 in a
#     screenshot), smoothed, then the smoothing brush with more stroke steps: each setting
#     in the printed stroke;
#  4. the denoise preset chosen in the solver panel's menu keeps the brush's region, and
#     the recipe exported then has its bilateral weights and the volume; the creases'
#     checkbox and sigma_r slider, the falloff's checkbox, radius slider and curve menu
#     clicked, each a solver-settings command, all in the next exported recipe.
#   window_paint.sh MESHFAIR MESHFAIR_CLI BUNNY.obj WORK_DIR
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    # A display and an X authority of its own (from :140 up), so that the window tests can
    # run at the same time.
    exec xvfb-run -a -n 140 -f "${4%/}.Xauthority" -s "-screen 0 1280x1024x24" "$0" "$@"
fi
meshfair=$1 cli=$2 bunny=$3 work=$4
name=paint
. "$(dirname "$0")/window_support.sh"
fresh_work_dir "$work"
"$cli" noise "$bunny" -o "$work/noisy.obj" --sigma 0.3 --seed 4 >/dev/null
# A scan's colours on every vertex, a group and a material, which a save must keep.
awk '/^v / { printf "%s %.3f 0.5 %.3f\n", $0, (NR % 97) / 96, (NR % 13) / 12; next }
     /^f / && !grouped { print "g bunny"; print "usemtl clay"; grouped = 1 } { print }' \
    "$work/noisy.obj" >"$work/coloured.obj"
mv "$work/coloured.obj" "$work/noisy.obj"
cp "$work/noisy.obj" "$work/input.obj"
start_editor "$meshfair" "$work/noisy.obj" "$work/editor.log" "$work/widgets.tsv"

# The vertex lines of two OBJ files are the same.
same_vertices() { cmp -s <(grep '^v ' "$1") <(grep '^v ' "$2"); }

# --- 1. A stroke of the smoothing brush over the flank, in the front view.
key 1
key Home
key o
drag 330 390 470 410 10
wait_line "gesture paint"
wait_line "^stroke {"
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "a command failed: $(grep 'failed' "$log" | head -3)"
next_frame # a frame drawn after the stroke's end, on the screen
xwd -root -silent | convert xwd:- "$work/painted.png"
# Tinted green (weight 1/2, cyan where less) under the stroke, over the surface seen through
# the tint: pixels far more green than red; the rest of the bunny its own colour (weight 0:
# no tint), grey-beige.
count() { # the expression computed on one channel only: the same count, a third of the work
    convert "${2:-$work/painted.png}" -crop 640x420+0+40 +repage -channel R -fx "$1" +channel \
        -format '%[fx:round(mean.r * w * h)]' info:
}
green=$(count 'g > r + 0.15 && g > 0.35')
plain=$(count 'r > 0.3 && abs(r - g) < 0.08 && r - b < 0.2 && r - b > -0.02')
[ "$green" -gt 300 ] && [ "$plain" -gt 20000 ] ||
    fail "the weight map is not shown over the surface: $green tinted pixels under the stroke, $plain of the surface's own colour"

# --- 2. The exported recipe and the printed stroke reproduce the shape.
export_recipe "stroke.json"
key ctrl+shift+s
wait_dialog
key ctrl+a
type_text "stroked.obj"
key Return
wait_line "command save: ok"
"$cli" smooth "$work/input.obj" -o "$work/cli.obj" --recipe "$work/stroke.json" --quiet
same_vertices "$work/cli.obj" "$work/stroked.obj" ||
    fail "meshfair-cli with the exported recipe does not give the stroke's shape"
same_vertices "$work/input.obj" "$work/stroked.obj" && fail "the stroke moved nothing"
colours() { awk '/^v / { printf "%.9g %.9g %.9g\n", $5, $6, $7 }' "$1"; }
cmp -s <(colours "$work/input.obj") <(colours "$work/stroked.obj") ||
    fail "the save did not keep the vertex colours"
[ "$(grep -c '^g bunny$\|^usemtl clay$' "$work/stroked.obj")" = 2 ] ||
    fail "the save did not keep the group and the material"
stroke=$(grep '^stroke ' "$log" | tail -1 | cut -d' ' -f2-)
echo "{\"actions\": [$stroke, {\"save_mesh\": \"$work/replayed.obj\"}]}" >"$work/replay.json"
env -u DISPLAY "$meshfair" --offscreen "$work/input.obj" --script "$work/replay.json" \
    --screenshot "$work/replayed.png" >/dev/null
same_vertices "$work/replayed.obj" "$work/stroked.obj" ||
    fail "the printed stroke, played as a script, does not give the stroke's shape"

# --- 3. Weights subtracted with a stroke (one undo step more), then undone.
undo_steps() { grep '^gesture paint' "$log" | tail -1 | sed 's/.*: \([0-9]*\) undo steps/\1/'; }
last_stroke() { grep '^stroke ' "$log" | tail -1; }
click_widget "subtract weight"
wait_line "command paint settings: ok"
strokes=$(count_lines '^gesture paint')
before=$(undo_steps)
drag 360 395 420 400 6
wait_line "^gesture paint" $((strokes + 1))
[ "$(undo_steps)" = $((before + 1)) ] ||
    fail "the subtract stroke made $(($(undo_steps) - before)) undo steps, not 1"
key ctrl+z
wait_line "command undo: ok"

# An anchor set's map: picked from the "paint set" menu, lowered with the sphere curve at
# a dragged strength, then smoothed; in colour red at 1, lower under the stroke.
set_paint() { # set_paint ACTION...: an action on the Paint panel, and its settings command
    local n
    n=$(count_lines "command paint settings: ok")
    "$@"
    wait_line "command paint settings: ok" $((n + 1))
    next_frame # the panel laid out again, after the frame that gave the command
}
drag_widget() { # drag_widget LABEL DX: a slider dragged from its centre
    local x y
    read -r x y < <(widget_at "$1")
    drag "$x" "$y" $((x + $2)) "$y" 4
}
key c
drag 300 370 480 420 6
key shift+a
wait_line "command create set: ok"
key alt+a # the selection's tint off the screenshot
key o
click_widget "paint set"
set_paint click_widget "paint set/anchor 1"
click_widget "brush curve"
set_paint click_widget "brush curve/sphere"
set_paint drag_widget "strength" 60
drag 360 395 420 400 6
wait_line "^gesture paint" $((strokes + 2))
python3 - "$(last_stroke | cut -d' ' -f2-)" <<'PY' || fail "the anchor stroke is not as clicked: $(last_stroke)"
import json, sys
p = json.loads(sys.argv[1])["paint"]
assert p["set"] == "anchor 1" and p["mode"] == "subtract" and p["curve"] == "sphere", p
assert p["strength"] > 0.5, p  # dragged right from 0.5
PY
next_frame # a frame drawn after the stroke's end, on the screen
xwd -root -silent | convert xwd:- "$work/anchors.png"
red=$(count 'r > g + 0.25 && r > b + 0.25 && r > 0.4' "$work/anchors.png")
[ "$red" -gt 300 ] || fail "the anchor set's map (weight 1) shows no red: $red pixels"
set_paint click_widget "smooth weights"
drag 360 395 420 400 6
wait_line "^gesture paint" $((strokes + 3))
[[ "$(last_stroke)" == *'"mode":"smooth"'* ]] || fail "no smoothing stroke: $(last_stroke)"
# Back to the smoothing brush on the brush's region, with more steps a stroke.
set_paint click_widget "smooth brush"
click_widget "paint set"
next_frame # the menu open: its items' places are this frame's, not those of the last time
set_paint click_widget "paint set/brush"
set_paint drag_widget "stroke steps" 40
before=$(undo_steps)
drag 360 395 420 400 6
wait_line "^gesture paint" $((strokes + 4))
[ "$(undo_steps)" = $((before + 1)) ] || fail "the smoothing stroke made no undo step"
python3 - "$(last_stroke | cut -d' ' -f2-)" <<'PY' || fail "the last stroke is not as clicked: $(last_stroke)"
import json, sys
p = json.loads(sys.argv[1])["paint"]
assert p["set"] == "brush" and p["mode"] == "relax" and p["steps"] != 10, p
PY
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "a command failed: $(grep 'failed' "$log" | head -3)"

# --- 4. The denoise preset over the brush's region.
click_widget "preset"
click_widget "preset/denoise"
wait_line "command preset: ok"
export_recipe "denoise-here.json" 2
for part in '"bilateral"' '"volume"' '"region"'; do
    grep -q "$part" "$work/denoise-here.json" ||
        fail "the recipe after the denoise preset lacks $part"
done

# The shape was saved, and sets are not the mesh file's: Ctrl+Q quits without asking.
# The bilateral weights off and on again, sigma_r dragged, a falloff with another radius
# and the linear curve: each click a solver-settings command.
settings=$(count_lines "command solver settings: ok")
click_widget "keep creases (bilateral)"
wait_line "command solver settings: ok" $((settings + 1))
click_widget "keep creases (bilateral)"
wait_line "command solver settings: ok" $((settings + 2))
read -r sx sy < <(widget_at "crease sigma_r")
drag "$sx" "$sy" $((sx - 60)) "$sy" 4 # the slider toward smaller values
wait_line "command solver settings: ok" $((settings + 3))
click_widget "falloff from border and pins"
wait_line "command solver settings: ok" $((settings + 4))
read -r rx ry < <(widget_at "falloff radius")
drag "$rx" "$ry" $((rx + 40)) "$ry" 4
wait_line "command solver settings: ok" $((settings + 5))
click_widget "falloff curve"
click_widget "falloff curve/linear"
wait_line "command solver settings: ok" $((settings + 6))
export_recipe "tuned.json" 3
python3 - "$work/tuned.json" <<'PY' || fail "the clicked settings are not in the exported recipe"
import json, sys
r = json.load(open(sys.argv[1]))
b = r["normal_smoothing"]["bilateral"]
f = r["falloff"]
assert b["neighbors"] == "vertex", b  # the preset's, back after off and on
assert abs(b["sigma_r"] - 0.3) > 0.01, b  # dragged from the preset's 0.3
assert f["curve"] == "linear" and f["radius"] != 8, f  # dragged from 8, then linear
PY

# The last smoothing stroke is not saved: Ctrl+Q asks.
key ctrl+q
click_widget "Discard and quit"
wait_exit "$pid" "$log" "$name" "Discard and quit"
echo "ok: a smoothing stroke ($green tinted pixels of weight 1/2, $plain of the surface untinted), reproduced by meshfair-cli and by its script; weights subtracted and undone; an anchor set's map painted and smoothed from the panel's menus and sliders ($red red pixels of weight 1); the denoise preset over the region"
