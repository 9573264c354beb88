#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The minimizer in a person's hands, in a real window under Xvfb driven by xdotool: a region
# brushed on a noisy bunny and pins in it; the pins dragged up with M at once: the drag takes
# the direct method with the thin plate (the exported recipe says so; a screenshot of the
# dome from outside the editor), and one Ctrl+Z gives back the pins and the Jacobi steps.
# Then the thin plate ticked in the solver panel; Enter (Solve) shows the minimizer of the
# sets; the pins dragged up with M, the shape solved again at the moves; the thin plate's
# weight slider dragged (factored on the analysis kept, which the trace says); saved, the recipe
# exported; then conjugate gradients chosen in the method's menu and the pins dragged with M
# again, solved a frame at a time to the minimizer (screenshot cg-drag.png); then implicit steps chosen in the method's menu, their time slider dragged and a
# run played (its recipe exported: "implicit" with the time set). Then:
#  - meshfair-cli smooth of the base with the exported recipe ("method": "direct", the
#    bending section) gives the saved shape (to 1e-9 of the bounding box's diagonal: the
#    editor solved from the shape before the drag, the command line from the base);
#  - the pins' lift raised a dome: the vertices next to the pins follow them more closely
#    than the membrane's (the edge energy's) horn lets them, as meshfair-cli solves both
#    from the same sets. (Faces turned over are not checked: on this noisy scan the
#    minimizers of both energies turn some; see docs/math.md, "The direct method".)
#   window_solve.sh MESHFAIR MESHFAIR_CLI BUNNY.obj WORK_DIR
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    # A display and an X authority of its own (from :160 up), so that the window tests can
    # run at the same time.
    exec xvfb-run -a -n 160 -f "${4%/}.Xauthority" -s "-screen 0 1280x1024x24" "$0" "$@"
fi
meshfair=$1 cli=$2 bunny=$3 work=$4
name=solve
. "$(dirname "$0")/window_support.sh"
fresh_work_dir "$work"
"$cli" noise "$bunny" -o "$work/scan.obj" --sigma 0.3 --seed 5 >/dev/null
cp "$work/scan.obj" "$work/base.obj"
start_editor "$meshfair" "$work/scan.obj" "$work/editor.log" "$work/widgets.tsv"
key 1
key Home

# A region of the body in a rectangle; pins in its middle.
key r
drag 330 330 470 450 6
key shift+r
key alt+a
drag 394 384 406 396 2
key shift+p
wait_line "command create set: ok" 2
# The region took in the vertices the rectangle enclosed but could not see (in the folds),
# so that none stays fixed among the moving ones, and said how many.
grep -q "command create set: ok (set 'region 1': [0-9]* vertices selected and [0-9]* enclosed vertices" "$log" ||
    fail "the region did not close its holes, or did not say so: $(grep 'create set' "$log" | head -1)"
# M at once: the drag raises the thin plate's dome (the direct method), in one undo step.
key m
drag 400 390 400 360 6
wait_line "gesture move pins"
wait_line "solved: the minimizer"
xwd -root -silent | convert xwd:- "$work/dome.png"
export_recipe "dome-recipe.json"
key ctrl+z
wait_line "command undo: ok"
export_recipe "undone-recipe.json" 2
python3 - "$work" <<'PY' || fail "the M drag did not take the thin plate, or Ctrl+Z did not give it back"
import json, sys
work = sys.argv[1]
dome = json.load(open(f"{work}/dome-recipe.json"))
undone = json.load(open(f"{work}/undone-recipe.json"))
assert dome.get("method") == "direct" and dome["bending"]["mu"] == 1, dome
assert "targets" in dome["hard"], "the drag moved no pin"
assert undone.get("method", "jacobi") == "jacobi" and "bending" not in undone, undone
assert "targets" not in undone["hard"], "the undo left the pins moved"
PY
# The thin plate, then Solve with Enter: the minimizer is shown.
click_widget "thin plate (a dome under pins)"
wait_line "command solver settings: ok"
key Return
wait_line "command solve: ok"
wait_line "solved: the minimizer"
solves=$(count_lines "solved: the minimizer")
# The pins dragged up with M: solved again at the moves (the factorization kept).
gestures=$(count_lines "gesture move pins")
key m
drag 400 390 400 360 6
wait_line "gesture move pins" $((gestures + 1))
wait_line "solved: the minimizer" $((solves + 1))
# The thin plate's weight dragged in the panel: a new recipe of the same pattern at each
# value, factored on the analysis kept from the run before (the trace and the panel say
# so), and the minimizer shown again.
kept=$(count_lines "solver: factored on the analysis kept")
settings=$(count_lines "command solver settings: ok")
read -r mx my < <(widget_at "bending mu")
drag "$mx" "$my" $((mx + 30)) "$my" 3
wait_line "command solver settings: ok" $((settings + 1))
wait_line "solver: factored on the analysis kept" $((kept + 1))
wait_line "solved: the minimizer" $((solves + 2))
widget_at "noise sigma" >/dev/null # the panel scrolled to the line that says how it factored
xwd -root -silent | convert xwd:- "$work/analysis-kept.png"
key ctrl+s
wait_line "command save: ok"
export_recipe "solve-recipe.json"
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "$(grep failed "$log" | head -3)"
# Conjugate gradients chosen in the method's menu (a system too large to factor): the
# minimizer shown again, then the pins dragged with M, solved a frame at a time to it.
settings=$(count_lines "command solver settings: ok")
solves=$(count_lines "solved: the minimizer")
click_widget "method"
click_widget "method/CG: the minimizer"
wait_line "command solver settings: ok" $((settings + 1))
wait_line "solved: the minimizer" $((solves + 1))
gestures=$(count_lines "gesture move pins")
key m
drag 400 360 400 340 6
wait_line "gesture move pins" $((gestures + 1))
wait_line "solved: the minimizer" $((solves + 2))
xwd -root -silent | convert xwd:- "$work/cg-drag.png"
export_recipe "cg-recipe.json" 4
grep -q '"method": "cg"' "$work/cg-recipe.json" || fail "the CG drag's recipe is not cg"
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "$(grep failed "$log" | head -3)"
# Implicit steps chosen in the method's menu, their time dragged, Space: a run of
# backward-Euler steps (after the save: the run is discarded at the end).
settings=$(count_lines "command solver settings: ok")
click_widget "method"
click_widget "method/implicit (backward Euler)"
wait_line "command solver settings: ok" $((settings + 1))
read -r tx ty < <(widget_at "time")
drag "$tx" "$ty" $((tx + 40)) "$ty" 3
wait_line "command solver settings: ok" $((settings + 2))
key space
wait_line "run stopped"
export_recipe "implicit-recipe.json" 5
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "$(grep failed "$log" | head -3)"
key ctrl+q # the run's shape is not saved: it asks
click_widget "Discard and quit"
wait_exit "$pid" "$log" "$name" "Discard and quit after the implicit run"
python3 - "$work" <<'PY' || fail "the implicit run's recipe is not what the panel was set to"
import json, sys
r = json.load(open(f"{sys.argv[1]}/implicit-recipe.json"))
assert r["method"] == "implicit", r["method"]
assert r["time"] > 1, r["time"]  # dragged right from 1
PY

grep -q '"method": "direct"' "$work/solve-recipe.json" || fail "the exported recipe is not direct"
grep -q '"bending"' "$work/solve-recipe.json" || fail "the exported recipe has no bending"
"$cli" smooth "$work/base.obj" -o "$work/cli.obj" --recipe "$work/solve-recipe.json" -q
# The pins' response, for the thin plate and for the membrane: the minimizer with the pins
# where the drag left them, less the minimizer with them where they were (the energies are
# quadratic: the difference is the drag's own effect, whatever the fairing of the region
# does to the rest of the shape).
python3 - "$work" <<'PY' || fail "cannot write the peer recipes"
import json
import sys
work = sys.argv[1]
r = json.load(open(f"{work}/solve-recipe.json"))
still = dict(r, hard={"vertices": r["hard"]["vertices"]})
membrane, membrane_still = dict(r), dict(still)
del membrane["bending"], membrane_still["bending"]
for name, recipe in [("plate-still", still), ("membrane", membrane), ("membrane-still", membrane_still)]:
    json.dump(recipe, open(f"{work}/{name}.json", "w"))
PY
for peer in plate-still membrane membrane-still; do
    "$cli" smooth "$work/base.obj" -o "$work/$peer.obj" --recipe "$work/$peer.json" -q
done
python3 - "$work" <<'PY' || fail "the solved shape is not what Solve and the thin plate promise"
import json
import math
import statistics
import sys

work = sys.argv[1]


def read(path):
    v, f = [], []
    for line in open(path):
        p = line.split()
        if p and p[0] == "v":
            v.append([float(c) for c in p[1:4]])
        elif p and p[0] == "f":
            f.append([int(c.split("/")[0]) - 1 for c in p[1:]])
    return v, f


base, faces = read(f"{work}/base.obj")
saved, cli = read(f"{work}/scan.obj")[0], read(f"{work}/cli.obj")[0]
plate_still = read(f"{work}/plate-still.obj")[0]
membrane, membrane_still = read(f"{work}/membrane.obj")[0], read(f"{work}/membrane-still.obj")[0]
recipe = json.load(open(f"{work}/solve-recipe.json"))


def indices(listed):
    # A recipe's index list: indices and runs [first, last] (docs/recipe.md).
    out = []
    for item in listed:
        out.extend(range(item[0], item[1] + 1) if isinstance(item, list) else [item])
    return out


diagonal = math.dist([min(p[a] for p in base) for a in range(3)],
                     [max(p[a] for p in base) for a in range(3)])
gap = max(abs(s - c) for ps, pc in zip(saved, cli) for s, c in zip(ps, pc))
if gap > 1e-9 * diagonal:
    sys.exit(f"the saved shape is {gap / diagonal:.3g} of the diagonal from the command line's")
pins = indices(recipe["hard"]["vertices"])
targets = recipe["hard"]["targets"]
lift = [sum(targets[k][a] - base[v][a] for k, v in enumerate(pins)) / len(pins) for a in range(3)]
length = math.hypot(*lift)
if length < 0.01 * diagonal:
    sys.exit(f"the pins were hardly moved ({length / diagonal:.3g} of the diagonal)")
direction = [c / length for c in lift]
centre = [sum(base[v][a] for v in pins) / len(pins) for a in range(3)]
region = sorted(set(indices(recipe["region"]["vertices"])) - set(pins),
                key=lambda i: math.dist(base[i], centre))


def response(after, before, i):
    return sum((after[i][a] - before[i][a]) * direction[a] for a in range(3)) / length


# The dome's top is flat: the region's 50 vertices nearest the pins follow them more
# closely than the membrane's horn lets them (measured 0.60 against 0.45 of the lift).
near = region[:50]
plate_near = statistics.median(response(saved, plate_still, i) for i in near)
membrane_near = statistics.median(response(membrane, membrane_still, i) for i in near)
print(f"next to the pins: the plate follows {plate_near:.2f} of the lift, the membrane {membrane_near:.2f}")
if not plate_near >= 1.2 * membrane_near:
    sys.exit("a horn, not a dome: the vertices next to the pins do not follow them")

PY
echo "ok: M raised a dome at once (the direct method with the thin plate, undone with the pins by one Ctrl+Z; picture: $work/dome.png); Enter solved the region with the thin plate; pins dragged with M solved again; the thin plate's weight dragged, factored on the analysis kept (picture: $work/analysis-kept.png); CG chosen and the pins dragged, solved frame by frame (picture: $work/cg-drag.png); the saved shape is meshfair-cli's minimizer and a dome"
