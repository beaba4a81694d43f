#!/usr/bin/env bash
# A full disk and a read-only folder, for real: a small tmpfs mounted in a private mount
# namespace (root only; skipped with exit code 77 elsewhere, which CTest reports as skipped).
#  1. The disk fills up during `holebench run`: the run stops with a one-line error naming
#     records.jsonl and "No space left on device"; every record written before stays whole;
#     the folder copied to a disk with room and resumed ends with the records of an
#     uninterrupted run, up to timings.
#  2. The disk is full when results.json is rewritten (`run --resume`) and when the report is
#     written: a one-line error naming the file; the old results.json and report.html stay
#     byte for byte, and no temporary file is left.
#  3. The folder is read-only: the same for `run --resume` and `report`.
#
# Usage: disk_full_test.sh HOLEBENCH WORK_DIR
set -euo pipefail
holebench="$1"
work="$2"
if [ "$(id -u)" -ne 0 ] || ! unshare -m true 2> /dev/null; then
  echo "disk_full_test: skipped: needs root and mount namespaces to mount a small tmpfs"
  exit 77
fi
if [ -z "${HOLEBENCH_DISK_FULL_NAMESPACE:-}" ]; then
  # Mounts made in a private namespace vanish with it, even if this script is killed.
  exec unshare -m --propagation private env HOLEBENCH_DISK_FULL_NAMESPACE=1 "$0" "$@"
fi
rm -rf "$work"
mkdir -p "$work/tmp"
export TMPDIR="$work/tmp"  # the jobs' temporary folders stay on a disk with room

# shellcheck source=smoke_part.sh
source "$(dirname "$0")/smoke_part.sh"
write_smoke_part "$work/part.json" disk_full_part "disk-full test: a part of the smoke suite"
run_args=(run --suite "$work/part.json" --no-snapshots --no-viewer-meshes --workers 2)

fail() {
  echo "disk_full_test: $*" >&2
  exit 1
}

# The command failed with a one-line error naming the file and the reason, not a crash.
expect_clear_error() {
  local what="$1" status="$2" log="$3" file="$4" reason="$5"
  [ "$status" -ne 0 ] || fail "$what: exit status 0 on a full or read-only disk"
  [ "$status" -lt 128 ] || fail "$what: killed by a signal (status $status): $(tail -3 "$log")"
  grep -q "terminate called\|Aborted\|core dumped" "$log" && fail "$what: crashed: $(cat "$log")"
  grep -F "$file" "$log" | grep -qF "$reason" ||
    fail "$what: no error naming $file and \"$reason\"; stderr was: $(tail -5 "$log")"
  echo "$what: $(grep -F "$file" "$log" | grep -F "$reason" | head -1)"
}

"$holebench" "${run_args[@]}" --out "$work/reference" > /dev/null 2> "$work/reference.log"
records_bytes=$(wc -c < "$work/reference/records.jsonl")
jobs=$(wc -l < "$work/reference/records.jsonl")

# 1. The disk fills up during the run: room for about half of the records.
mnt="$work/small_disk"
mkdir -p "$mnt"
pages=$(((records_bytes / 2 + 4095) / 4096))
mount -t tmpfs -o size=$((pages * 4096)) tmpfs "$mnt"
status=0
"$holebench" "${run_args[@]}" --out "$mnt/run" > /dev/null 2> "$work/full.log" || status=$?
expect_clear_error "run on a full disk" "$status" "$work/full.log" "$mnt/run/records.jsonl" \
  "No space left on device"
kept=$(python3 - "$mnt/run/records.jsonl" << 'PY'
import json, sys
lines = open(sys.argv[1], "rb").read().split(b"\n")
whole = 0
for i, line in enumerate(lines):
    if not line:
        continue
    try:
        json.loads(line)
        whole += 1
    except ValueError:
        # Only the line the disk filled up in may be cut short: the last one.
        if any(rest for rest in lines[i + 1:]):
            sys.exit(f"line {i + 1} of {sys.argv[1]} is cut short and lines follow it")
print(whole)
PY
)
[ "$kept" -gt 0 ] && [ "$kept" -lt "$jobs" ] ||
  fail "expected some of the $jobs records kept on the full disk, got $kept"
echo "run on a full disk: $kept of $jobs records kept whole"
cp -r "$mnt/run" "$work/resumed"
umount "$mnt"
"$holebench" "${run_args[@]}" --out "$work/resumed" --resume > /dev/null 2> "$work/resumed.log"
same_records "$work/reference/results.json" "$work/resumed/results.json"
echo "resumed on a disk with room: the records of an uninterrupted run"

# 2. A complete run and its report, then the disk filled up.
mount -t tmpfs -o size=$((4 * records_bytes + 4 * 1024 * 1024)) tmpfs "$mnt"
"$holebench" "${run_args[@]}" --out "$mnt/run" > /dev/null 2> "$work/complete.log"
"$holebench" report "$mnt/run" > /dev/null 2> "$work/report.log"
cp "$mnt/run/results.json" "$work/results.before"
cp "$mnt/run/report/report.html" "$work/report.before"
dd if=/dev/zero of="$mnt/filler" bs=4096 2> /dev/null || true
status=0
"$holebench" "${run_args[@]}" --out "$mnt/run" --resume > /dev/null 2> "$work/full_results.log" ||
  status=$?
expect_clear_error "results.json on a full disk" "$status" "$work/full_results.log" \
  "$mnt/run/results.json" "No space left on device"
cmp -s "$mnt/run/results.json" "$work/results.before" || fail "results.json changed on a full disk"
status=0
"$holebench" report "$mnt/run" > /dev/null 2> "$work/full_report.log" || status=$?
expect_clear_error "report on a full disk" "$status" "$work/full_report.log" "$mnt/run/report" \
  "No space left on device"
cmp -s "$mnt/run/report/report.html" "$work/report.before" ||
  fail "report.html changed on a full disk"
leftovers=$(find "$mnt/run" -name '*.partial' | head -3)
[ -z "$leftovers" ] || fail "temporary files left on a full disk: $leftovers"

# 3. The same folder read-only.
rm -f "$mnt/filler"
mount -o remount,ro "$mnt"
status=0
"$holebench" "${run_args[@]}" --out "$mnt/run" --resume > /dev/null 2> "$work/ro_run.log" ||
  status=$?
expect_clear_error "run in a read-only folder" "$status" "$work/ro_run.log" "$mnt/run" \
  "Read-only file system"
status=0
"$holebench" report "$mnt/run" > /dev/null 2> "$work/ro_report.log" || status=$?
expect_clear_error "report in a read-only folder" "$status" "$work/ro_report.log" "$mnt/run/report" \
  "Read-only file system"
cmp -s "$mnt/run/results.json" "$work/results.before" || fail "results.json changed"
cmp -s "$mnt/run/report/report.html" "$work/report.before" || fail "report.html changed"
umount "$mnt"
echo "disk_full_test: passed"
