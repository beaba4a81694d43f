# Sourced by the shell tests of interruption and full disks (kill_resume_test.sh,
# disk_full_test.sh): the part of the smoke suite they run, and how they compare records.

# Writes the part of the smoke suite to FILE: its quicker cases, two methods, two noise levels
# (16 jobs, about 8 s on 2 busy cores). NAME and DESCRIPTION name the suite.
write_smoke_part() {
  local file="$1" name="$2" description="$3"
  cat > "$file" << JSON
{
  "name": "$name",
  "description": "$description",
  "cases": ["box/edge", "box/corner", "brep/k1/inner/small", "brep/k1/outer/outer/small"],
  "methods": ["liepa_cgal", "cgal_triangulate"],
  "noise_percent": [0, 5],
  "include_cad": false,
  "timeout_s": 120
}
JSON
}

# Records equal up to timings: every record's fields but its times, in order. Exit status 1,
# with the first difference on stderr, when they differ.
same_records() {
  python3 - "$1" "$2" << 'PY'
import json, sys
def records(path):
    out = []
    for r in json.load(open(path))["results"]:
        for key in ("stages_s", "phases_s", "evaluation_phases_s", "method_seconds",
                    "method_run_seconds"):
            r.pop(key, None)
        r.get("metrics", {}).pop("time_method_s", None)
        out.append(r)
    return out
a, b = records(sys.argv[1]), records(sys.argv[2])
if a != b:
    ids_a = [r["job_id"] for r in a]
    ids_b = [r["job_id"] for r in b]
    print(f"records differ: {len(a)} vs {len(b)} records", file=sys.stderr)
    for x, y in zip(a, b):
        if x != y:
            print("first difference:", x["job_id"], file=sys.stderr)
            for k in sorted(set(x) | set(y)):
                if x.get(k) != y.get(k):
                    print(f"  {k}: {x.get(k)!r:.200} != {y.get(k)!r:.200}", file=sys.stderr)
            break
    if ids_a != ids_b:
        print("job ids differ", file=sys.stderr)
    sys.exit(1)
PY
}
