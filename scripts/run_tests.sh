#!/usr/bin/env bash
# From a fresh clone on a fresh machine to the test results: installs the Debian packages
# (scripts/setup.sh), builds the Release preset, runs the smoke suite end to end (every
# method on a few cases of each family, in isolated processes; its report lands in
# build/smoke), then every test with CTest; the Slurm test (tests/slurm/) compares its merged
# shards with that smoke run instead of running the suite again.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh release
build/release/harness/holebench run --suite smoke --out build/smoke --no-snapshots
build/release/harness/holebench report build/smoke > /dev/null
HOLEBENCH_SMOKE_RESULTS="$PWD/build/smoke/results.json" ctest --preset release -j "$(nproc)"
