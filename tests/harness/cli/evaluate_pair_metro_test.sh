#!/usr/bin/env bash
# `holebench evaluate --complete A --repaired B --json` through the command line on the fandisk
# test pair (cad/fandisk/edge_convex/small, exported, and liepa_cgal's repair of it kept by
# `run --repaired-meshes`), against
#   - the run's own record of that job: every distance equal to 1e-12 relative (the patch's
#     elements are numbered as the file lists them), and
#   - MeshLab's Metro (meshlabserver's Hausdorff Distance filter, both ways: every vertex and
#     SAMPLES face samples): Metro's maximum is the largest distance at a sample, so at most our
#     certified upper bound (plus its six printed decimals) and, a sampled lower estimate, within
#     10 % below our attained distance (7 % on this pair: its farthest point lies inside a face);
#     its mean and RMS are Monte Carlo estimates, within four standard errors of our intervals
#     (as tests/metrics/meshlab_hausdorff_test.cpp checks them on other pairs).
# Prints both tools' wall times. Skipped (77) without meshlabserver or xvfb-run.
#
# Usage: evaluate_pair_metro_test.sh HOLEBENCH WORK_DIR [SAMPLES]
set -euo pipefail
holebench="$1"
work="$2"
samples="${3:-100000}"
if ! command -v meshlabserver > /dev/null || ! command -v xvfb-run > /dev/null; then
  echo "meshlabserver or xvfb-run not installed (Debian meshlab, xvfb): skipped"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
case_id=cad/fandisk/edge_convex/small
"$holebench" run --case "$case_id" --method liepa_cgal --out "$work/run" --no-snapshots \
  --repaired-meshes --workers 1 > "$work/run.txt"
"$holebench" cases export "$work/cases" "$case_id" 2> "$work/export.txt"
complete="$work/cases/cad_fandisk_edge_convex_small/complete.off"
repaired="$work/run/repaired/cad_fandisk_edge_convex_small_liepa_cgal_no_user_0_0.ply"

start=$EPOCHREALTIME
"$holebench" evaluate --complete "$complete" --repaired "$repaired" --json > "$work/pair.json"
holebench_seconds=$(python3 -c "print($EPOCHREALTIME - $start)")

cat > "$work/hausdorff.mlx" <<MLX
<!DOCTYPE FilterScript>
<FilterScript>
$(for pair in "0 1" "1 0"; do set -- $pair; cat <<FILTER
 <filter name="Hausdorff Distance">
  <Param type="RichMesh" value="$1" name="SampledMesh"/>
  <Param type="RichMesh" value="$2" name="TargetMesh"/>
  <Param type="RichBool" value="false" name="SaveSample"/>
  <Param type="RichBool" value="true" name="SampleVert"/>
  <Param type="RichBool" value="false" name="SampleEdge"/>
  <Param type="RichBool" value="false" name="SampleFauxEdge"/>
  <Param type="RichBool" value="true" name="SampleFace"/>
  <Param type="RichInt" value="$samples" name="SampleNum"/>
  <Param type="RichAbsPerc" value="100" min="0" max="100" name="MaxDist"/>
 </filter>
FILTER
done)
</FilterScript>
MLX
cp "$repaired" "$work/repaired.ply"
cp "$complete" "$work/complete.off"
start=$EPOCHREALTIME
(cd "$work" && timeout 300 xvfb-run -a meshlabserver -i complete.off repaired.ply \
  -s hausdorff.mlx -l metro_log.txt > metro_output.txt 2>&1)
metro_seconds=$(python3 -c "print($EPOCHREALTIME - $start)")

python3 - "$work" "$samples" "$holebench_seconds" "$metro_seconds" <<'PY'
import json, math, re, sys
work, samples = sys.argv[1], int(sys.argv[2])
pair = json.load(open(f"{work}/pair.json"))
m = pair["metrics"]
diag = pair["complete_bounding_box_diagonal"]
run = json.load(open(f"{work}/run/results.json"))["results"][0]["metrics"]
failures = []
for name in ("hausdorff_rel_diag", "hausdorff_upper_rel_diag", "mean_distance_rel_diag",
             "mean_distance_lower_rel_diag", "mean_distance_upper_rel_diag",
             "rms_distance_rel_diag", "rms_distance_lower_rel_diag",
             "rms_distance_upper_rel_diag", "chamfer_l1_rel_diag", "f_score_1pct_fraction",
             "normal_consistency_fraction", "valid_repair_ok" if "valid_repair_ok" in m else
             "is_closed"):
    if not math.isclose(m[name], run[name], rel_tol=1e-12, abs_tol=1e-15):
        failures.append(f"{name}: evaluate {m[name]} != run {run[name]}")

# Metro's log: per direction, the first values line after "Sampled ... on X searched closest on Y".
directions, current = {}, None
for line in open(f"{work}/metro_log.txt"):
    s = re.search(r"Sampled \d+ pts .* on (\S+) searched closest on (\S+)", line)
    if s:
        current = s.group(1) + ">" + s.group(2)
        continue
    v = re.search(r"min : ([-0-9.eE+]+)\s+max ([-0-9.eE+]+)\s+mean : ([-0-9.eE+]+)\s+"
                  r"RMS : ([-0-9.eE+]+)", line)
    if v and current and current not in directions:
        directions[current] = [float(v.group(i)) / diag for i in (2, 3, 4)]
        current = None
if len(directions) != 2:
    sys.exit(f"could not read both directions from {work}/metro_log.txt: {directions}")
metro_max = max(d[0] for d in directions.values())
metro_mean = max(d[1] for d in directions.values())
metro_rms = max(d[2] for d in directions.values())
printed = 2e-6 / diag  # six printed decimals, single precision
n = samples
if metro_max > m["hausdorff_upper_rel_diag"] + printed:
    failures.append(f"Metro's maximum {metro_max} above our upper bound {m['hausdorff_upper_rel_diag']}")
if metro_max < 0.9 * m["hausdorff_rel_diag"]:
    failures.append(f"Metro's maximum {metro_max} more than 10 % below {m['hausdorff_rel_diag']}")
mean_tol = 4 * math.sqrt(max(0.0, m["rms_distance_upper_rel_diag"] ** 2 -
                             m["mean_distance_lower_rel_diag"] ** 2) / n) \
    + 0.01 * m["mean_distance_upper_rel_diag"] + printed
rms_tol = 4 * m["hausdorff_upper_rel_diag"] / (2 * math.sqrt(n)) \
    + 0.01 * m["rms_distance_upper_rel_diag"] + printed
if not (m["mean_distance_lower_rel_diag"] - mean_tol <= metro_mean <= m["mean_distance_upper_rel_diag"] + mean_tol):
    failures.append(f"Metro's mean {metro_mean} outside [{m['mean_distance_lower_rel_diag']}, "
                    f"{m['mean_distance_upper_rel_diag']}] +- {mean_tol}")
if not (m["rms_distance_lower_rel_diag"] - rms_tol <= metro_rms <= m["rms_distance_upper_rel_diag"] + rms_tol):
    failures.append(f"Metro's RMS {metro_rms} outside [{m['rms_distance_lower_rel_diag']}, "
                    f"{m['rms_distance_upper_rel_diag']}] +- {rms_tol}")
print(f"holebench evaluate: {float(sys.argv[3]):.2f} s; Hausdorff {m['hausdorff_rel_diag']:.6f} "
      f"(upper {m['hausdorff_upper_rel_diag']:.6f}), mean {m['mean_distance_rel_diag']:.3e}, "
      f"RMS {m['rms_distance_rel_diag']:.3e}")
print(f"Metro ({n} face samples + vertices): {float(sys.argv[4]):.2f} s; Hausdorff {metro_max:.6f}, "
      f"mean {metro_mean:.3e}, RMS {metro_rms:.3e}")
if failures:
    sys.exit("\n".join(failures))
PY
