#!/usr/bin/env bash
# From a fresh clone on a fresh machine to the test results: installs the Debian packages
# (scripts/setup.sh), builds the Release preset, runs the smoke suite end to end (every
# method on a few cases of each family, in isolated processes; its report lands in
# build/smoke), checks its results file with `holebench validate` (every record complete,
# every metric in its range and order: a violation fails here), compares it with the
# reviewed baseline results/baselines/smoke.json by the suite's tolerances (a regression
# fails here; after an intended change, refresh it with scripts/refresh_baseline.sh smoke and
# commit it), then every test with CTest; the Slurm test (tests/slurm/) compares its merged
# shards with that smoke run instead of running the suite again. Validation and comparison
# are reported, and fail the script, after CTest has run. Last it builds the fuzz preset and
# runs every fuzz target for 30 s (scripts/run_fuzz.sh; about 9 minutes' cold build and
# 3 minutes' fuzzing on 2 cores), failing on a finding; HOLEBENCH_CI_FUZZ=0 leaves that out
# (for a quick local check).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh release
build/release/harness/holebench run --suite smoke --out build/smoke --no-snapshots
build/release/harness/holebench report build/smoke > /dev/null
smoke_validate=0
build/release/harness/holebench validate build/smoke/results.json > build/smoke/validate.txt \
  || smoke_validate=$?
smoke_compare=0
build/release/harness/holebench compare results/baselines/smoke.json build/smoke/results.json \
  --suite smoke --junit build/smoke/junit.xml > build/smoke/compare.md || smoke_compare=$?
HOLEBENCH_SMOKE_RESULTS="$PWD/build/smoke/results.json" ctest --preset release -j "$(nproc)"
failed=0
if [ "${HOLEBENCH_CI_FUZZ:-1}" != 0 ]; then
  scripts/run_fuzz.sh 30 || failed=1
fi
if [ "$smoke_validate" -ne 0 ]; then
  cat build/smoke/validate.txt
  echo "run_tests.sh: the smoke suite's results.json has violations (above)" >&2
  failed=1
fi
if [ "$smoke_compare" -ne 0 ]; then
  cat build/smoke/compare.md
  echo "run_tests.sh: the smoke suite changed against results/baselines/smoke.json (above)" >&2
  failed=1
fi
[ "$failed" -eq 0 ] || exit 1
echo "run_tests.sh: the smoke suite is valid and matches its baseline; every test passed"
