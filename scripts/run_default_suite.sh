#!/usr/bin/env bash
# From a fresh clone on a fresh machine to the default suite's report: installs the Debian
# packages, builds, and runs the default suite into holebench-out/ (results.json,
# results.csv and one PNG snapshot per job in holebench-out/snapshots/).
# Usage: scripts/run_default_suite.sh [output folder]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-holebench-out}"
scripts/setup.sh
scripts/build.sh release
build/release/harness/holebench run --out "$out"
