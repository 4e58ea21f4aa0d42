#!/usr/bin/env bash
# `fluence farm` end to end on a throw-away one-node Slurm cluster (ctest: farm_slurm).
#   slurm_farm_test.sh FLUENCE_BINARY SOURCE_DIR
# Starts munged, slurmctld and slurmd from a temporary folder (private munge key and socket,
# random free ports, no file under /etc touched) inside a private PID namespace (unshare), so
# nothing outlives the test even if it crashes. Then: a 2x2 tile render of the Cornell box as a
# Slurm job array with task 2 failing on its first attempt (FLUENCE_FARM_FAIL_TASK), waits on
# `fluence farm status` (which polls squeue), checks the failure is reported and no image was
# merged, resumes, waits again, and checks the merged EXR against a single-process render, bit
# for bit. Daemons are stopped by PID. Without Slurm, munge, unshare or root it prints SKIPPED
# and exits 77 (ctest's SKIP_RETURN_CODE for this test).
# Recipe: shared/notes/slurm-one-node.md (Slurm 22.05 on Debian 12, no systemd).
set -euo pipefail
FLUENCE=$1
SOURCE_DIR=$2
SCENE="$SOURCE_DIR/usd_samples/cornell_box.usda"
RENDER_ARGS=(-r 21 15 --spp 4)

skip() {
  echo "**************************************************************" >&2
  echo "*** SKIPPED: fluence farm Slurm test: $*" >&2
  echo "**************************************************************" >&2
  exit 77
}
for tool in sbatch squeue sinfo scancel slurmctld slurmd munged mungekey unshare; do
  command -v "$tool" >/dev/null || skip "'$tool' is not installed (apt-get install slurm-wlm munge; scripts/install_dependencies.sh)"
done
[ "$(id -u)" = 0 ] || skip "needs root (munged and slurmd run as root in a private PID namespace)"
if [ -z "${FLUENCE_FARM_TEST_NAMESPACE:-}" ]; then
  unshare --pid --fork --mount-proc true 2>/dev/null || skip "unshare --pid is not permitted here"
  FLUENCE_FARM_TEST_NAMESPACE=1 exec unshare --pid --fork --mount-proc bash "$0" "$@"
fi

fail() { echo "FAILED: $*" >&2; exit 1; }
D=$(mktemp -d -t fluence-slurm-farm.XXXXXX)
chmod 755 "$D"  # munged wants o+x on every folder above its socket
mkdir -p "$D"/{munge,state,spool,work}
PIDS=()
stop_cluster() {  # reverse order: slurmd, slurmctld, munged
  local i p
  for (( i=${#PIDS[@]}-1; i>=0; i-- )); do
    p=${PIDS[i]}
    kill "$p" 2>/dev/null || continue
    for _ in $(seq 100); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$p" 2>/dev/null && kill -9 "$p"
  done
  PIDS=()
}
finish() {
  local code=$?
  stop_cluster
  if [ "$code" != 0 ]; then
    echo "--- logs ($D) ---" >&2
    tail -n 20 "$D"/*.log "$D"/work/farm/logs/*.log 2>/dev/null >&2 || true
  fi
  rm -rf "$D"
}
trap finish EXIT

free_port() {  # a port nothing listens on, from 20000-39999
  local p
  while :; do
    p=$((20000 + RANDOM % 20000))
    (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return; }
  done
}
CTLD_PORT=$(free_port)
SLURMD_PORT=$(free_port)
[ "$CTLD_PORT" != "$SLURMD_PORT" ] || SLURMD_PORT=$((CTLD_PORT + 1))

# 1. munge with a private key and socket.
mungekey --create --keyfile="$D/munge/munge.key"
munged -F --socket="$D/munge/sock" --key-file="$D/munge/munge.key" --pid-file="$D/munge/pid" \
  --log-file="$D/munge.log" --seed-file="$D/munge/seed" 2>>"$D/munge.log" &
PIDS+=($!)
for _ in $(seq 200); do [ -S "$D/munge/sock" ] && break; sleep 0.05; done
[ -S "$D/munge/sock" ] || fail "munged did not start"

# 2. slurm.conf; clients (sbatch, squeue, and so fluence farm) find it through SLURM_CONF.
cat > "$D/slurm.conf" <<CONF
ClusterName=fluencefarmtest
SlurmctldHost=localhost
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$D/munge/sock
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/slurmctld.log
SlurmdLogFile=$D/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0
MpiDefault=none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MailProg=/usr/bin/true
ReturnToService=2
MinJobAge=600
# Small, so that the four tiles' task array (indices 0 to 3) is split: tasks 0-2 in one array, task
# 3 in a second one shifted by 3 (apps/farm_slurm_backend.h).
MaxArraySize=3
NodeName=localhost CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$D/slurm.conf"

# 3. The daemons in the foreground (-D), backgrounded here so the test owns their PIDs.
slurmctld -D -c -f "$SLURM_CONF" >"$D/slurmctld.out.log" 2>&1 &
PIDS+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" >"$D/slurmd.out.log" 2>&1 &
PIDS+=($!)
node_idle() { [ "$(sinfo -h -n localhost -o %T 2>/dev/null)" = idle ]; }
for _ in $(seq 300); do node_idle && break; sleep 0.1; done
node_idle || fail "the Slurm node did not come up"
echo "cluster up after ${SECONDS}s (ports $CTLD_PORT, $SLURMD_PORT)"

# Polls `fluence farm status` (which asks squeue) until the work is neither queued nor running;
# prints the last report and returns its exit code.
wait_farm() {
  local code
  for _ in $(seq 600); do
    code=0
    "$FLUENCE" farm status "$D/work/farm" >"$D/status.txt" 2>&1 || code=$?
    [ "$code" = 8 ] || { cat "$D/status.txt"; return "$code"; }
    sleep 0.2
  done
  cat "$D/status.txt"
  fail "the farm was still running after 120 s"
}

# Every file under a final name is whole: no temporary file is left, every EXR reads.
check_no_partial_files() {
  local leftovers
  leftovers=$(find "$D/work/farm" -name '.*.tmp-*')
  [ -z "$leftovers" ] || fail "temporary files left: $leftovers"
  for exr in $(find "$D/work/farm" -name '*.exr'); do
    oiiotool "$exr" --printstats >/dev/null 2>&1 || fail "$exr does not read as a whole EXR"
  done
}

cd "$D/work"
"$FLUENCE" render "$SCENE" "${RENDER_ARGS[@]}" -o "$D/work/whole.exr" >/dev/null || fail "the single-process render failed"
t=$SECONDS

# 4. Submit with task 2 failing once: the merge job must be dropped, status must say so.
FLUENCE_FARM_FAIL_TASK=2 "$FLUENCE" farm submit "$SCENE" --tiles 2 2 --backend slurm --output-dir "$D/work/farm" -j 1 \
  -- "${RENDER_ARGS[@]}" || fail "farm submit failed"
code=0
wait_farm || code=$?
[ "$code" = 9 ] || fail "farm status after the failed task: exit $code, expected 9 (incomplete)"
grep -Eq '^  task 2 .* failed +exit 1 on attempt 1' "$D/status.txt" || fail "farm status does not report task 2 as failed"
[ "$(grep -c ' done  ' "$D/status.txt")" = 3 ] || fail "farm status does not report tasks 0, 1 and 3 as done"
[ ! -e "$D/work/farm/cornell_box.exr" ] || fail "an image was merged although a tile was missing"
grep -q 'failing on purpose' "$D/work/farm/logs/task_2.log" || fail "task 2's log does not hold its failure"
grep -q 'rendered' "$D/work/farm/logs/task_3.log" || fail "task 3 (in the second, shifted array) has no log of its own"
grep -q ':[0-9]*+3"' "$D/work/farm/farm.json" || fail "the plan does not record the task array as two Slurm arrays"
command -v oiiotool >/dev/null || fail "oiiotool (openimageio-tools) is needed to check the images"
check_no_partial_files
echo "failure seen after $((SECONDS - t))s"

# 5. Resume: only task 2 and the merge are submitted; all done afterwards.
FLUENCE_FARM_FAIL_TASK=2 "$FLUENCE" farm resume "$D/work/farm" | tee "$D/resume.txt" || fail "farm resume failed"
grep -q 'resubmitting 1 task' "$D/resume.txt" || fail "farm resume did not resubmit exactly one task"
code=0
wait_farm || code=$?
[ "$code" = 0 ] || fail "farm status after resume: exit $code, expected 0 (done)"
check_no_partial_files
oiiotool --fail 0 --warn 0 --diff "$D/work/whole.exr" "$D/work/farm/cornell_box.exr" \
  || fail "the merged image differs from the single-process render"
grep -q 'merged 4 tiles' "$D/work/farm/logs/merge.log" || fail "the merge job's log does not say it merged"
echo "farm test took $((SECONDS - t))s"

# 6. Stop once the node is idle again (a step daemon still reporting would outlive slurmd).
for _ in $(seq 100); do node_idle && break; sleep 0.1; done
stop_cluster
echo "PASSED: fluence farm on Slurm; ${SECONDS}s in all"
