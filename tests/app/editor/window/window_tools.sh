#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every tool and panel of the editor in a real window under Xvfb, driven by synthetic input
# (xdotool) as a person drives it:
#  1. each tool key (N, K, C, R, L, M, D) with moves and drags over the view, with and
#     without sets to act on: the editor lives and every command succeeds;
#  2. a selection, then with each tool active, clicks on an empty part of the side panel and
#     on its widgets: no click reaches the view (no gesture in the trace), so a region made
#     of the selection and smoothed moves only the selected part (the saved file says so);
#  3. the volume and Taubin's method clicked in the solver panel, in the exported recipe;
#     the menus and the file dialogs with typed names (Ctrl+A then typing replaces the name,
#     fast typing loses nothing), Save As then Ctrl+S, the window's title;
#  4. quitting with unsaved changes (asks; Cancel keeps the editor) and without.
#   window_tools.sh MESHFAIR MESHFAIR_CLI BUNNY.obj WORK_DIR
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    # A display and an X authority of its own (from :120 up), so that the window tests can
    # run at the same time.
    exec xvfb-run -a -n 120 -f "${4%/}.Xauthority" -s "-screen 0 1280x1024x24" "$0" "$@"
fi
meshfair=$1 cli=$2 bunny=$3 work=$4
name=tools
. "$(dirname "$0")/window_support.sh"
fresh_work_dir "$work"
"$cli" noise "$bunny" -o "$work/noisy.obj" --sigma 0.3 --seed 2 >/dev/null
cp "$work/noisy.obj" "$work/loaded.obj"
start_editor "$meshfair" "$work/noisy.obj" "$work/editor.log" "$work/widgets.tsv"

# --- 1. Each tool over the view, with no set to act on, then with sets.
for round in 1 2; do
    for t in n k c r l m d; do
        key "$t"
        move_to 250 250 # each move seen by the tool before the next
        move_to 330 300
        case "$round$t" in
            2m) # from the pins, in the view they were made in (N's drag orbited)
                key 1 && key Home && key m && drag 400 390 430 360 4 ;;
            2d) # from the normals' arrows
                key 1 && key Home && key d && drag 447 407 490 420 4 ;;
            *) drag 300 260 360 320 4 ;;
        esac
        alive "tool $t, round $round"
    done
    if [ "$round" = 1 ]; then
        # Sets for M and D to grab, on the body in the front view: pins in a small
        # rectangle, normals of a few faces.
        key 1
        key Home
        key r
        drag 390 380 410 400 2
        key shift+p
        key v
        drag 440 400 455 415 2
        key shift+n
        key v
        wait_line "command create set: ok" 2
    fi
done
wait_line "gesture move pins"
wait_line "gesture normal direction"
key ctrl+z
key ctrl+y
alive "undo and redo"
[ "$(count_lines 'command .*: failed')" = 0 ] || fail "a command failed: $(grep 'failed' "$log" | head -3)"

# --- 2. A selection, then panel clicks with each tool active.
key ctrl+z
key ctrl+z # the normals' aim and the pins' move undone; the sets stay, outside the region
key alt+a
key r
drag 280 240 360 330 4
wait_line "gesture rectangle select"
gestures=$(count_lines '^gesture')
read -r gx gy < <(widget_at "Grow")
for t in n k c r l m d; do
    key "$t"
    click_at $((gx + 70)) "$gy"            # empty panel, right of the command buttons
    click_widget "through the surface"     # a checkbox, twice: back as it was
    click_widget "through the surface"
    alive "panel clicks with tool $t"
done
[ "$(count_lines '^gesture')" = "$gestures" ] ||
    fail "a click on the panel reached the view: $(grep '^gesture' "$log" | tail -2)"
key shift+r
key space # a run of 20 steps, stopping by itself
wait_line "run stopped"
key ctrl+s
wait_line "command save: ok"
read -r same moved < <(awk 'FNR == NR { if ($1 == "v") a[++n] = $0; next }
    $1 == "v" { ++k; if ($0 == a[k]) s++; else m++ }
    END { print s + 0, m + 0 }' "$work/loaded.obj" "$work/noisy.obj")
total=$(grep -c '^v ' "$work/loaded.obj")
[ "$moved" -gt 20 ] && [ "$moved" -lt $((total / 4)) ] ||
    fail "the region's run moved $moved of $total vertices (only the selected part should move)"

# --- 3. Shape settings clicked in the solver panel, then menus and file dialogs with typed
# names: the exported recipe keeps the volume, runs Taubin's pairs and fades from the border.
settings=$(count_lines "command solver settings: ok")
click_widget "keep volume"
wait_line "command solver settings: ok" $((settings + 1))
click_widget "method"
click_widget "method/Taubin lambda|mu"
wait_line "command solver settings: ok" $((settings + 2))
click_widget "falloff from border and pins" # the region's border and the pins fade
wait_line "command solver settings: ok" $((settings + 3))
export_recipe "exported-by-hand.json"
[ -f "$work/exported-by-hand.json" ] || fail "the recipe was not written under the typed name"
for part in '"volume"' '"method": "taubin"' '"falloff"'; do
    grep -q "$part" "$work/exported-by-hand.json" ||
        fail "the recipe lacks $part, clicked in the solver panel"
done
# No recipe under another name (the typed name appended to the suggested one, say).
[ "$(cd "$work" && ls -- *.json)" = "exported-by-hand.json" ] ||
    fail "recipes under other names: $(cd "$work" && ls -- *.json)"
key ctrl+shift+s
wait_dialog
key ctrl+a
type_text "renamed-scan.obj"
key Return
wait_line "command save: ok" 2
[ -f "$work/renamed-scan.obj" ] || fail "Save As wrote no renamed-scan.obj"
# The title, set after the frame that saved is drawn: until it names the new file.
end=$((SECONDS + wait_limit))
while title=$(xdotool getwindowname "$win") && [[ $title != *renamed-scan.obj* ]]; do
    [ $SECONDS -lt $end ] || fail "the title is '$title' after Save As"
    nap
done
cp "$work/renamed-scan.obj" "$work/before-second-run.obj"
key space
wait_line "run stopped" 2
key ctrl+s
wait_line "command save: ok" 3
cmp -s "$work/renamed-scan.obj" "$work/before-second-run.obj" &&
    fail "Ctrl+S after Save As did not write the new name"

# --- 4. Quit: with unsaved changes it asks, Cancel keeps the editor.
key space
wait_line "run stopped" 3
key ctrl+q
click_widget "Cancel"
alive "Cancel in the quit prompt"
key ctrl+q
click_widget "Discard and quit"
wait_exit "$pid" "$log" "$name" "Discard and quit"

# Quit without changes: no question.
start_editor "$meshfair" "$work/loaded.obj" "$work/editor2.log" "$work/widgets2.tsv"
key ctrl+q
wait_exit "$pid" "$log" "$name" "Ctrl+Q on an unchanged mesh"
echo "ok: every tool over the view, panel clicks with each tool ($moved of $total vertices moved by the region), menus, dialogs, Save As, quit"
