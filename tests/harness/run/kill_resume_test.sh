#!/usr/bin/env bash
# Interruption at any moment: `holebench run` killed outright (SIGKILL to the runner and to
# every job process, as a machine losing power or an OOM kill would) at several pseudo-random
# moments of a small part of the smoke suite, resumed each time with --resume, ends with the
# same records as an uninterrupted run, up to timings. Then `holebench merge --shards` killed
# at random moments never leaves a half-written results.json: after each kill the file is
# either absent or the complete merged file, and a rerun gives the same records. Last,
# `holebench report` killed at random moments never leaves a half-written file in report/:
# each file there is absent or the whole file an uninterrupted report writes.
#
# Usage: kill_resume_test.sh HOLEBENCH WORK_DIR   (HOLEBENCH_KILL_SEED: the moments' seed)
set -euo pipefail
holebench="$1"
work="$2"
seed="${HOLEBENCH_KILL_SEED:-23}"
kills="${HOLEBENCH_KILLS:-5}"
rm -rf "$work"
mkdir -p "$work/tmp"
export TMPDIR="$work/tmp"  # the jobs' temporary folders that a kill leaves stay in here

# shellcheck source=smoke_part.sh
source "$(dirname "$0")/smoke_part.sh"
write_smoke_part "$work/part.json" smoke_part "kill-and-resume test: a part of the smoke suite"
# Its sharded part for merge --shards: 4 jobs in 2 shards.
cat > "$work/shards.json" <<'JSON'
{
  "name": "smoke_shards",
  "description": "kill-and-resume test: a sharded part of the smoke suite",
  "cases": ["box/edge", "box/corner"],
  "methods": ["cgal_triangulate"],
  "noise_percent": [0, 5],
  "include_cad": false,
  "timeout_s": 120
}
JSON
run_args=(run --suite "$work/part.json" --no-snapshots --workers 2)

# Kills a process started with setsid (its group), every group process it started and every
# job process those started (each leads its own group), all with SIGKILL, the runner first.
kill_tree() {
  local pid="$1"
  local children groups
  groups=$(ps -o pid= --ppid "$pid" 2>/dev/null || true)
  children="$groups"
  for group in $groups; do
    children="$children $(ps -o pid= --ppid "$group" 2>/dev/null || true)"
  done
  kill -KILL -- "-$pid" 2>/dev/null || true
  for child in $children; do
    kill -KILL -- "-$child" 2>/dev/null || kill -KILL "$child" 2>/dev/null || true
  done
  wait "$pid" 2>/dev/null || true
  # Until every process of those groups is gone (a job's program included).
  for _ in $(seq 1 100); do
    local alive=0
    for group in "$pid" $children; do
      if pgrep -g "$group" >/dev/null 2>&1; then alive=1; fi
    done
    [ "$alive" -eq 0 ] && return 0
    sleep 0.05
  done
  echo "kill_resume_test: processes of run $pid outlived it" >&2
  return 1
}

start=$(date +%s.%N)
"$holebench" "${run_args[@]}" --out "$work/reference" 2> "$work/reference.log" > /dev/null
reference_seconds=$(python3 -c "import time; print(time.time() - $start)")
echo "uninterrupted run: $reference_seconds s"

# Moments spread over the run: pseudo-random, reproducible from the seed.
moments=$(python3 -c "
import random
r = random.Random($seed)
total = $reference_seconds
print(' '.join(f'{r.uniform(0.03, 0.45) * total:.3f}' for _ in range($kills)))")
echo "kill moments (s after each start): $moments"

out="$work/interrupted"
resume=()
for moment in $moments; do
  setsid "$holebench" "${run_args[@]}" --out "$out" "${resume[@]}" > /dev/null 2>> "$work/interrupted.log" &
  pid=$!
  sleep "$moment"
  kill_tree "$pid"
  lines=$( [ -f "$out/records.jsonl" ] && wc -l < "$out/records.jsonl" || echo 0)
  echo "killed at $moment s: $lines lines in records.jsonl"
  # A results.json present after a kill is always complete JSON (written atomically).
  if [ -f "$out/results.json" ]; then
    python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$out/results.json" \
      || { echo "kill_resume_test: a half-written results.json after a kill" >&2; exit 1; }
  fi
  resume=(--resume)
done
"$holebench" "${run_args[@]}" --out "$out" --resume > /dev/null 2>> "$work/interrupted.log"
same_records "$work/reference/results.json" "$out/results.json"
"$holebench" validate "$out/results.json" > /dev/null
echo "run: killed $kills times and resumed: the same records as the uninterrupted run"

# merge --shards: a smaller part in 2 shards, merged while being killed at random moments.
shards="$work/sharded"
shard_args=(run --suite "$work/shards.json" --no-snapshots --workers 2)
"$holebench" slurm submit --suite "$work/shards.json" --shards 2 --out "$shards" --dry-run \
  --no-snapshots > /dev/null
"$holebench" "${shard_args[@]}" --out "$work/shards_reference" > /dev/null 2>&1
for i in 0 1; do
  "$holebench" "${shard_args[@]}" --shard "$i/2" --out "$shards/shard-$i" > /dev/null 2>&1
done
"$holebench" merge --shards "$shards" --out "$work/merged_reference" > /dev/null 2>&1
same_records "$work/shards_reference/results.json" "$work/merged_reference/results.json"
merged="$work/merged"
moments=$(python3 -c "
import random
r = random.Random($seed + 1)
print(' '.join(f'{r.uniform(0.0, 0.08):.3f}' for _ in range(12)))")
for moment in $moments; do
  setsid "$holebench" merge --shards "$shards" --out "$merged" > /dev/null 2>&1 &
  pid=$!
  sleep "$moment"
  kill_tree "$pid"
  if [ -f "$merged/results.json" ]; then
    same_records "$work/merged_reference/results.json" "$merged/results.json" \
      || { echo "kill_resume_test: merge killed at $moment s left another results.json" >&2; exit 1; }
  fi
done
"$holebench" merge --shards "$shards" --out "$merged" > /dev/null 2>&1
same_records "$work/merged_reference/results.json" "$merged/results.json"
echo "merge --shards: killed 12 times, never a half-written results.json"

# report: killed at random moments of its run; every file it has written is whole.
reported="$work/reported"
cp -r "$work/reference" "$work/report_reference"
start=$(date +%s.%N)
"$holebench" report "$work/report_reference" > /dev/null 2>&1
report_seconds=$(python3 -c "import time; print(time.time() - $start)")
moments=$(python3 -c "
import random
r = random.Random($seed + 2)
print(' '.join(f'{r.uniform(0.0, $report_seconds):.3f}' for _ in range(4)))")
cp -r "$work/reference" "$reported"
for moment in $moments; do
  setsid "$holebench" report "$reported" > /dev/null 2>&1 &
  pid=$!
  sleep "$moment"
  kill_tree "$pid"
  while IFS= read -r -d '' file; do
    relative="${file#"$reported/report/"}"
    case "$relative" in *.partial) continue ;; esac
    cmp -s "$file" "$work/report_reference/report/$relative" \
      || { echo "kill_resume_test: report killed at $moment s left a partial $relative" >&2; exit 1; }
  done < <(find "$reported/report" -type f -print0 2> /dev/null)
done
"$holebench" report "$reported" > /dev/null 2>&1
diff -r --exclude='*.partial' "$work/report_reference/report" "$reported/report" > /dev/null \
  || { echo "kill_resume_test: the report after the kills differs" >&2; exit 1; }
echo "report: killed 4 times (report takes $report_seconds s), never a partial file"
