# SPDX-License-Identifier: MIT
# Shared by the real-window tests (sourced): waiting for the editor's first frame and for
# its exit, each failing the test with the editor's log.

# wait_first_frame PID LOG NAME: until LOG says the window is open (30 s at most).
wait_first_frame() {
    local pid=$1 log=$2 name=$3
    for _ in $(seq 1 300); do
        grep -qs "window open" "$log" && return 0
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    echo "FAIL $name: no first frame"
    cat "$log"
    kill "$pid" 2>/dev/null || true
    exit 1
}

# wait_exit PID LOG NAME HOW: until the editor has quit (10 s at most) with exit code 0.
wait_exit() {
    local pid=$1 log=$2 name=$3 how=$4
    for _ in $(seq 1 100); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    if kill -0 "$pid" 2>/dev/null; then
        echo "FAIL $name: still running 10 s after $how"
        kill "$pid"
        exit 1
    fi
    local rc=0
    wait "$pid" || rc=$?
    if [ "$rc" != 0 ]; then
        echo "FAIL $name: exit code $rc"
        cat "$log"
        exit 1
    fi
}

# fresh_work_dir DIR: an empty work folder, holding the editor's settings and recovery files
# too (none of the user's), and the environment of a window test.
fresh_work_dir() {
    rm -rf "$1"
    mkdir -p "$1"
    export GALLIUM_DRIVER=llvmpipe
    export XDG_CONFIG_HOME="$1/config" XDG_STATE_HOME="$1/state"
    export ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0"
}

# The editor driven as a person drives it (xdotool), with its --trace on stdout in $log and
# its --widget-map in $map. start_editor MESHFAIR MESH LOG MAP [ARGS...] sets $pid and $win.
start_editor() {
    local meshfair=$1 mesh=$2
    log=$3 map=$4
    shift 4
    rm -f "$map"
    "$meshfair" "$mesh" --size 1000x700 --trace --widget-map "$map" "$@" >"$log" 2>&1 &
    pid=$!
    wait_first_frame "$pid" "$log" "$name"
    win=$(xdotool search --sync --name "MeshFair - $(basename "$mesh")" | head -1)
    xdotool windowfocus --sync "$win"
    for _ in $(seq 1 100); do [ -s "$map" ] && break; sleep 0.05; done
}

fail() {
    {
        echo "FAIL $name: $*"
        echo "--- editor log:"
        tail -40 "$log"
    } >&2
    kill "$pid" 2>/dev/null || true
    exit 1
}

alive() { kill -0 "$pid" 2>/dev/null || fail "the editor died ($*)"; }

# wait_line PATTERN [N]: until the log has N (default 1) lines matching PATTERN (10 s).
wait_line() {
    local pattern=$1 n=${2:-1}
    for _ in $(seq 1 400); do
        [ "$(grep -c -- "$pattern" "$log")" -ge "$n" ] && return 0
        alive "waiting for '$pattern'"
        sleep 0.05
    done
    fail "no '$pattern' in the trace ($n wanted)"
}

# count_lines PATTERN: how many lines of the log match.
count_lines() { grep -c -- "$1" "$log" || true; }

# The editor's input counters from the widget map's '#input' line: the key, button and
# wheel events it has handled, 1 while a key or button is down, 1 while events wait.
input_count() { awk -F'\t' '$1 == "#input" { print $2 }' "$map"; }

# wait_input N0 MIN: until the editor has handled MIN more events than N0, with no key or
# button down and none waiting (10 s), or has quit: the input sent is taken, however slow
# the frames. A release follows its press, so no key is down only once the last release
# is handled.
wait_input() {
    local n0=$1 min=$2 routed held queued
    for _ in $(seq 1 500); do
        read -r routed held queued < <(awk -F'\t' '$1 == "#input" { print $2, $3, $4 }' "$map")
        if [ -n "${routed:-}" ] && [ "$routed" -ge $((n0 + min)) ] && [ "$held" = 0 ] &&
            [ "$queued" = 0 ]; then
            return 0
        fi
        # Gone: the input quit it (Ctrl+Q, a quit button); the caller's wait_exit or next
        # step judges whether it should have.
        kill -0 "$pid" 2>/dev/null || return 0
        sleep 0.02
    done
    fail "the editor did not take its input in 10 s (${routed:-?} of $((n0 + min)) events)"
}

# A key chord to the focused window (through XTEST, as a keyboard gives it), until the
# editor has taken it (a press and a release at least).
key() {
    local n0
    n0=$(input_count)
    xdotool key --clearmodifiers "$@"
    wait_input "$n0" 2
}

# The centre of a widget of the interface, from the widget map (waits until it is shown;
# a widget scrolled out of the side panel is scrolled to with the wheel, as a person does).
widget_at() {
    local label=$1 at="" wheel frame
    for attempt in $(seq 1 42); do
        at=$(widget_centre "$label")
        [ -n "$at" ] && break
        # Not in two frames drawn since: scrolled out of the panel, scrolled to with the
        # wheel (down, then up), a frame waited for after each turn.
        frame=$(frame_number)
        if [ "$attempt" -gt 2 ]; then
            wheel=5
            [ "$attempt" -gt 22 ] && wheel=4
            xdotool mousemove --window "$win" 830 400 click "$wheel"
        fi
        wait_frame_after "$frame"
    done
    [ -n "$at" ] || fail "no widget '$label' on screen"
    # Drawn but below or above the side panel's visible part (the panel is longer than the
    # window): scrolled into view, as a hand scrolls it.
    for _ in $(seq 1 30); do
        local x=${at%% *} y=${at#* }
        [ "$x" -gt 660 ] || break # the side panel only
        if [ "$y" -gt 640 ]; then
            wheel=5
        elif [ "$y" -lt 40 ]; then
            wheel=4
        else
            break
        fi
        xdotool mousemove --window "$win" 830 400 click "$wheel"
        # The frame that scrolls rewrites the map; a slow frame must not leave the old place.
        local before=$at
        for _ in $(seq 1 40); do
            sleep 0.05
            at=$(widget_centre "$label")
            [ "$at" != "$before" ] && break
        done
    done
    # Settled: the hand moves over it, and the frames drawn after two such moves show it
    # where it was (a layout that moves - a widget shown above it, the panel scrolled - has
    # settled before the hand presses; a slow frame is waited for, not guessed at).
    local again settled=0 nudge=0
    for _ in $(seq 1 20); do
        local x=${at%% *} y=${at#* } frame
        frame=$(frame_number)
        xdotool mousemove --window "$win" $((x + nudge)) "$y"
        nudge=$((1 - nudge)) # a move the window sees each time
        wait_frame_after "$frame"
        again=$(widget_centre "$label")
        if [ -n "$again" ] && [ "$again" = "$at" ]; then
            settled=$((settled + 1))
            [ "$settled" -ge 2 ] && break
        else
            settled=0
            at=$again
        fi
    done
    [ -n "$at" ] || fail "no widget '$label' on screen"
    echo "$at"
}

# The number of the frame that last wrote the widget map.
frame_number() { awk -F'\t' '$1 == "#frame" { print $2 }' "$map"; }

# wait_frame_after N: until a frame after frame N has been drawn (10 s).
wait_frame_after() {
    for _ in $(seq 1 200); do
        [ "$(frame_number)" -gt "$1" ] 2>/dev/null && return 0
        alive "waiting for a frame"
        sleep 0.05
    done
    fail "no frame drawn in 10 s after frame $1"
}

widget_centre() {
    awk -F'\t' -v n="$1" '$1 == n { print int(($2 + $4) / 2), int(($3 + $5) / 2) }' "$map"
}

click_at() {
    local n0
    xdotool mousemove --window "$win" "$1" "$2"
    sleep 0.1
    n0=$(input_count)
    xdotool click 1
    wait_input "$n0" 2
}

click_widget() {
    local at
    at=$(widget_at "$1")
    # shellcheck disable=SC2086
    click_at $at
}

# drag X0 Y0 X1 Y1 [STEPS]: a left drag in the window, as a hand moves.
drag() {
    local x0=$1 y0=$2 x1=$3 y1=$4 steps=${5:-6}
    xdotool mousemove --window "$win" "$x0" "$y0"
    sleep 0.1
    xdotool mousedown 1
    sleep 0.1
    for k in $(seq 1 "$steps"); do
        xdotool mousemove --window "$win" $((x0 + (x1 - x0) * k / steps)) $((y0 + (y1 - y0) * k / steps))
        sleep 0.04
    done
    # Held a moment at the end, as a hand does: a slow frame sees the button still down.
    sleep 0.15
    local n0
    n0=$(input_count)
    xdotool mouseup 1
    wait_input "$n0" 1
}

# wait_dialog: until a file dialog shows with its name field taking the keys.
wait_dialog() {
    widget_at "dialog/name#active" >/dev/null
}

# type_text TEXT: typed fast, as a person in a hurry types.
type_text() {
    local n0
    n0=$(input_count)
    xdotool type --delay 8 "$1"
    wait_input "$n0" $((2 * ${#1})) # a press and a release per character at least
}

# export_recipe NAME [N]: File -> Export recipe... through the menu and its dialog, the
# name typed, until the trace has N (default 1) exports done.
export_recipe() {
    click_widget "File"
    click_widget "File/Export recipe..."
    wait_dialog
    key ctrl+a
    type_text "$1"
    key Return
    wait_line "command export recipe: ok" "${2:-1}"
}
