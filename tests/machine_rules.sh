#!/usr/bin/env bash
# machine_rules.sh MESHPARTICLES SPHERE WORKDIR: what a run decides must not
# hang on the machine's free memory, or where it does, the run says so.
# - `--distances auto` picks the store by the mesh alone: under a tight
#   `ulimit -v` the paper method keeps the dense table and writes the same
#   particles as without it (it took local balls there before).
# - spread's working mesh is capped by half the usable memory: where that cap
#   cuts the asked resolution short, stderr warns and report.json's
#   working_mesh says so (cut_short, vertex_cap_set_by); unlimited, neither.
set -euo pipefail
bin=$1 sphere=$2 work=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
field() { /usr/bin/python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))
for key in sys.argv[2].split("."): r = r[key]
print(r)' "$1" "$2"; }

"$bin" run "$sphere" --method paper --backend serial-field -q --out "$work/free" >/dev/null
(ulimit -v 250000 && exec "$bin" run "$sphere" --method paper --backend serial-field -q --out "$work/tight") >/dev/null
[ "$(field "$work/tight/report.json" distances.store)" = dense ] || fail "auto under ulimit -v: $(field "$work/tight/report.json" distances.store)"
cmp -s "$work/free/particles.particles" "$work/tight/particles.particles" || fail "the paper method's particles differ under ulimit -v"

# The working mesh at 3,000 particles: 57,997 vertices, its cap under 160,000
# KiB about 50,000 (one thread: no second malloc arena to make room for).
"$bin" run "$sphere" -n 3000 --threads 1 --out "$work/spread_free" >/dev/null 2>"$work/spread_free.log"
(ulimit -v 160000 && exec "$bin" run "$sphere" -n 3000 --threads 1 --out "$work/spread_tight") >/dev/null 2>"$work/spread_tight.log"
grep -q "warning: .*sphere.off: the working mesh stops at [0-9]* vertices, short of the resolution asked .*half the memory usable here .*ulimit -v 160000 KiB.*with more memory the particles differ" \
  "$work/spread_tight.log" || fail "no warning of the memory cap: $(cat "$work/spread_tight.log")"
[ "$(field "$work/spread_tight/report.json" working_mesh.cut_short)" = True ] || fail "report.json: not cut short"
field "$work/spread_tight/report.json" working_mesh.vertex_cap_set_by | grep -q "^memory: .*ulimit -v 160000 KiB" ||
  fail "report.json: cap set by $(field "$work/spread_tight/report.json" working_mesh.vertex_cap_set_by)"
! grep -q "warning" "$work/spread_free.log" || fail "a warning without a limit: $(cat "$work/spread_free.log")"
[ "$(field "$work/spread_free/report.json" working_mesh.cut_short)" = False ] || fail "cut short without a limit"
echo "ok"
