#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# docs/batch.md's Slurm job array on a real single-node Slurm cluster, started and stopped
# here: munged, slurmctld and slurmd from Debian's packages (munge, slurm-wlm), each with
# its own key, configuration, ports, state and logs in a temporary folder. The doc's two
# code blocks (the submission and smooth.sbatch) are taken from docs/batch.md as they are
# and run over 7 PLY scans in 3 tasks, one of the scans malformed. Checks:
#  - every output is byte-identical to what `meshfair-cli batch` writes for the same files;
#  - the malformed scan is reported (status "rejected", its file and line) in the report of
#    the task that had it, and that task alone exits non-zero (Slurm's ExitCode);
#  - the daemons are gone afterwards.
#   slurm_job_array.sh MESHFAIR_CLI DOCS_BATCH_MD ASSETS_DIR WORK_DIR
set -euo pipefail
cli=$(realpath "$1") doc=$(realpath "$2") assets=$(realpath "$3") work=$4
fail() {
    echo "FAIL slurm: $*" >&2
    for log in "$work"/run/*.log; do
        [ -f "$log" ] && { echo "--- $log" >&2; tail -20 "$log" >&2; }
    done
    exit 1
}
for tool in munged slurmctld slurmd sbatch squeue scontrol; do
    command -v "$tool" >/dev/null || fail "$tool not found (apt-get install munge slurm-wlm)"
done
rm -rf "$work"
mkdir -p "$work/run" "$work/job"
chmod 700 "$work/run"
run=$(realpath "$work/run") job=$(realpath "$work/job")

# The daemons, stopped however the test ends.
pids=()
stop() {
    local p
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    for p in "${pids[@]}"; do
        for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$p" 2>/dev/null || true
    done
}
trap stop EXIT

# --- munge: a key of its own, a socket in the run folder.
dd if=/dev/urandom of="$run/munge.key" bs=1024 count=1 status=none
chmod 400 "$run/munge.key"
munged --foreground --force --key-file="$run/munge.key" --socket="$run/munge.socket" \
    --pid-file="$run/munged.pid" --log-file="$run/munged.log" --seed-file="$run/munged.seed" &
pids+=($!)
for _ in $(seq 100); do [ -S "$run/munge.socket" ] && break; sleep 0.1; done
[ -S "$run/munge.socket" ] || fail "munged did not start"

# --- Slurm: one node with this machine's CPUs, two free ports.
cpus=$(slurmd -C | sed -n 's/.* CPUs=\([0-9]*\).*/\1/p')
port=$(( 20000 + RANDOM % 20000 ))
mkdir -p "$run/state" "$run/spool"
export SLURM_CONF="$run/slurm.conf"
cat >"$SLURM_CONF" <<CONF
ClusterName=meshfair
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$(( port + 1 ))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$run/munge.socket
CredType=cred/munge
StateSaveLocation=$run/state
SlurmdSpoolDir=$run/spool
SlurmctldPidFile=$run/slurmctld.pid
SlurmdPidFile=$run/slurmd.pid
SlurmctldLogFile=$run/slurmctld.log
SlurmdLogFile=$run/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
MinJobAge=3600
NodeName=meshfair-node NodeAddr=127.0.0.1 NodeHostname=$(hostname) CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=meshfair-node Default=YES MaxTime=INFINITE State=UP
CONF
# No cgroup is used (processes tracked through /proc, tasks not bound), and slurmd looks
# for none: an empty folder of its own stands for the cgroup mount point, which a chroot or
# a container may not have.
mkdir -p "$run/cgroup"
cat >"$run/cgroup.conf" <<CONF
CgroupPlugin=cgroup/v1
CgroupMountpoint=$run/cgroup
CgroupAutomount=no
CONF
slurmctld -D -i &
pids+=($!)
slurmd -D -N meshfair-node &
pids+=($!)
for _ in $(seq 100); do
    [[ "$(sinfo -h -o %T 2>/dev/null)" == *idle* ]] && break
    sleep 0.2
done
[[ "$(sinfo -h -o %T)" == *idle* ]] || fail "the node did not come up: $(sinfo 2>&1)"

# --- The scans: 7 PLY files (the bunny, noisy copies, a quad cube), one of
# them malformed (a face past the last vertex).
cd "$job"
mkdir scans
cp "$assets/recipes/denoise.json" recipe.json
"$cli" convert "$assets/bunny.obj" -o scans/bunny.ply >/dev/null
for seed in 1 2 3 4; do
    "$cli" noise "$assets/bunny.obj" -o "scans/noisy$seed.ply" --sigma 0.2 --seed "$seed" >/dev/null
done
printf 'ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n' >scans/cube.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n' >scans/broken.ply

# --- docs/batch.md's blocks, as they are: the block after each marker comment.
block() { awk -v marker="<!-- $1 -->" '$0 == marker { found = 1; next }
    found && /^```/ { if (inside) exit; inside = 1; next } inside { print }' "$doc"; }
block slurm-submit >submit.sh
block slurm-script >smooth.sbatch
if [ ! -s submit.sh ] || [ ! -s smooth.sbatch ]; then
    fail "docs/batch.md has no slurm-submit or slurm-script block"
fi
PATH="$(dirname "$cli"):$PATH"
export PATH
export PER_TASK=3 # 7 files, 3 tasks
submitted=$(sh submit.sh) || fail "the submission failed: $submitted"
id=$(echo "$submitted" | sed -n 's/^Submitted batch job \([0-9]*\)$/\1/p')
[ -n "$id" ] || fail "no job id in: $submitted"
for _ in $(seq 600); do
    [ -z "$(squeue -h -j "$id" 2>/dev/null)" ] && break
    sleep 0.5
done
[ -z "$(squeue -h -j "$id")" ] || fail "the array did not finish in 5 minutes: $(squeue -j "$id")"

# --- Each task's exit code, as Slurm has it.
declare -A exit_code
for task in 0 1 2; do
    exit_code[$task]=$(scontrol show job "${id}_$task" | sed -n 's/.* ExitCode=\([0-9:]*\).*/\1/p')
done
# The task that had the malformed scan.
mapfile -t files <files.txt
bad_task=-1
for i in "${!files[@]}"; do
    [ "${files[$i]}" = scans/broken.ply ] && bad_task=$(( i / PER_TASK ))
done
for task in 0 1 2; do
    [ -f "reports/$task.jsonl" ] || fail "task $task wrote no report"
    if [ "$task" = "$bad_task" ]; then
        [ "${exit_code[$task]}" != 0:0 ] || fail "task $task had the malformed scan and exited 0"
        grep -q '"file":"scans/broken.ply".*"status":"rejected"\|"status":"rejected".*"file":"scans/broken.ply"' \
            "reports/$task.jsonl" || fail "task $task's report does not reject scans/broken.ply"
        grep -q 'broken.ply:13:7: face 0 uses vertex index 5' "reports/$task.jsonl" ||
            fail "task $task's report does not name the line: $(cat "reports/$task.jsonl")"
    else
        [ "${exit_code[$task]}" = 0:0 ] || fail "task $task exited ${exit_code[$task]}"
        ! grep -q rejected "reports/$task.jsonl" || fail "task $task rejected a file"
    fi
done
[ "$(cat reports/*.jsonl | wc -l)" = 7 ] || fail "not one report line per scan"

# --- The same bytes as meshfair-cli batch on one machine.
"$cli" batch --recipe recipe.json --out-dir local scans/*.ply >local.jsonl 2>/dev/null && true
for f in scans/*.ply; do
    name=$(basename "$f")
    if [ "$name" = broken.ply ]; then
        [ ! -e "smoothed/$name" ] || fail "the malformed scan has an output"
        continue
    fi
    cmp -s "smoothed/$name" "local/$name" || fail "smoothed/$name differs from meshfair-cli batch's"
done

stop
trap - EXIT
for p in "${pids[@]}"; do ! kill -0 "$p" 2>/dev/null || fail "daemon $p is still running"; done
echo "slurm: 3 tasks, 6 scans smoothed as meshfair-cli batch smooths them, scans/broken.ply rejected by task $bad_task (ExitCode ${exit_code[$bad_task]})"
