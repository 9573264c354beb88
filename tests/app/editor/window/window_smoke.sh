#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The editor in real windows under Xvfb, on meshes of every format and kind (OBJ, OFF,
# binary PLY and STL, quads and a pentagon, an open grid, a non-manifold fan): each
# opens, draws a first frame that a screenshot taken by the X server shows (not blank),
# and quits with exit code 0, every other one on Ctrl+Q typed as real key events and the
# rest on a close request from outside (what a window manager's close button sends).
#   window_smoke.sh MESHFAIR MESHFAIR_CLI BUNNY.obj WORK_DIR SEND_CLOSE
set -euo pipefail
if [ -z "${MESHFAIR_IN_XVFB:-}" ]; then
    export MESHFAIR_IN_XVFB=1
    # A display and an X authority of its own (from :110 up), so that the window tests can
    # run at the same time.
    exec xvfb-run -a -n 110 -f "${4%/}.Xauthority" -s "-screen 0 1280x1024x24" "$0" "$@"
fi
meshfair=$1 cli=$2 bunny=$3 work=$4 send_close=$5
. "$(dirname "$0")/window_support.sh"
rm -rf "$work"
mkdir -p "$work"
export GALLIUM_DRIVER=llvmpipe
# The recent-files list goes into the work folder, not the user's configuration.
export XDG_CONFIG_HOME="$work/config"
# Autosaves too: a recovery file left by an earlier run would be offered, in a dialog that
# takes the keys.
export XDG_STATE_HOME="$work/state"
# Under AddressSanitizer: the GLX driver is unloaded before leaks are reported, so its
# allocations cannot be told apart (the OSMesa tests keep leak detection).
export ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0"

# The meshes: the bunny in four formats, and small ones of each kind.
"$cli" convert "$bunny" -o "$work/bunny.off" >/dev/null
"$cli" convert "$bunny" -o "$work/bunny.ply" --encoding binary >/dev/null
"$cli" convert "$bunny" -o "$work/bunny.stl" --encoding binary >/dev/null
cat >"$work/polygons.obj" <<'MESH'
v 0 0 0
v 1 0 0
v 2 0 0.3
v 0 1 0
v 1 1 0.2
v 2 1 0
v 1.5 1.8 0.1
f 1 2 5 4
f 2 3 6 5
f 4 5 7
f 5 6 7
MESH
cat >"$work/open_grid.off" <<'MESH'
OFF
9 4 0
0 0 0
1 0 0.2
2 0 0
0 1 0.2
1 1 0.5
2 1 0.2
0 2 0
1 2 0.2
2 2 0
4 0 1 4 3
4 1 2 5 4
4 3 4 7 6
4 4 5 8 7
MESH
cat >"$work/nonmanifold_fan.ply" <<'MESH'
ply
format ascii 1.0
element vertex 5
property float x
property float y
property float z
element face 3
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0.5 1 0
0.5 -1 0
0.5 0 1
3 0 1 2
3 1 0 3
3 0 1 4
MESH

count=0
for mesh in "$bunny" "$work/bunny.off" "$work/bunny.ply" "$work/bunny.stl" \
    "$work/polygons.obj" "$work/open_grid.off" "$work/nonmanifold_fan.ply"; do
    name=$(basename "$mesh")
    log="$work/$name.log"
    "$meshfair" "$mesh" --size 800x600 >"$log" 2>&1 &
    pid=$!
    wait_first_frame "$pid" "$log" "$name"
    shot="$work/$name.png"
    # Not blank: the grey levels of the screen vary (a blank or single-colour screen has
    # a standard deviation of 0). The editor says the window is open once its first frame
    # is swapped; should the X server not show it yet, the screen is looked at again until
    # it does ($wait_limit s).
    looks=0 end=$((SECONDS + wait_limit))
    while :; do
        deviation=$(xwd -root -silent |
            convert xwd:- -write "$shot" -colorspace gray -format '%[fx:standard_deviation]' info:)
        looks=$((looks + 1))
        awk -v s="$deviation" 'BEGIN { exit !(s > 0.02) }' && break
        if [ $SECONDS -ge $end ]; then
            echo "FAIL $name: the screenshot is blank (grey standard deviation $deviation, $looks looks)"
            exit 1
        fi
        nap
    done
    window=$(xdotool search --sync --name "MeshFair - $name" | awk 'NR == 1')
    if [ $((count++ % 2)) = 0 ]; then
        how="Ctrl+Q"
        xdotool windowfocus --sync "$window"
        xdotool key --clearmodifiers ctrl+q
    else
        how="a close request"
        "$send_close" "$window"
    fi
    wait_exit "$pid" "$log" "$name" "$how"
    if ! grep -qx "$(cd "$(dirname "$mesh")" && pwd)/$name" "$XDG_CONFIG_HOME/meshfair/recent.txt"; then
        echo "FAIL $name: not in the recent files"
        exit 1
    fi
    echo "ok $name: $(head -1 "$log"), screenshot deviation $deviation ($looks looks), exit 0 on $how"
done
