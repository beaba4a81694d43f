#!/usr/bin/env bash
# Runs the nightly suite and stores its results as the reviewed baseline that
# `holebench compare` checks nightly runs against: results/baselines/nightly.json.
# Usage: scripts/refresh_baseline.sh [suite]   (default: nightly)
set -euo pipefail
cd "$(dirname "$0")/.."
suite="${1:-nightly}"
out="build/baseline-run-$suite"
build/release/harness/holebench run --suite "$suite" --out "$out" --no-snapshots
mkdir -p results/baselines
cp "$out/results.json" "results/baselines/$suite.json"
echo "baseline written: results/baselines/$suite.json (review and commit it)"
