#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The preset menu on an open scan in a real window under Xvfb, driven by synthetic input
# (xdotool) as a person drives it. The scan: the noisy bunny with its base cut away and five
# holes punched (six boundary loops), as a scanner gives it.
#  0. nothing holds the whole scan: "until converged" greyed with the reason (a click on it
#     changes nothing; a screenshot); fair-region chosen in the solver panel's menu on the
#     whole scan: Space refused with the reason (the play command fails with it, no run
#     is left waiting; the reason in a box over the view, its whole text a click away,
#     closed by its x), the preset undone;
#  1. denoise chosen in the solver panel's menu runs (Space) to its end, the run's note
#     saying how the open scan's volume is kept; saved (Ctrl+S) and its recipe exported:
#     meshfair-cli smooth of the scan with that recipe gives the saved file byte for byte; a
#     screenshot of the window taken from outside the editor;
#  2. Reset to the scan; denoise-organic chosen (its menu entry hovered first: the tooltip
#     says what it is for, a screenshot); its note says the noise it found and the
#     iterations taken; the strength slider dragged: the run restarts with more iterations
#     for the stronger setting, said in a new note; Reset, run to its end (the preset's own
#     12 steps), saved, its recipe
#     exported: meshfair-cli smooth of the scan with that recipe gives the saved file byte
#     for byte; a screenshot;
#     then relax and combined chosen and run in turn, each with its note;
#  3. the shape after the three runs: no face turned over against the scan (more than 90
#     degrees from its normal) and its volume, capped by the boundary loops, within 0.5 %.
#   window_open_scan.sh MESHFAIR MESHFAIR_CLI BUNNY.obj WORK_DIR
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    # A display and an X authority of its own (from :150 up), so that the window tests can
    # run at the same time.
    exec xvfb-run -a -n 150 -f "${4%/}.Xauthority" -s "-screen 0 1280x1024x24" "$0" "$@"
fi
meshfair=$1 cli=$2 bunny=$3 work=$4
name=open-scan
. "$(dirname "$0")/window_support.sh"
fresh_work_dir "$work"
"$cli" noise "$bunny" -o "$work/noisy.obj" --sigma 0.3 --seed 6 >/dev/null
python3 - "$work/noisy.obj" "$work/scan.obj" <<'PY'
# The bunny below a quarter of its height cut away and five holes of 3 % of its diagonal
# punched around vertices spread over it; the vertices no face keeps dropped.
import math, sys
vs, fs = [], []
for line in open(sys.argv[1]):
    if line.startswith("v "):
        vs.append(tuple(float(t) for t in line.split()[1:4]))
    elif line.startswith("f "):
        fs.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
lo = [min(v[a] for v in vs) for a in range(3)]
hi = [max(v[a] for v in vs) for a in range(3)]
cut = lo[1] + 0.25 * (hi[1] - lo[1])
radius = 0.03 * math.dist(lo, hi)
centroids = [[sum(vs[i][a] for i in f) / len(f) for a in range(3)] for f in fs]
# Hole centres: faces well above the cut, each far from the ones before, taken in a stride.
holes = []
for k in range(0, len(fs), 997):
    c = centroids[k]
    if c[1] > cut + 4 * radius and all(math.dist(c, h) > 6 * radius for h in holes):
        holes.append(c)
    if len(holes) == 5:
        break
kept = [f for f, c in zip(fs, centroids)
        if c[1] > cut and all(math.dist(c, h) > radius for h in holes)]
used = sorted({i for f in kept for i in f})
number = {i: k + 1 for k, i in enumerate(used)}
with open(sys.argv[2], "w") as out:
    for i in used:
        out.write("v %r %r %r\n" % vs[i])
    for f in kept:
        out.write("f " + " ".join(str(number[i]) for i in f) + "\n")
PY
cp "$work/scan.obj" "$work/input.obj"
boundary=$("$cli" info "$work/scan.obj" | awk '/^edges:/ { print }')
case "$boundary" in *" 0 boundary"*) fail "the scan is closed: $boundary" ;; esac
start_editor "$meshfair" "$work/scan.obj" "$work/editor.log" "$work/widgets.tsv"
key 1
key Home

# run_preset NAME N: the preset chosen in the solver panel's menu (the N-th command of its
# kind), its run's note read in the trace, Space, and the run played to its end.
run_preset() {
    local preset=$1 n=$2 stopped notes
    stopped=$(count_lines "run stopped")
    notes=$(count_lines "run note: volume: 1 of 1 components are open")
    click_widget "preset"
    click_widget "preset/$preset"
    wait_line "command preset: ok" "$n"
    wait_line "run note: volume: 1 of 1 components are open" $((notes + 1))
    key space
    wait_line "run stopped" $((stopped + 1))
    [ "$(count_lines 'command .*: failed')" = "$refusals" ] ||
        fail "a command failed: $(grep 'failed' "$log" | tail -3)"
}

# --- 0. Nothing holds the whole scan: "until converged" is greyed with the reason under it,
# and a click on it changes nothing (the preset chosen next is the first settings' change).
wait_line "solver: no minimizer: the free part of .* is held by nothing"
settings=$(count_lines "command solver settings: ok")
click_widget "until converged"
next_frame
xwd -root -silent | convert xwd:- "$work/no-minimizer.png"
# fair-region fairs a region: chosen on the whole scan, which nothing holds, Space says why
# and changes nothing; Ctrl+Z takes the preset back.
click_widget "preset"
click_widget "preset/fair-region"
wait_line "command preset: ok"
[ "$(count_lines "command solver settings: ok")" = "$settings" ] ||
    fail "a click on the greyed 'until converged' changed the settings"
key space
wait_line "solver failed: .*is held by nothing"
# Space is refused with the reason when the verdict came first, or its run ends at once
# when the verdict comes after it: no run is left waiting for frames that never come.
next_frame
refusals=$(count_lines "command play/pause: failed: cannot solve: .*is held by nothing")
# The reason stands in a box over the view, where the artist looks: its first lines, the
# whole text a click away; closed, it goes.
next_frame
[ -n "$(widget_centre "toast/text")" ] || fail "no box over the view says why the run was refused"
xwd -root -silent | convert xwd:- "$work/refused.png"
if [ -n "$(widget_centre "toast/whole text")" ]; then
    click_widget "toast/whole text"
    next_frame
    next_frame # (the box fits its new text from the frame after)
    xwd -root -silent | convert xwd:- "$work/refused-whole.png"
fi
click_widget "toast/close"
next_frame
next_frame
[ -z "$(widget_centre "toast/text")" ] || fail "the refusal's box did not close"
key ctrl+z
wait_line "command undo: ok"

# --- 1. denoise, saved, exported, reproduced by meshfair-cli; the window's picture.
run_preset denoise 2
grep -q "run note: volume: .*capped by fans from the loops' centroids" "$log" ||
    fail "the run's note does not say how the open scan's volume is kept"
# The picture after the run: the note in the status bar (no newer message), from outside,
# once a frame drawn after the run's end is on the screen.
next_frame
xwd -root -silent | convert xwd:- "$work/denoised.png"
key ctrl+s
wait_line "command save: ok"
export_recipe "denoise-here.json"
"$cli" smooth "$work/input.obj" -o "$work/cli.obj" --recipe "$work/denoise-here.json" -q
cmp "$work/cli.obj" "$work/scan.obj" ||
    fail "meshfair-cli smooth with the exported recipe does not give the saved file"
grep -q '"prevent_flips": true' "$work/denoise-here.json" ||
    fail "the exported recipe lacks the preset's flip guard"
noise_note="run note: normal smoothing: noise of [0-9.]* mean edge lengths found in the mesh"
grep -q "$noise_note: [0-9]* iterations (strength 1)" "$log" ||
    fail "the run's note does not say the noise denoise found in the scan"

# --- 2. Reset to the scan; denoise-organic, its tooltip, its strength slider; then the
# other presets, each run from where the last one stopped.
notes=$(count_lines "$noise_note")
click_widget "Reset"
wait_line "command reset: ok"
# The reset restarts the solver from the scan, which notes the noise again: waited for, so
# that the count below is not taken before it comes.
wait_line "$noise_note" $((notes + 1))
click_widget "preset"
hover $(widget_at "preset/denoise-organic")
next_frame
xwd -root -silent | convert xwd:- "$work/organic-tooltip.png"
notes=$(count_lines "$noise_note")
stopped=$(count_lines "run stopped")
click_widget "preset/denoise-organic" # the menu is open: the entry hovered is taken
wait_line "command preset: ok" 3
wait_line "$noise_note: [0-9]* iterations (strength 1)" $((notes + 1))
key space
wait_line "run stopped" $((stopped + 1))
first=$(grep "$noise_note" "$log" | tail -1 | sed 's/.*mesh: \([0-9]*\) iterations.*/\1/')
settings=$(count_lines "command solver settings: ok")
read -r sx sy < <(widget_at "strength")
drag "$sx" "$sy" $((sx + 60)) "$sy" 4 # toward a stronger smoothing
wait_line "command solver settings: ok" $((settings + 1))
wait_line "$noise_note: [0-9]* iterations (strength [0-9.]*)" $((notes + 2))
line=$(grep "$noise_note" "$log" | tail -1)
strength=$(sed 's/.*(strength \([0-9.]*\)).*/\1/' <<<"$line")
second=$(sed 's/.*mesh: \([0-9]*\) iterations.*/\1/' <<<"$line")
python3 -c "import sys; s, a, b = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]); sys.exit(0 if s > 1.2 and b > a else 1)" \
    "$strength" "$first" "$second" ||
    fail "the strength slider did not take more iterations: strength $strength, $first then $second"
# From the scan again with the new strength, for the preset's own steps.
click_widget "Reset"
wait_line "command reset: ok" 2
stopped=$(count_lines "run stopped")
key space
wait_line "run stopped" $((stopped + 1))
# The preset's sets' glyphs hidden (display only), so the picture shows the surface.
shown=$(count_lines "command show set: ok")
click_widget "sets/centroid/show"
wait_line "command show set: ok" $((shown + 1))
click_widget "sets/normal/show"
wait_line "command show set: ok" $((shown + 2))
next_frame
xwd -root -silent | convert xwd:- "$work/organic-strength.png"
key ctrl+s
wait_line "command save: ok" 2
export_recipe "organic-here.json" 2
grep -q '"iterations": "auto"' "$work/organic-here.json" ||
    fail "the exported recipe does not take its iterations from the noise"
grep -q "\"strength\": $strength" "$work/organic-here.json" ||
    grep -q "\"strength\": ${strength}[0-9]" "$work/organic-here.json" ||
    fail "the exported recipe lacks the strength $strength"
"$cli" smooth "$work/input.obj" -o "$work/cli-organic.obj" --recipe "$work/organic-here.json" -q
cmp "$work/cli-organic.obj" "$work/scan.obj" ||
    fail "meshfair-cli smooth with the exported organic recipe does not give the saved file"

# The iterations from the noise off: the panel offers a count instead; on again: the
# strength comes back.
settings=$(count_lines "command solver settings: ok")
click_widget "iterations from the noise"
wait_line "command solver settings: ok" $((settings + 1))
widget_at "normal iterations" >/dev/null
click_widget "iterations from the noise"
wait_line "command solver settings: ok" $((settings + 2))
widget_at "strength" >/dev/null

run_preset relax 4
run_preset combined 5
key ctrl+s
wait_line "command save: ok" 3

# --- 3. No face turned over against the scan, its capped volume kept.
python3 - "$work/input.obj" "$work/scan.obj" <<'PY' || fail "the presets' result is not what they promise"
import sys
from collections import defaultdict


def read(path):
    vs, fs = [], []
    for line in open(path):
        if line.startswith("v "):
            vs.append([float(t) for t in line.split()[1:4]])
        elif line.startswith("f "):
            fs.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
    return vs, fs


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def newell(vs, f):
    n = [0.0, 0.0, 0.0]
    for k in range(len(f)):
        c = cross(vs[f[k]], vs[f[(k + 1) % len(f)]])
        n = [n[a] + c[a] for a in range(3)]
    return n


def capped_volume(vs, fs):
    # The faces fanned from their first corners, and each boundary loop capped by the fan
    # from its centroid (the edges traversed one way more than the other, walked into loops).
    six = 0.0
    net = defaultdict(int)
    for f in fs:
        for k in range(1, len(f) - 1):
            six += dot(vs[f[0]], cross(vs[f[k]], vs[f[k + 1]]))
        for k in range(len(f)):
            a, b = f[k], f[(k + 1) % len(f)]
            net[(min(a, b), max(a, b))] += 1 if a < b else -1
    out = defaultdict(list)
    for (a, b), c in sorted(net.items()):
        for _ in range(abs(c)):
            (out[a] if c > 0 else out[b]).append(b if c > 0 else a)
    loops = 0
    for start in sorted(out):
        while out[start]:
            loop, v = [], start
            while True:
                loop.append(v)
                v = out[v].pop(0)
                if v == start:
                    break
            p = [sum(vs[i][a] for i in loop) / len(loop) for a in range(3)]
            for k in range(len(loop)):
                six += dot(p, cross(vs[loop[(k + 1) % len(loop)]], vs[loop[k]]))
            loops += 1
    return six / 6, loops


before, faces = read(sys.argv[1])
after, _ = read(sys.argv[2])
# Turned over: more than 90 degrees from the scan's normal, among the faces within 60
# degrees of the surface around them (the faces sharing a vertex, each once per shared
# vertex); the others are the scan's noise, which smoothing turns (docs/math.md).
own = [newell(before, f) for f in faces]
at_vertex = defaultdict(lambda: [0.0, 0.0, 0.0])
for f, n in zip(faces, own):
    for v in f:
        at_vertex[v] = [at_vertex[v][a] + n[a] for a in range(3)]
turned = 0
for f, n in zip(faces, own):
    around = [sum(at_vertex[v][a] for v in f) for a in range(3)]
    lies = dot(n, around) > 0.5 * (dot(n, n) * dot(around, around)) ** 0.5
    if lies and dot(n, newell(after, f)) <= 0:
        turned += 1
v0, loops = capped_volume(before, faces)
v1, _ = capped_volume(after, faces)
change = 100 * (v1 - v0) / v0
print("turned over: %d of %d faces, capped volume %+.4f %% (%d loops)" % (turned, len(faces), change, loops))
assert loops == 6, loops
assert turned == 0, turned
assert abs(change) <= 0.5, change
assert before != after
PY

key ctrl+q
wait_exit "$pid" "$log" "$name" "Ctrl+Q after the save"
echo "ok: the five presets chosen from the solver panel's menu on an open scan (6 boundary loops), each run to its end with its note; denoise's and denoise-organic's (strength $strength: $first then $second normal-smoothing iterations) saved shapes reproduced by meshfair-cli from the exported recipes; no face turned over, the capped volume kept; pictures: $work/denoised.png, $work/organic-tooltip.png, $work/organic-strength.png"
