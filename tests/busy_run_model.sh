#!/usr/bin/env bash
# busy_run_model.sh MESHPARTICLES SHIM MESHES WORKDIR: a second `run` (and a
# second `model`) into the --out of one in progress is refused in one line
# (exit 2), and the first ends with its own outputs; both once ended with
# exit 0. The first is stopped (SIGSTOP, through tests/kill_at_rename_shim.cpp)
# just before it puts its set in place, holding --out.
set -euo pipefail
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
bin=$1 shim=$2 meshes=$3 work=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"

# busy NAME ARGS-OF-THE-FIRST -- ARGS-OF-THE-SECOND: the first stopped as it
# renames its set onto $work/NAME, the second run meanwhile.
busy() {
  local name=$1 first second=() status=0
  shift
  local args=()
  while [ "$1" != "--" ]; do args+=("$1"); shift; done
  shift
  second=("$@")
  KILL_AT_RENAME="/$name" KILL_AT_RENAME_WHEN=before KILL_AT_RENAME_SIGNAL=STOP LD_PRELOAD="$shim" \
    "$bin" "${args[@]}" --out "$work/$name" > /dev/null 2> "$work/$name.first.log" &
  first=$!
  until [ "$(ps -o stat= -p "$first" | cut -c1)" = T ]; do
    kill -0 "$first" 2> /dev/null || fail "the first ${args[0]} ended before it held --out: $(cat "$work/$name.first.log")"
    sleep 0.05
  done
  "$bin" "${second[@]}" --out "$work/$name" > /dev/null 2> "$work/$name.second.log" || status=$?
  kill -CONT "$first"
  wait "$first" || fail "the first ${args[0]} failed after the second was refused: $(cat "$work/$name.first.log")"
  [ "$status" -eq 2 ] && [ "$(wc -l < "$work/$name.second.log")" -eq 1 ] ||
    fail "second ${args[0]}: exit $status: $(cat "$work/$name.second.log")"
  grep -q "output directory .*/$name is in use by another ${args[0]}" "$work/$name.second.log" ||
    fail "unclear: $(cat "$work/$name.second.log")"
}

busy out run "$meshes/tetrahedron.off" -n 4 -q -- run "$meshes/tetrahedron.off" -n 3 -q
grep -q '"n": 4' "$work/out/report.json" || fail "the first run's output is not its own"
"$bin" run "$meshes/tetrahedron.off" -n 3 -q --out "$work/out" > /dev/null || fail "a run after the first was refused"
grep -q '"n": 3' "$work/out/report.json" || fail "the run after the first did not write its set"
echo "ok: a second run into a busy --out refused; the first's outputs are its own"

printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' > "$work/a.particles"
printf '0 0 0\n2 0 0\n0 1 0\n0 0 1\n' > "$work/b.particles"
printf '0 0 0\n1 0 0\n0 3 0\n0 0 1\n' > "$work/c.particles"
busy model model "$work/a.particles" "$work/b.particles" -q -- model "$work/a.particles" "$work/c.particles" -q
grep -q 'b.particles' "$work/model/model.json" || fail "the first model's output is not its own"
echo "ok: a second model into a busy --out refused; the first's outputs are its own"
