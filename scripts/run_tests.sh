#!/usr/bin/env bash
# From a fresh clone on a fresh machine to the test results: installs the Debian packages
# (scripts/setup.sh), builds the Release preset, runs the smoke suite end to end (every
# method on a few cases of each family, in isolated processes; its report lands in
# build/smoke), compares it with the reviewed baseline results/baselines/smoke.json by the
# suite's tolerances (a regression fails here; after an intended change, refresh it with
# scripts/refresh_baseline.sh smoke and commit it), then every test with CTest; the Slurm
# test (tests/slurm/) compares its merged shards with that smoke run instead of running the
# suite again.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh release
build/release/harness/holebench run --suite smoke --out build/smoke --no-snapshots
build/release/harness/holebench report build/smoke > /dev/null
smoke_compare=0
build/release/harness/holebench compare results/baselines/smoke.json build/smoke/results.json \
  --suite smoke --junit build/smoke/junit.xml > build/smoke/compare.md || smoke_compare=$?
HOLEBENCH_SMOKE_RESULTS="$PWD/build/smoke/results.json" ctest --preset release -j "$(nproc)"
if [ "$smoke_compare" -ne 0 ]; then
  cat build/smoke/compare.md
  echo "run_tests.sh: the smoke suite changed against results/baselines/smoke.json (above)" >&2
  exit 1
fi
echo "run_tests.sh: the smoke suite matches its baseline; every test passed"
