#!/usr/bin/env bash
# `holebench run` starts itself again with glibc.malloc.hugetlb=1 in GLIBC_TUNABLES where the
# kernel gives transparent huge pages (harness/run/huge_page_heap.h), keeps a value the user
# set, and adds to the user's other tunables. Seen from inside a job: an external method
# inherits the run's environment and writes the variable down.
#
# Usage: huge_page_heap_run_test.sh HOLEBENCH WORK_DIR
set -euo pipefail
holebench="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work"

cat > "$work/probe.sh" <<'SH'
#!/bin/sh
# An external method that only writes down GLIBC_TUNABLES (and then fails: no output mesh).
printf '%s' "${GLIBC_TUNABLES-unset}" > "$(dirname "$0")/seen"
exit 1
SH
chmod +x "$work/probe.sh"

# The variable a job sees when the run starts with GLIBC_TUNABLES=$1 ("-": unset).
seen_by_a_job() {
  rm -rf "$work/out" "$work/seen"
  local run=("$holebench" run --out "$work/out" --no-cad --case box/edge --method probe
             --external "name=probe;command=$work/probe.sh {input} {output}"
             --no-snapshots --workers 1)
  if [ "$1" = "-" ]; then
    env -u GLIBC_TUNABLES "${run[@]}" > /dev/null 2>&1
  else
    GLIBC_TUNABLES="$1" "${run[@]}" > /dev/null 2>&1
  fi
  cat "$work/seen"
}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

mode="$(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null || true)"
case "$mode" in
  *"[always]"* | *"[madvise]"*) allowed=1 ;;
  *) allowed=0 ;;
esac
echo "transparent huge pages: ${mode:-no such file}"

got="$(seen_by_a_job -)"
if [ "$allowed" = 1 ]; then
  [ "$got" = "glibc.malloc.hugetlb=1" ] || fail "unset: a job saw '$got'"
else
  [ "$got" = "unset" ] || fail "huge pages not allowed, yet a job saw '$got'"
fi

got="$(seen_by_a_job glibc.malloc.hugetlb=0)"
[ "$got" = "glibc.malloc.hugetlb=0" ] || fail "the user's own hugetlb=0: a job saw '$got'"

got="$(seen_by_a_job glibc.malloc.check=0)"
if [ "$allowed" = 1 ]; then
  [ "$got" = "glibc.malloc.check=0:glibc.malloc.hugetlb=1" ] || fail "another tunable: a job saw '$got'"
else
  [ "$got" = "glibc.malloc.check=0" ] || fail "another tunable: a job saw '$got'"
fi
echo "ok"
