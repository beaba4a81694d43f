#!/usr/bin/env bash
# Installs every Debian package holebench needs. Idempotent; run as root
# (or through sudo). Safe to run again: apt-get skips what is installed.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build ccache pkg-config git
  # geometry and mesh libraries
  libcgal-dev libcgal-demo libeigen3-dev libgmp-dev libmpfr-dev libboost-dev
  libopenmesh-dev
  libembree-dev libtbb-dev
  # B-Rep files (STEP, IGES, BREP) through OpenCASCADE 7.6 (core/occt/)
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev
  libocct-foundation-dev
  # images (OpenImageIO's CMake targets name /usr/include/opencv4 and its tools)
  libopenimageio-dev libopencv-core-dev openimageio-tools
  # formatting, JSON, command line
  libfmt-dev nlohmann-json3-dev libcli11-dev
  # the viewer's mesh files, gzip-compressed (harness/outputs/gzip_bytes.h)
  zlib1g-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  # METIS: CGAL's parallel Hausdorff distance, the benchmarks' two-thread reference
  libmetis-dev
  # MeshLab: the cross-check of the distance metrics (tests/metrics/meshlab_hausdorff_test.cpp)
  # and the external method meshlab_close_holes (methods/external/), run under xvfb-run
  meshlab xvfb xauth
  # reports: plots; the worked example of an external method (examples/fan_fill.py)
  python3 python3-matplotlib
  # the Python module (python/): pybind11 and NumPy
  python3-dev pybind11-dev python3-numpy
  # the report's 3D viewer: three.js r111, copied into each report (harness/outputs/viewer/),
  # and the headless browser its test draws it in (tests/harness/outputs/viewer/)
  libjs-three chromium
  # formatting of the sources
  clang-format
  # coverage-guided fuzzing of the readers (scripts/run_fuzz.sh): clang with libFuzzer
  clang libclang-rt-14-dev
  # the cluster workflow's test on a throwaway single-node Slurm (tests/slurm/)
  slurmctld slurmd slurm-client munge
)

if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then exec sudo -E "$0" "$@"; fi
  echo "setup.sh: run as root (apt-get needs it)" >&2
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup.sh: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "setup.sh: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup.sh: done"
