#!/usr/bin/env bash
# The nightly job: run the nightly suite, keep its results among the last N nightlies', write
# the history of those (OUT/report/history.html), the report, and compare with the baseline.
# Exits non-zero on a regression; leaves OUT/report/report.html and OUT/junit.xml.
# Usage: scripts/nightly.sh [--keep N] [output folder]   (default: build/nightly, N = 30)
#   --keep N  keep the results.json of the last N nightlies in OUT-history/ (as
#             results-<UTC time>.json; older ones are deleted) and draw their history;
#             0: keep nothing, no history.
set -euo pipefail
cd "$(dirname "$0")/.."
keep=30
while [ $# -gt 0 ]; do
  case "$1" in
    --keep) keep="${2-}"; shift $(($# > 1 ? 2 : 1)) ;;
    --keep=*) keep="${1#--keep=}"; shift ;;
    -h | --help) sed -n '2,8p' "$0" | cut -c3-; exit 0 ;;
    -*) echo "nightly.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
case "$keep" in
  '' | *[!0-9]*) echo "nightly.sh: --keep needs a whole number, not '$keep'" >&2; exit 2 ;;
esac
out="${1:-build/nightly}"
history_dir="${out%/}-history"
holebench=build/release/harness/holebench
# No 3D viewer meshes: the nightly's report is read for its tables and history.
"$holebench" run --suite nightly --out "$out" --no-viewer-meshes
"$holebench" cases gallery "$out" > /dev/null  # linked from the report
if [ "$keep" -gt 0 ]; then
  mkdir -p "$history_dir" "$out/report"
  cp "$out/results.json" "$history_dir/results-$(date -u +%Y%m%dT%H%M%SZ).json"
  # The names sort by time: all but the newest N go.
  find "$history_dir" -maxdepth 1 -name 'results-*.json' | sort | head -n -"$keep" |
    xargs -r rm -f --
  find "$history_dir" -maxdepth 1 -name 'results-*.json' | sort |
    xargs "$holebench" history --out "$out/report"  # linked from the report
fi
"$holebench" report "$out"
"$holebench" compare results/baselines/nightly.json "$out/results.json" \
  --suite nightly --junit "$out/junit.xml"
