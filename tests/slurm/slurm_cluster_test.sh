#!/usr/bin/env bash
# The cluster workflow on a real, single-node Slurm (docs/cluster.md): stands up munged,
# slurmctld and slurmd from the Debian packages (slurmctld slurmd slurm-client munge; Debian 12
# ships Slurm 22.05) with a configuration written here, runs the smoke suite as a job array of
# 4 shards (`holebench slurm submit`), breaks one shard and resubmits it alone, to finish
# only its missing jobs
# (`slurm status`, `slurm resubmit`), merges (`holebench merge --shards`) and checks that the
# merged results equal a single-process run of the suite up to timings: the same jobs in the
# same order with the same statuses, messages, metrics and holes (`holebench compare` must
# also find no change).
#
# Usage: slurm_cluster_test.sh HOLEBENCH WORK_DIR
#   WORK_DIR is emptied; it keeps the daemons' logs and the sharded run for inspection.
#   HOLEBENCH_SMOKE_RESULTS: a results.json of `holebench run --suite smoke --no-snapshots`
#   (scripts/run_tests.sh sets it to build/smoke's); reused as the single-process run when it
#   is newer than HOLEBENCH, otherwise the test runs the suite in one process itself.
# Exit code 77 (CTest's SKIP_RETURN_CODE) with a message when Slurm or munge is not installed
# or we are not root (slurmd must be).
#
# No systemd here (nor needed): every daemon runs in the foreground as our child, in the
# background, with its files in WORK_DIR, and is stopped by its pid on exit. Debian details:
#  - munged is started with its own key, socket, pid, log and seed files (not /run/munge,
#    which does not exist without the package's service), and --force since we are root;
#    Slurm finds the socket through AuthInfo=socket=... in slurm.conf.
#  - No cgroups: proctrack/linuxproc, task/none, jobacct_gather/none, no accounting storage
#    (so no sacct; the test polls squeue and the shards' files).
#  - slurmd logs harmless "mpi/pmix ... can not load PMIx library" errors; MpiDefault=none.
#  - The spool folder must exist before slurmd starts (its domain socket lives there).
set -euo pipefail

skip() {
  echo "SKIPPED: $*" >&2
  exit 77
}

[ $# -eq 2 ] || { echo "usage: $0 HOLEBENCH WORK_DIR" >&2; exit 2; }
holebench=$(realpath "$1")
work=$2
for tool in munged mungekey slurmctld slurmd sbatch squeue sinfo scancel python3; do
  command -v "$tool" >/dev/null 2>&1 ||
    skip "$tool not found: install the Debian packages slurmctld slurmd slurm-client munge (scripts/setup.sh)"
done
[ "$(id -u)" -eq 0 ] || skip "slurmd must run as root to launch jobs; run the test as root"

started=$(date +%s)
log() { echo "[slurm test $(($(date +%s) - started))s] $*"; }

rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
cluster=$work/cluster
mkdir -p "$cluster"/{munge,state,spool,log}
chmod 700 "$cluster/munge"

pids=()
job_ids=()
cleanup() {
  local status=$?
  for id in "${job_ids[@]}"; do scancel "$id" 2>/dev/null || true; done
  # Stop the daemons by pid, newest first: slurmd, slurmctld, munged.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill "${pids[i]}" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [ "$status" -ne 0 ] && [ "$status" -ne 77 ]; then
    echo "FAILED; the daemons' logs and the runs are in $work" >&2
    tail -n 20 "$cluster"/log/*.log >&2 2>/dev/null || true
  fi
  exit "$status"
}
trap cleanup EXIT

# Two free TCP ports for slurmctld and slurmd.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
sockets = [socket.socket() for _ in range(2)]
for s in sockets: s.bind(("", 0))
print(*[s.getsockname()[1] for s in sockets])')

log "starting munged"
mungekey --create --keyfile="$cluster/munge/munge.key"
munged --foreground --force --socket="$cluster/munge/munge.socket" \
  --key-file="$cluster/munge/munge.key" --pid-file="$cluster/munge/munged.pid" \
  --log-file="$cluster/log/munged.log" --seed-file="$cluster/munge/munged.seed" \
  >"$cluster/log/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$cluster/munge/munge.socket" ] && break; sleep 0.1; done
munge --socket="$cluster/munge/munge.socket" --no-input | unmunge --socket="$cluster/munge/munge.socket" >/dev/null ||
  { echo "munged does not answer (see $cluster/log/munged.out)" >&2; exit 1; }

host=$(hostname -s)
export SLURM_CONF=$cluster/slurm.conf
cat >"$SLURM_CONF" <<CONF
# Written by tests/slurm/slurm_cluster_test.sh: a throwaway single-node cluster.
ClusterName=holebench-test
SlurmctldHost=$host
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$cluster/munge/munge.socket
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/log/slurmctld.log
SlurmdLogFile=$cluster/log/slurmd.log
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF

log "starting slurmctld and slurmd on $host (ports $ctld_port, $slurmd_port)"
slurmctld -D -f "$SLURM_CONF" >"$cluster/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$cluster/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 120); do
  [ "$(sinfo --noheader --Node --format=%t 2>/dev/null)" = idle ] && break
  sleep 0.5
done
[ "$(sinfo --noheader --Node --format=%t 2>/dev/null)" = idle ] ||
  { echo "the node did not come up idle:" >&2; sinfo >&2 || true; exit 1; }
log "cluster up: $(sinfo --noheader --format='%P %a %D %t %N')"

# Waits until Slurm job $1 has left the queue (at most $2 seconds).
wait_for_job() {
  local id=$1 deadline=$(($(date +%s) + $2))
  while [ -n "$(squeue --noheader --jobs="$id" 2>/dev/null)" ]; do
    [ "$(date +%s)" -lt "$deadline" ] || { echo "job $id still queued after $2 s" >&2; squeue >&2; exit 1; }
    sleep 1
  done
}

# Submits with the arguments given; prints the Slurm job id.
submitted_job_id() {
  "$@" | tee "$work/submit.out" >&2
  sed -n 's/^Submitted Slurm job \([0-9]*\).*/\1/p' "$work/submit.out"
}

run=$work/run
log "submitting the smoke suite as 4 shards"
id=$(submitted_job_id "$holebench" slurm submit --suite smoke --shards 4 --out "$run" --no-snapshots)
[ -n "$id" ] || { echo "no Slurm job id from holebench slurm submit" >&2; exit 1; }
job_ids+=("$id")
wait_for_job "$id" 1200
log "array $id done"
"$holebench" slurm status --out "$run"

log "breaking shard-2 (all but its first 36 records, and results.json, gone); status must name it"
shard2=$run/shard-2
head -n 36 "$shard2/records.jsonl" >"$shard2/records.partial" && mv "$shard2/records.partial" "$shard2/records.jsonl"
rm "$shard2/results.json"
if "$holebench" slurm status --out "$run" | tee "$work/status.out"; then
  echo "slurm status says complete with shard-2 broken" >&2; exit 1
fi
# 36 of the shard's jobs (a quarter of the smoke suite, whatever its size) remain.
grep -Eq "shard-2 +incomplete +36/[0-9]+ jobs" "$work/status.out"
grep -q "not complete: shard-2\." "$work/status.out"
if "$holebench" merge --shards "$run" 2>"$work/merge-refused.out"; then
  echo "merge went ahead with shard-2 incomplete" >&2; exit 1
fi
grep -q "shard-2" "$work/merge-refused.out"

log "resubmitting shard-2 alone"
id=$(submitted_job_id "$holebench" slurm resubmit --out "$run")
grep -q "^Resubmitting shard-2$" "$work/submit.out"
job_ids+=("$id")
wait_for_job "$id" 600
"$holebench" slurm status --out "$run"
log "shard-2 done"

log "merging"
"$holebench" merge --shards "$run"

single_results=${HOLEBENCH_SMOKE_RESULTS:-}
if [ -n "$single_results" ] && [ -f "$single_results" ] && [ "$single_results" -nt "$holebench" ]; then
  log "single-process run: reusing $single_results"
else
  log "single-process run of the smoke suite"
  "$holebench" run --suite smoke --out "$work/single" --no-snapshots >"$work/single.log" 2>&1
  single_results=$work/single/results.json
fi

log "comparing the merged results with the single-process run"
"$holebench" compare "$single_results" "$run/results.json" --suite smoke >"$work/compare.md"
tail -n 1 "$work/compare.md"
python3 - "$single_results" "$run/results.json" <<'PY'
# Equal up to timings: the same records in the same order; only the method's and the
# phases' times (and time_* metrics) may differ, and the snapshot paths (none here; the
# reused smoke run may have them).
import json, sys
def records(path):
    with open(path) as f:
        data = json.load(f)
    out = []
    for r in data["results"]:
        r = dict(r)
        r.pop("method_seconds", None)
        r.pop("stages_s", None)
        r.pop("phases_s", None)
        r.pop("evaluation_phases_s", None)
        r.pop("snapshot", None)
        r["metrics"] = {k: v for k, v in r.get("metrics", {}).items() if not k.startswith("time_")}
        out.append(r)
    return data["context"], out
single_context, single = records(sys.argv[1])
merged_context, merged = records(sys.argv[2])
problems = []
if len(single) != len(merged):
    problems.append(f"{len(single)} records in the single run, {len(merged)} merged")
for i, (a, b) in enumerate(zip(single, merged)):
    if a != b:
        keys = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
        problems.append(f"record {i} ({a.get('job_id')} / {b.get('job_id')}) differs in {keys}")
for key in ("suite", "code_version", "build_type", "schema_version"):
    if single_context.get(key) != merged_context.get(key):
        problems.append(f"context {key}: {single_context.get(key)!r} vs {merged_context.get(key)!r}")
if "shard" in merged_context:
    problems.append("the merged context still names a shard")
if problems:
    print("merged results differ from the single-process run:", *problems[:20], sep="\n  ")
    sys.exit(1)
print(f"merged == single-process run up to timings: {len(merged)} records, same order")
PY
log "passed"
