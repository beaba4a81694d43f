#!/usr/bin/env bash
# The nightly job: run the nightly suite, write the report, compare with the baseline.
# Exits non-zero on a regression; leaves OUT/report/report.html and OUT/junit.xml.
# Usage: scripts/nightly.sh [output folder]   (default: build/nightly)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/nightly}"
build/release/harness/holebench run --suite nightly --out "$out"
build/release/harness/holebench cases gallery "$out" > /dev/null  # linked from the report
build/release/harness/holebench report "$out"
build/release/harness/holebench compare results/baselines/nightly.json "$out/results.json" \
  --suite nightly --junit "$out/junit.xml"
