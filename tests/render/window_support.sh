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
