#!/usr/bin/env bash
# quality_commands.sh MESHPARTICLES MESH WORKDIR SCRIPTS: the quality loop
# end to end. run --iterations 0 writes the start with its quality and the
# ParaView files; `quality` on that file (between the input's vertices: a
# spread run's start on its refined mesh) reproduces the report's metrics
# through the same store; `compare` of a file with itself finds zero
# distances both ways; a spread run spreads its start more evenly, a paper
# run lowers the energy it reports; bench --quality tabulates the baselines;
# render.py and plot_trace.py draw them.
set -euo pipefail
bin=$1 mesh=$2 work=$3 scripts=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
json() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

"$bin" run "$mesh" -n 100 --iterations 0 --out "$work/start" -q > "$work/start.txt"
[ "$(json "$work/start/report.json" "d['iterations_run']")" = 0 ] || fail "--iterations 0 ran iterations"
grep -q "^quality     nn min" "$work/start.txt" || fail "run prints no quality line"
for key in nn_min nn_mean nn_cv rho cover energy stacked; do
  [ "$(json "$work/start/report.json" "'$key' in d['quality']")" = True ] || fail "report.json quality lacks $key"
done

# A spread run measures through balls of 1.5 d_hex (docs/ALGORITHM.md).
"$bin" quality "$mesh" "$work/start/particles.particles" --distances local --cutoff 1.5 --json -q > "$work/quality.json"
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
evener=$(/usr/bin/python3 -c "
import json, sys
start, end = (json.load(open(f))['quality'] for f in sys.argv[1:])
print(end['nn_cv'] < start['nn_cv'] and end['rho'] > start['rho'])" "$work/start/report.json" "$work/end/report.json")
[ "$evener" = True ] || fail "the spread run did not spread its start more evenly"
"$bin" run "$mesh" -n 100 --method paper --iterations 0 --out "$work/paper_start" -q > /dev/null
"$bin" run "$mesh" -n 100 --method paper --out "$work/paper_end" -q > /dev/null
lower=$(/usr/bin/python3 -c "
import json, sys
print(json.load(open(sys.argv[2]))['quality']['energy'] < json.load(open(sys.argv[1]))['quality']['energy'])" \
  "$work/paper_start/report.json" "$work/paper_end/report.json")
[ "$lower" = True ] || fail "the paper run did not lower the energy of its start"
[ -s "$work/end/particles.ply" ] && [ -s "$work/end/mesh_distance.vtk" ] || fail "no ParaView files"

"$bin" bench --quality --case torus:64 --backend serial,field --json "$work/bench_quality.json" -q > "$work/bench_quality.txt"
grep -q "^farthest " "$work/bench_quality.txt" || fail "bench --quality has no farthest row"
rows=$(json "$work/bench_quality.json" "[r['placement'] + '/' + str(r['backend']) for r in d['quality_cases'][0]['rows']]")
[ "$rows" = "['random/None', 'farthest/None', 'paper: v0 + sequential/serial', 'default/serial', 'default/field']" ] \
  || fail "bench --quality rows: $rows"
[ "$(json "$work/bench_quality.json" "abs(d['quality_cases'][0]['rows'][4]['energy_vs_serial']) < 0.005")" = True ] \
  || fail "field's energy is not within 0.5% of the serial reference's"

"$scripts/render.py" "$mesh" "$work/start/particles.particles" "$work/end/particles.particles" --out "$work/render.png" > /dev/null
"$scripts/plot_trace.py" "$work/paper_end/report.json" --out "$work/trace.png" > /dev/null
[ -s "$work/render.png" ] && [ -s "$work/trace.png" ] || fail "render.py or plot_trace.py wrote no PNG"
if "$scripts/render.py" "$mesh" "$work/start/report.json" --out "$work/bad.png" 2> "$work/render_error.txt"; then
  fail "render.py accepted a JSON file as particles"
fi
grep -q "not a particle file" "$work/render_error.txt" || fail "render.py: no clear error for a bad particle file"
echo "ok"
