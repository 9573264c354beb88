#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A whole editing session in a real window under Xvfb, driven by synthetic input (xdotool)
# as a user drives it: select with a rectangle, make a pin set of it, play live solving,
# pause, save; undo the run, save again; quit. The saved files are checked: after the
# run every vertex but the pinned ones moved and the pinned ones kept their bits; after the
# undo the file is the loaded mesh again, byte for byte.
#   window_session.sh MESHFAIR MESHFAIR_CLI BUNNY.obj WORK_DIR
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$@"
fi
meshfair=$1 cli=$2 bunny=$3 work=$4
. "$(dirname "$0")/window_support.sh"
rm -rf "$work"
mkdir -p "$work"
export GALLIUM_DRIVER=llvmpipe
export XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state"
export ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0"

# The mesh as the editor writes it (the same writer): what a save of the untouched mesh gives.
"$cli" convert "$bunny" -o "$work/bunny.obj" >/dev/null
cp "$work/bunny.obj" "$work/loaded.obj"
log="$work/editor.log"
"$meshfair" "$work/bunny.obj" --size 1000x700 >"$log" 2>&1 &
pid=$!
wait_first_frame "$pid" "$log" session
window=$(xdotool search --sync --name "MeshFair - bunny.obj" | head -1)
xdotool windowfocus --sync "$window"
sleep 0.3
key() { xdotool key --clearmodifiers "$@"; sleep 0.4; }
saved_after() { # waits until the file changes after a save key
    local before=$1
    for _ in $(seq 1 100); do
        [ "$(stat -c %Y.%s "$work/bunny.obj" 2>/dev/null)" != "$before" ] && return 0
        sleep 0.1
    done
    return 1
}

key r # the rectangle tool
xdotool mousemove --window "$window" 200 200 mousedown 1
for x in 260 320 380 440; do
    xdotool mousemove --window "$window" "$x" $((x - 20))
    sleep 0.05
done
xdotool mouseup 1
sleep 0.5
key shift+p # a pin set of the selected vertices
key space   # play
sleep 2
key space # pause
# The autosave (every 3 s, not while playing) has written the session's recovery files.
sleep 3.5
ls "$XDG_STATE_HOME"/meshfair/recovery/*/state.json >/dev/null 2>&1 ||
    { echo "FAIL: no recovery files 3.5 s after the run"; exit 1; }
stamp=$(stat -c %Y.%s "$work/bunny.obj")
sleep 1.1 # a new modification time
key ctrl+s
saved_after "$stamp" || { echo "FAIL: Ctrl+S wrote nothing"; cat "$log"; exit 1; }
cp "$work/bunny.obj" "$work/after_run.obj"
key ctrl+z # undo the run
stamp=$(stat -c %Y.%s "$work/bunny.obj")
sleep 1.1
key ctrl+s
saved_after "$stamp" || { echo "FAIL: the second Ctrl+S wrote nothing"; cat "$log"; exit 1; }
key ctrl+q
wait_exit "$pid" "$log" session "Ctrl+Q (unsaved changes?)"

# After the run: the pinned vertices kept their lines, all the others moved.
read -r same moved < <(awk 'FNR == NR { if ($1 == "v") a[++n] = $0; next }
    $1 == "v" { ++k; if ($0 == a[k]) s++; else m++ }
    END { print s + 0, m + 0 }' "$work/loaded.obj" "$work/after_run.obj")
total=$(grep -c '^v ' "$work/loaded.obj")
if [ "$same" -lt 10 ] || [ "$moved" -lt $((total / 2)) ]; then
    echo "FAIL: after the run $same vertices kept their place and $moved moved (of $total)"
    exit 1
fi
# After the undo: the loaded mesh again, byte for byte.
if ! cmp -s "$work/loaded.obj" "$work/bunny.obj"; then
    echo "FAIL: after the undo the saved file differs from the loaded one"
    exit 1
fi
[ -z "$(ls -A "$XDG_STATE_HOME/meshfair/recovery" 2>/dev/null)" ] ||
    { echo "FAIL: recovery files left after a clean exit"; exit 1; }
echo "ok: $same pinned vertices kept, $moved of $total moved by the run; undo restored the file"
