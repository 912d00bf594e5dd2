#!/usr/bin/env bash
# busy_output.sh MESHPARTICLES SHIM MESHES WORKDIR: a second batch into the
# --out of one in progress is refused in one line (exit 2), and the first
# ends with its own outputs. The first is stopped (SIGSTOP, through
# tests/kill_at_rename_shim.cpp) as it writes its first summary, holding --out.
set -euo pipefail
# Under the sanitizer build, its runtime wants to come first; the shim only wraps rename().
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
bin=$1 shim=$2 meshes=$3 work=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
KILL_AT_RENAME=/summary.csv KILL_AT_RENAME_SIGNAL=STOP LD_PRELOAD="$shim" \
  "$bin" batch "$meshes/tetrahedron.off" -n 4 --out "$work/out" > /dev/null 2> "$work/first.log" &
first=$!
until [ "$(ps -o stat= -p "$first" | cut -c1)" = T ]; do
  kill -0 "$first" 2> /dev/null || fail "the first batch ended before it held --out: $(cat "$work/first.log")"
  sleep 0.05
done
status=0
"$bin" batch "$meshes/tetrahedron.off" -n 3 --out "$work/out" > /dev/null 2> "$work/second.log" || status=$?
kill -CONT "$first"
wait "$first" || fail "the first batch failed after the second was refused: $(cat "$work/first.log")"
[ "$status" -eq 2 ] && [ "$(wc -l < "$work/second.log")" -eq 1 ] || fail "second batch: exit $status: $(cat "$work/second.log")"
grep -q "output directory .*/out is in use by another batch" "$work/second.log" || fail "unclear: $(cat "$work/second.log")"
grep -q '"n": 4' "$work/out/tetrahedron/report.json" || fail "the first batch's output is not its own"
# Once the first has ended, the folder is free again.
"$bin" batch "$meshes/tetrahedron.off" -n 4 -q --out "$work/out" > /dev/null || fail "a batch after the first was refused"
echo "ok: a second batch into a busy --out refused; the first's outputs are its own"
