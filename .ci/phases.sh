# shellcheck shell=bash
# SPDX-License-Identifier: MIT
# Shared by .ci/setup.sh (sourced from the project's root): where the time goes, and jobs
# started beside others at the lowest priority.

# phase NAME: the time since the last phase (the first from the script's start), printed
# at the end by print_phases.
times=()
phase_start=0
phase() {
    times+=("$(printf '%-36s %5d s' "$1" $((SECONDS - phase_start)))")
    phase_start=$SECONDS
}
print_phases() {
    echo "Time by phase ($SECONDS s in all):"
    printf '  %s\n' "${times[@]}"
}

# A job started beside others runs at the lowest priority, in a process group of its own
# (stopped if the script stops), with its output in a log printed when it ends: it takes
# only the core time the others leave idle (the fuzz replays, the last fuzz target alone).
logs=build/ci-logs
mkdir -p "$logs"
declare -A beside=()
start_beside() { # start_beside NAME COMMAND...
    local name=$1
    shift
    # A session of its own is also a scheduling group of its own where the kernel groups
    # sessions (autogroup), which would share the cores equally with the tests whatever
    # its nice value: the group is niced too, from inside the session.
    # shellcheck disable=SC2016 # expanded by the inner shell
    setsid bash -c 'echo 19 2>/dev/null >/proc/self/autogroup || true; exec nice -n 19 "$@"' \
        "$name" "$@" >"$logs/$name.log" 2>&1 &
    beside[$name]=$!
}
finish_beside() { # finish_beside NAME: waits for it, prints its log, returns its status
    local name=$1 status=0
    wait "${beside[$name]}" || status=$?
    unset "beside[$name]"
    cat "$logs/$name.log"
    [ "$status" = 0 ] || echo "$name failed (exit $status)" >&2
    return "$status"
}
stop_beside() {
    local pid
    for pid in "${beside[@]}"; do
        kill -- "-$pid" 2>/dev/null || true
    done
}
trap stop_beside EXIT
