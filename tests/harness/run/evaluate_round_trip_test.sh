#!/usr/bin/env bash
# The round trip of `holebench evaluate --cases` through the command line: the smoke suite's
# cases run with liepa_cgal keeping its repairs (`run --repaired-meshes`), the cases exported
# (`cases export`, one folder per noise level), the repairs scored again; the records equal the
# run's up to timings: `holebench compare` finds no change, every record's status, message and
# hole reports are the same, and every metric but the times the same to 1e-12 relative (the
# patch's edges and new vertices are numbered as the file lists them, not as the method made
# them, so a sum over them may run in another order and differ in its last bits).
#
# Last, one pair through `holebench evaluate --complete --repaired --holed --json` (the exported
# complete and holed meshes of two noise-free cases, the run's repaired mesh): its distances
# equal the run's record to 1e-12 relative.
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

for case in box_corner brep_k2_inner_convex_small; do
  "$holebench" evaluate --complete "$work/cases/noise-0/$case/complete.ply" \
    --holed "$work/cases/noise-0/$case/input.ply" \
    --repaired "$work/run/repaired/${case}_liepa_cgal_no_user_0_0.ply" --json > "$work/pair-$case.json"
  python3 - "$work/run/results.json" "$work/pair-$case.json" <<'PY'
import json, sys
pair = json.load(open(sys.argv[2]))
stem = sys.argv[2].split("pair-")[1][:-len(".json")]
run = [r for r in json.load(open(sys.argv[1]))["results"]
       if r["job_id"].replace("/", "_").replace("|", "_") == stem + "_liepa_cgal_no_user_0_0"]
assert len(run) == 1, f"no run record for {stem}"
problems = []
for name in ("hausdorff_rel_diag", "hausdorff_upper_rel_diag", "mean_distance_rel_diag",
             "rms_distance_rel_diag", "hole_hausdorff_rel_diag", "hole_mean_distance_rel_diag",
             "f_score_1pct_fraction", "is_closed", "self_intersections_count", "new_faces_count"):
    x, y = run[0]["metrics"].get(name), pair["metrics"].get(name)
    if x is None or y is None or abs(x - y) > 1e-12 * max(abs(x), abs(y)):
        problems.append(f"{stem}: {name}: run {x!r}, evaluate --complete {y!r}")
print(f"pair {stem}: {len(problems)} differences")
for line in problems:
    print(line)
sys.exit(1 if problems else 0)
PY
done
