#!/usr/bin/env bash
# From a fresh clone on a fresh machine to the test results: installs the Debian packages
# (scripts/setup.sh), builds the Release preset and runs every test with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh release
ctest --preset release -j "$(nproc)"
