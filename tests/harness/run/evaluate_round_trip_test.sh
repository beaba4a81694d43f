#!/usr/bin/env bash
# The round trip of `holebench evaluate --cases` through the command line: the smoke suite's
# cases run with liepa_cgal keeping its repairs (`run --repaired-meshes`), the cases exported
# (`cases export`, one folder per noise level), the repairs scored again; the records equal the
# run's up to timings: `holebench compare` finds no change, every record's status, message and
# hole reports are the same, and every metric but the times the same to 1e-12 relative (the
# patch's edges and new vertices are numbered as the file lists them, not as the method made
# them, so a sum over them may run in another order and differ in its last bits).
#
# Usage: evaluate_round_trip_test.sh HOLEBENCH WORK_DIR
set -euo pipefail
holebench="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work"
suite="$(dirname "$0")/../../../suites/smoke.json"
mapfile -t patterns < <(python3 -c 'import json,sys; print("\n".join(json.load(open(sys.argv[1]))["cases"]))' "$suite")

"$holebench" run --suite smoke --method liepa_cgal --out "$work/run" --no-snapshots \
  --repaired-meshes --workers 2 > "$work/run.txt"
for noise in 0 5; do
  "$holebench" cases export "$work/cases/noise-$noise" "${patterns[@]}" --noise "$noise" \
    --no-cad 2> "$work/export-$noise.txt"
done
"$holebench" evaluate --cases "$work/cases" --repaired "$work/run/repaired" \
  --method liepa_cgal --out "$work/again" --no-snapshots --workers 2 > "$work/again.txt"
"$holebench" compare "$work/run/results.json" "$work/again/results.json" --suite smoke \
  > "$work/compare.md"

python3 - "$work/run/results.json" "$work/again/results.json" <<'PY'
import json, sys
def records(path):
    return {r["job_id"]: r for r in json.load(open(path))["results"]}
run, again = records(sys.argv[1]), records(sys.argv[2])
problems = []
if set(run) != set(again):
    problems.append(f"job ids differ: only in the run {sorted(set(run) - set(again))[:5]}, "
                    f"only scored {sorted(set(again) - set(run))[:5]}")
for job_id in sorted(set(run) & set(again)):
    a, b = run[job_id], again[job_id]
    for field in ("status", "message", "holes", "case_family", "case_kind", "user"):
        if a.get(field) != b.get(field):
            problems.append(f"{job_id}: {field} {a.get(field)!r} -> {b.get(field)!r}")
    ma = {k: v for k, v in a.get("metrics", {}).items() if not k.startswith("time_")}
    mb = {k: v for k, v in b.get("metrics", {}).items() if not k.startswith("time_")}
    for name in sorted(set(ma) | set(mb)):
        x, y = ma.get(name), mb.get(name)
        if x is None or y is None or abs(x - y) > 1e-12 * max(abs(x), abs(y)):
            problems.append(f"{job_id}: {name} {ma.get(name)!r} -> {mb.get(name)!r}")
print(f"{len(run)} records; {len(problems)} differences")
for line in problems[:40]:
    print(line)
sys.exit(1 if problems or not run else 0)
PY
