#!/usr/bin/env bash
# quality_commands.sh MESHPARTICLES MESH WORKDIR: the quality loop end to end.
# run --iterations 0 writes the start with its quality; `quality` on that
# file reproduces the report's metrics; `compare` of a file with itself finds
# zero distances both ways; a run that iterates lowers the energy it reports.
set -euo pipefail
bin=$1 mesh=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
json() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

"$bin" run "$mesh" -n 100 --iterations 0 --out "$work/start" -q > "$work/start.txt"
[ "$(json "$work/start/report.json" "d['iterations_run']")" = 0 ] || fail "--iterations 0 ran iterations"
grep -q "^quality     nn min" "$work/start.txt" || fail "run prints no quality line"
for key in nn_min nn_mean nn_cv rho cover energy stacked; do
  [ "$(json "$work/start/report.json" "'$key' in d['quality']")" = True ] || fail "report.json quality lacks $key"
done

"$bin" quality "$mesh" "$work/start/particles.particles" --json -q > "$work/quality.json"
same=$(/usr/bin/python3 -c "
import json, sys
report = json.load(open(sys.argv[1]))['quality']; measured = json.load(open(sys.argv[2]))
ok = all(abs(report[k] - measured['quality'][k]) <= 1e-6 * max(1.0, abs(report[k])) for k in ('nn_min', 'nn_mean', 'nn_cv', 'rho', 'cover', 'energy'))
print(ok and measured['n'] == 100 and measured['largest_snap'] < 1e-5)" "$work/start/report.json" "$work/quality.json")
[ "$same" = True ] || fail "quality of the written start differs from the run's report"

"$bin" compare "$mesh" "$work/start/particles.particles" "$work/start/particles.particles" --json -q > "$work/self.json"
[ "$(json "$work/self.json" "d['mean_distance_a_to_b'] == 0 and d['mean_distance_b_to_a'] == 0")" = True ] \
  || fail "a set compared with itself is not at distance 0"

"$bin" run "$mesh" -n 100 --out "$work/end" -q > /dev/null
"$bin" compare "$mesh" "$work/start/particles.particles" "$work/end/particles.particles" -q > "$work/compare.txt"
grep -q "^mean distance to the nearest particle of the other set: A -> B [0-9]" "$work/compare.txt" || fail "compare table"
lower=$(/usr/bin/python3 -c "
import json, sys
print(json.load(open(sys.argv[2]))['quality']['energy'] < json.load(open(sys.argv[1]))['quality']['energy'])" \
  "$work/start/report.json" "$work/end/report.json")
[ "$lower" = True ] || fail "the run did not lower the energy of its start"
echo "ok"
