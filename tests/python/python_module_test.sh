#!/usr/bin/env bash
# The Python module `holebench` against the command line: a liepa_cgal run on the fandisk and a
# box keeping its repairs (`run --repaired-meshes`), their cases exported, the fandisk pair
# printed by `holebench evaluate --complete --repaired --holed --json`; then
# holebench_module_test.py checks the module against those files (Debian's python3, which has
# NumPy), and examples/python_leaderboard.py runs on the smoke suite.
#
# Usage: python_module_test.sh HOLEBENCH MODULE_DIR WORK_DIR
set -euo pipefail
holebench="$1"
module_dir="$2"
work="$3"
here="$(cd "$(dirname "$0")" && pwd)"
python=/usr/bin/python3
rm -rf "$work"
mkdir -p "$work"

cases=(cad/fandisk/edge_convex/small box/corner)
for case in "${cases[@]}"; do
  args+=(--case "$case")
done
"$holebench" run "${args[@]}" --method liepa_cgal --noise 0 --noise 5 --out "$work/run" \
  --no-snapshots --repaired-meshes --workers 2 > "$work/run.txt"
"$holebench" cases export "$work/cases" "${cases[@]}" 2> "$work/export.txt"
fandisk="$work/cases/cad_fandisk_edge_convex_small"
"$holebench" evaluate --complete "$fandisk/complete.ply" \
  --repaired "$work/run/repaired/cad_fandisk_edge_convex_small_liepa_cgal_no_user_0_0.ply" \
  --holed "$fandisk/input.ply" --json > "$work/fandisk_pair.json"

export PYTHONPATH="$module_dir${PYTHONPATH:+:$PYTHONPATH}"
"$python" -c "import holebench"
HOLEBENCH_TEST_WORK="$work" "$python" "$here/holebench_module_test.py" -v
"$python" "$here/../../examples/python_leaderboard.py" > "$work/leaderboard.md" \
  2> "$work/leaderboard_progress.txt"
cat "$work/leaderboard.md"
grep -q "^| numpy_fan |" "$work/leaderboard.md"
grep -q "^| liepa_cgal |" "$work/leaderboard.md"
