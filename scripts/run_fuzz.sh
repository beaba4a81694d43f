#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset: clang, AddressSanitizer, UBSan) and runs
# each for a bounded time from its seed corpus in tests/fuzz/corpus/<target>/. Fails (exit 1)
# on any finding: a crash, a sanitizer report, a timeout of one input, or an allocation past
# the memory limit; the input that caused it is left in build/fuzz/findings/<target>/ and the
# fuzzer's output in build/fuzz/logs/<target>.log. Prints one line per target: executions and
# coverage (libFuzzer's `cov:` edges and `ft:` features) at the end of its run.
#
# Usage: scripts/run_fuzz.sh [SECONDS_PER_TARGET] [TARGET...]   (default: 30 s, every target)
# Environment: HOLEBENCH_FUZZ_JOBS, targets run at once (default: the number of cores);
# HOLEBENCH_FUZZ_SEED, libFuzzer's random seed (default 1: a run from the committed seeds
# mutates the same way on every machine, a faster machine only getting further).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
fuzz_seed="${HOLEBENCH_FUZZ_SEED:-1}"
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(mesh_off mesh_obj mesh_stl mesh_ply brep_step brep_iges brep_brep suite results
           case_pattern)
fi
cmake --preset fuzz > /dev/null
cmake --build --preset fuzz -j "$(nproc)"
mkdir -p build/fuzz/logs build/fuzz/findings build/fuzz/corpus

# Runs a fuzzer with a bound from outside: SIGKILL to it and every process it started (its
# process group) past the fuzzing time plus a grace period.
grace=90
bounded() {
  timeout -s KILL $((seconds + grace)) "$@"
}

run_target() {
  local target="$1"
  local binary="build/fuzz/tests/fuzz/fuzz_${target}"
  local corpus="build/fuzz/corpus/${target}"  # grows as the fuzzer finds inputs; seeds copied
  local findings="build/fuzz/findings/${target}"
  mkdir -p "$corpus" "$findings"
  cp -n tests/fuzz/corpus/"${target}"/* "$corpus"/ 2>/dev/null || true
  local log="build/fuzz/logs/${target}.log"
  case "$target" in
    brep_*)
      # OpenCASCADE crashes on some damaged files (a null handle); holebench reads B-Rep files
      # in a child process for that reason. Here OpenCASCADE runs in-process, so that its
      # coverage guides the fuzzer, in fork mode, which goes on after a crash; every crash is
      # then replayed through holebench's isolated reader, where it must be an error. Leaks
      # are not findings: OpenCASCADE keeps caches it never frees.
      # libFuzzer's own timeout handler can deadlock in ASan's allocator when an input keeps
      # OpenCASCADE allocating (seen: BRepTools::Read of a damaged BREP file), so the run is
      # bounded from outside too; the isolated reader has its own time limit for such files.
      local status=0
      bounded "$binary" "$corpus" -fork=1 -ignore_crashes=1 -max_total_time="$seconds" \
        -seed="$fuzz_seed" -timeout=20 -rss_limit_mb=2048 -max_len=65536 -detect_leaks=0 \
        -artifact_prefix="$findings/" -print_final_stats=1 > "$log" 2>&1 || status=$?
      if [ "$status" -eq 137 ]; then
        echo "stopped after $((seconds + grace)) s: a fuzzing process hung in OpenCASCADE" >> "$log"
      fi
      local contained=0
      for input in "$findings"/crash-* "$findings"/oom-* "$findings"/timeout-*; do
        [ -e "$input" ] || continue
        if HOLEBENCH_FUZZ_ISOLATED=1 bounded "$binary" -detect_leaks=0 -timeout=60 "$input" \
          >> "$log.replay" 2>&1; then
          contained=$((contained + 1))
        else
          echo "not contained by the isolated reader: $input" >> "$log"
          return 1
        fi
      done
      echo "OpenCASCADE crashes found and contained by the isolated reader: $contained" >> "$log"
      ;;
    *)
      # A hang past the bound is a finding like a crash (the input is not saved then: run the
      # target on build/fuzz/corpus/<target>/ with -timeout to find it).
      bounded "$binary" "$corpus" -max_total_time="$seconds" -seed="$fuzz_seed" -timeout=20 \
        -rss_limit_mb=2048 -max_len=65536 -artifact_prefix="$findings/" -print_final_stats=1 \
        > "$log" 2>&1
      ;;
  esac
}

failed=()
pids=()
jobs_at_once="${HOLEBENCH_FUZZ_JOBS:-$(nproc)}"
for target in "${targets[@]}"; do
  run_target "$target" &
  pids+=("$!:$target")
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_at_once" ]; do sleep 0.5; done
done
for entry in "${pids[@]}"; do
  pid="${entry%%:*}"
  target="${entry#*:}"
  wait "$pid" || failed+=("$target")
done

# The summary: the last status line of each run (#N executions, cov: edges, ft: features).
for target in "${targets[@]}"; do
  log="build/fuzz/logs/${target}.log"
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  runs=$(grep -E 'stat::number_of_executed_units' "$log" | awk '{print $2}' || true)
  contained=$(grep -oE 'contained by the isolated reader: [0-9]+' "$log" | grep -oE '[0-9]+$' || true)
  printf '%-14s executions %-9s %s%s\n' "$target" "${runs:-$(echo "$last" | grep -oE '^#[0-9]+' | tr -d '#')}" \
    "$(echo "$last" | grep -oE 'cov: [0-9]+ ft: [0-9]+' || true)" \
    "${contained:+  (OpenCASCADE crashes contained: $contained)}"
done
if [ ${#failed[@]} -gt 0 ]; then
  for target in "${failed[@]}"; do
    echo "run_fuzz.sh: fuzz_${target} found a problem: build/fuzz/logs/${target}.log, input in build/fuzz/findings/${target}/" >&2
    grep -m3 -E 'ERROR|SUMMARY|runtime error' "build/fuzz/logs/${target}.log" >&2 || true
  done
  exit 1
fi
echo "run_fuzz.sh: ${#targets[@]} targets, ${seconds} s each, no finding"
