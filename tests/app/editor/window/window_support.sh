# SPDX-License-Identifier: MIT
# Shared by the real-window tests (sourced): waiting for the editor's first frame and for
# its exit, each failing the test with the editor's log; driving it with xdotool and
# waiting, after each step, for the state that shows the editor has taken it (its widget
# map, its trace), never for a guessed time. Every wait polls briefly and fails only after
# a generous time, so that a loaded machine makes the tests slower, not flaky.

# How long a wait for the editor's input, frames or trace may take (s), and the pause
# between two looks.
wait_limit=${MESHFAIR_WINDOW_WAIT:-60}
poll=0.01

# nap [SECONDS]: the pause between two looks ($poll by default), a read that times out on
# a pipe nobody writes to (no process started: looking a hundred times a second costs no
# CPU the editor needs).
exec {nap_fd}<> <(:)
nap() { read -rt "${1:-$poll}" -u "$nap_fd" _ || true; }

# wait_first_frame PID LOG NAME: until LOG says the window is open (60 s at most).
wait_first_frame() {
    local pid=$1 log=$2 name=$3 end=$((SECONDS + wait_limit))
    while [ $SECONDS -lt $end ]; do
        grep -qs "window open" "$log" && return 0
        kill -0 "$pid" 2>/dev/null || break
        nap
    done
    echo "FAIL $name: no first frame"
    cat "$log"
    kill "$pid" 2>/dev/null || true
    exit 1
}

# wait_exit PID LOG NAME HOW: until the editor has quit (60 s at most) with exit code 0.
wait_exit() {
    local pid=$1 log=$2 name=$3 how=$4 end=$((SECONDS + wait_limit))
    while [ $SECONDS -lt $end ]; do
        kill -0 "$pid" 2>/dev/null || break
        nap
    done
    if kill -0 "$pid" 2>/dev/null; then
        echo "FAIL $name: still running $wait_limit s after $how"
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
    local meshfair=$1 mesh=$2 end
    log=$3 map=$4
    shift 4
    rm -f "$map"
    # 1000 x 700 for the view and the panels, and 224 more for the energy plot's strip under
    # the view (kEnergyPanelHeight): the view is 1000 x 654 from (0, 19), where the tests'
    # points on the mesh were taken.
    "$meshfair" "$mesh" --size 1000x924 --trace --widget-map "$map" "$@" >"$log" 2>&1 &
    pid=$!
    wait_first_frame "$pid" "$log" "$name"
    win=$(xdotool search --sync --name "MeshFair - $(basename "$mesh")" | awk 'NR == 1')
    xdotool windowfocus --sync "$win"
    end=$((SECONDS + wait_limit))
    until [ -s "$map" ]; do
        [ $SECONDS -lt $end ] || fail "no widget map written"
        alive "waiting for the widget map"
        nap
    done
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

# wait_line PATTERN [N]: until the log has N (default 1) lines matching PATTERN (a look
# every 0.03 s: each is a grep).
wait_line() {
    local pattern=$1 n=${2:-1} end=$((SECONDS + wait_limit))
    while [ $SECONDS -lt $end ]; do
        [ "$(grep -c -- "$pattern" "$log")" -ge "$n" ] && return 0
        alive "waiting for '$pattern'"
        nap 0.03
    done
    fail "no '$pattern' in the trace ($n wanted)"
}

# count_lines PATTERN: how many lines of the log match.
count_lines() { grep -c -- "$1" "$log" || true; }

# map_state: the widget map's first two lines, read by the shell itself (the map is
# replaced whole by a rename, never seen half written), into
#   m_frame: '#frame N', the last frame drawn, on the screen (the map is written after it);
#   m_routed m_held m_queued m_moves m_x m_y: '#input EVENTS HELD QUEUED MOVES X Y', the
#     key, button and wheel events the editor has handled, 1 while a key or button is down,
#     1 while events wait, the cursor moves it has handled and where the last one put the
#     cursor (window pixels).
map_state() {
    local first="" second=""
    { IFS= read -r first && IFS= read -r second; } 2>/dev/null <"$map" || true
    IFS=$'\t' read -r _ m_frame <<<"$first"
    # shellcheck disable=SC2034 # m_moves: for a driver that counts the moves
    IFS=$'\t' read -r _ m_routed m_held m_queued m_moves m_x m_y <<<"$second"
}

# The editor's count of key, button and wheel events handled.
input_count() {
    map_state
    echo "$m_routed"
}

# wait_input N0 MIN: until the editor has handled MIN more events than N0, with no key or
# button down and none waiting, or has quit: the input sent is taken, however slow the
# frames. A release follows its press, so no key is down only once the last release is
# handled.
wait_input() {
    local n0=$1 min=$2 end=$((SECONDS + wait_limit))
    while [ $SECONDS -lt $end ]; do
        map_state
        if [ -n "${m_routed:-}" ] && [ "$m_routed" -ge $((n0 + min)) ] && [ "$m_held" = 0 ] &&
            [ "$m_queued" = 0 ]; then
            return 0
        fi
        # Gone: the input quit it (Ctrl+Q, a quit button); the caller's wait_exit or next
        # step judges whether it should have.
        kill -0 "$pid" 2>/dev/null || return 0
        nap
    done
    fail "the editor did not take its input in $wait_limit s (${m_routed:-?} of $((n0 + min)) events)"
}

# wait_pressed N0: until the editor has handled a press after N0 events and holds it, with
# no event waiting.
wait_pressed() {
    local n0=$1 end=$((SECONDS + wait_limit))
    while [ $SECONDS -lt $end ]; do
        map_state
        if [ -n "${m_routed:-}" ] && [ "$m_routed" -ge $((n0 + 1)) ] && [ "$m_held" = 1 ] &&
            [ "$m_queued" = 0 ]; then
            return 0
        fi
        alive "waiting for a press to be taken"
        nap
    done
    fail "the editor did not take the press in $wait_limit s (${m_routed:-?} of $((n0 + 1)) events)"
}

# move_to X Y: the pointer moved to X Y of the window, until a frame on the screen has
# handled the move (the editor's cursor there, no event waiting). A press sent then lands
# there: the window reads a press's place from the pointer when its frame takes the press,
# not from the event, so a press sent while an earlier move waits could land further on.
# The pointer already seen there: nothing to wait for (X sends no move that moves nothing).
move_to() {
    local x=$1 y=$2 end=$((SECONDS + wait_limit)) tries=0
    xdotool mousemove --window "$win" "$x" "$y"
    while [ $SECONDS -lt $end ]; do
        map_state
        [ "${m_x:-}" = "$x" ] && [ "${m_y:-}" = "$y" ] && [ "$m_queued" = 0 ] && return 0
        alive "waiting for the pointer at $x $y"
        # Every 50 looks (half a second or more): the move sent again by way of the next
        # pixel, should X have sent none (the pointer there before the editor saw it, at
        # its start); harmless otherwise, the pointer ends where it was sent.
        if [ $((++tries % 50)) = 0 ]; then
            xdotool mousemove --window "$win" $((x + 1)) "$y" mousemove --window "$win" "$x" "$y"
        fi
        nap
    done
    fail "the editor did not see the pointer at $x $y in $wait_limit s (at ${m_x:-?} ${m_y:-?})"
}

# hover X Y: the pointer moved to X Y, or to the next pixel if the editor has it at X Y
# already: a frame drawn after a move the editor has handled, on the screen when it returns.
hover() {
    local x=$1 y=$2
    map_state
    [ "${m_x:-}" = "$x" ] && [ "${m_y:-}" = "$y" ] && x=$((x + 1))
    move_to "$x" "$y"
}

# next_frame: a frame drawn after now, asked for as a hand asks, with the pointer moved by
# a pixel, to and fro (the editor draws on input, else twice a second); on the screen when
# it returns.
next_frame() {
    map_state
    local x=${m_x:-0} y=${m_y:-0}
    if [ $((x % 2)) = 1 ]; then x=$((x - 1)); else x=$((x + 1)); fi
    move_to "$x" "$y"
}

# wheel_panel N: the wheel turned once over the side panel (N: 5 down, 4 up), until the
# editor has handled the turn (its frame, scrolled, on the screen).
wheel_panel() {
    local n0
    move_to 830 400
    n0=$(input_count)
    xdotool click --delay 0 "$1" # no pause after it (xdotool waits 0.1 s by default)
    wait_input "$n0" 1
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
    local label=$1 at=""
    for attempt in $(seq 1 42); do
        at=$(widget_centre "$label")
        [ -n "$at" ] && break
        # Not in two frames drawn since: scrolled out of the panel, scrolled to with the
        # wheel (down, then up), the frame that takes each turn waited for.
        if [ "$attempt" -le 2 ]; then
            next_frame
        elif [ "$attempt" -le 22 ]; then
            wheel_panel 5
        else
            wheel_panel 4
        fi
    done
    [ -n "$at" ] || fail "no widget '$label' on screen"
    # Drawn but below or above the side panel's visible part (the panel is longer than the
    # window): scrolled into view, as a hand scrolls it; the map read after the frame that
    # took the turn.
    for _ in $(seq 1 30); do
        local x=${at%% *} y=${at#* } wheel again
        [ "$x" -gt 660 ] || break # the side panel only
        if [ "$y" -gt 860 ]; then
            wheel=5
        elif [ "$y" -lt 40 ]; then
            wheel=4
        else
            break
        fi
        wheel_panel "$wheel"
        again=$(widget_centre "$label")
        [ -n "$again" ] && at=$again
    done
    # Settled: the hand moves over it, and the frames drawn after two such moves, each
    # handled by the editor, show it where it was (a layout that moves - a widget shown
    # above it, the panel scrolled, a menu placed where it opened - has settled before the
    # hand presses; a slow frame is waited for, not guessed at).
    local settled=0
    for _ in $(seq 1 20); do
        local x=${at%% *} y=${at#* } again
        hover "$x" "$y"
        again=$(widget_centre "$label")
        if [ -n "$again" ] && [ "$again" = "$at" ]; then
            settled=$((settled + 1))
            [ "$settled" -ge 2 ] && break
        else
            settled=0
            [ -n "$again" ] && at=$again
        fi
    done
    [ -n "$at" ] || fail "no widget '$label' on screen"
    echo "$at"
}

# The number of the frame that last wrote the widget map (the last one on the screen).
frame_number() { awk -F'\t' '$1 == "#frame" { print $2 }' "$map"; }

# wait_frame_after N: until a frame after frame N is on the screen.
wait_frame_after() {
    local end=$((SECONDS + wait_limit))
    while [ $SECONDS -lt $end ]; do
        map_state
        [ "${m_frame:-0}" -gt "$1" ] 2>/dev/null && return 0
        alive "waiting for a frame"
        nap
    done
    fail "no frame drawn in $wait_limit s after frame $1"
}

widget_centre() {
    awk -F'\t' -v n="$1" '$1 == n { print int(($2 + $4) / 2), int(($3 + $5) / 2) }' "$map"
}

# click_at X Y: a left click there, once the editor has seen the pointer there.
click_at() {
    local n0
    move_to "$1" "$2"
    n0=$(input_count)
    xdotool click --delay 0 1 # no pause after it (xdotool waits 0.1 s by default)
    wait_input "$n0" 2
}

click_widget() {
    local at
    at=$(widget_at "$1")
    # shellcheck disable=SC2086
    click_at $at
}

# drag X0 Y0 X1 Y1 [STEPS]: a left drag in the window, as a hand moves: pressed where the
# editor has seen the pointer, each step of the way seen with the button down (the last one
# too: a slow frame sees the button still down at the end), then let go.
drag() {
    local x0=$1 y0=$2 x1=$3 y1=$4 steps=${5:-6} n0
    move_to "$x0" "$y0"
    n0=$(input_count)
    xdotool mousedown 1
    wait_pressed "$n0"
    for k in $(seq 1 "$steps"); do
        move_to $((x0 + (x1 - x0) * k / steps)) $((y0 + (y1 - y0) * k / steps))
    done
    n0=$(input_count)
    xdotool mouseup 1
    wait_input "$n0" 1
}

# wait_dialog: until a file dialog shows with its name field taking the keys (a frame drawn
# for each look), settled.
wait_dialog() {
    local end=$((SECONDS + wait_limit))
    until [ -n "$(widget_centre "dialog/name#active")" ]; do
        [ $SECONDS -lt $end ] || fail "no file dialog with its name field active"
        next_frame
    done
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
