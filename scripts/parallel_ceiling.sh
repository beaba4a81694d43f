#!/usr/bin/env bash
# How much of this machine's second core a run gets: the suite run with one worker, with two,
# and as two independent one-worker runs of its two shards side by side, in rounds (each runs
# the three in turn: the machine's speed drifts over minutes). The halves side by side share no
# runner at all, so their speed-up is the machine's own ceiling for two processes; the
# two-worker run's speed-up against it says what the runner costs. Records are not compared
# (the three runs are the same jobs); the outputs go to a temporary folder that is removed.
#   scripts/parallel_ceiling.sh [SUITE] [ROUNDS]      (default: smoke, 3)
set -euo pipefail
cd "$(dirname "$0")/.."
suite="${1:-smoke}"
rounds="${2:-3}"
holebench=build/release/harness/holebench
[ -x "$holebench" ] || { echo "parallel_ceiling.sh: build first (scripts/build.sh release)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

seconds_of() {  # runs "$@" and prints its wall time in seconds
  local start end
  start=$(date +%s.%N)
  "$@"
  end=$(date +%s.%N)
  awk -v s="$start" -v e="$end" 'BEGIN { printf "%.1f", e - s }'
}
run() {  # run OUT WORKERS [SHARD]
  rm -rf "$1"
  "$holebench" run --suite "$suite" --out "$1" --workers "$2" ${3:+--shard "$3"} > /dev/null 2>&1
}
halves() {
  run "$work/h0" 1 0/2 &
  local first=$!
  run "$work/h1" 1 1/2
  wait "$first"
}

echo "| round | 1 worker | 2 workers | halves side by side | 2 workers: speed-up | halves: speed-up |"
echo "| ---: | ---: | ---: | ---: | ---: | ---: |"
for round in $(seq 1 "$rounds"); do
  one=$(seconds_of run "$work/one" 1)
  two=$(seconds_of run "$work/two" 2)
  side=$(seconds_of halves)
  awk -v r="$round" -v a="$one" -v b="$two" -v c="$side" \
    'BEGIN { printf "| %d | %s s | %s s | %s s | %.2fx | %.2fx |\n", r, a, b, c, a / b, a / c }'
done
