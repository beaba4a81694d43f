#!/usr/bin/env bash
# From a fresh clone on a fresh machine to the default suite's report: installs the Debian
# packages, builds, runs the default suite (suites/default.json) into holebench-out/
# (results.json, results.csv, snapshots/) and writes its report (holebench-out/report/).
# Usage: scripts/run_default_suite.sh [output folder]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-holebench-out}"
scripts/setup.sh
scripts/build.sh release
build/release/harness/holebench run --suite default --out "$out"
# The case gallery first, so that the report's page links it.
build/release/harness/holebench cases gallery "$out" > /dev/null
build/release/harness/holebench report "$out"
