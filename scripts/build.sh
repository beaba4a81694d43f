#!/usr/bin/env bash
# Configures and builds holebench (Release preset: CGAL code is far too slow in Debug).
# Usage: scripts/build.sh [preset]   (default: release)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
cmake --preset "$preset"
cmake --build --preset "$preset" -j "$(nproc)"
