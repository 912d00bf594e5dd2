#!/usr/bin/env bash
# bench_device.sh OUT_DIR [STAGE ...]: the figures docs/PERFORMANCE.md records for one OpenCL
# device (a GPU in production), in one go. STAGE is any of:
#   paper  the paper's kernels swept over work-group and tile sizes (sphere, n = 1024), then
#          `bench` of every backend with the best sizes, and the field kernel's work-group sweep
#   large  issue 16's sizes on local distances: atrium/1024 from cold (local and dense), the
#          generated 100k atrium (n = 10,000), and the generated sphere at 10k, 100k and 1M
#          vertices (V/n = 10, cutoff 5, and the 1M one also at the default cutoff 7), each on
#          field and on serial-field
# (default: both). The device is $MESHPARTICLES_DEVICE, else the first GPU. Every run writes its
# report.json under OUT_DIR; summary.txt gets one line per run: wall seconds, peak memory of the
# process, iterations, the slowest iteration after the first, energy and the distance store.
# MESHPARTICLES=path/to/binary (default build/meshparticles); WORK=scratch folder for the
# generated meshes (default /tmp/meshparticles_bench_device); ONLY=a regular expression: the
# runs of `large` whose labels it matches (default all).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out=${1:?usage: bench_device.sh OUT_DIR [paper|large ...]}
shift
stages=("${@:-paper large}")
bin=${MESHPARTICLES:-$ROOT/build/meshparticles}
work=${WORK:-/tmp/meshparticles_bench_device}
mkdir -p "$out" "$work"
out=$(realpath "$out") work=$(realpath "$work") bin=$(realpath "$bin")  # before the cd below
summary="$out/summary.txt"
cd "$ROOT"  # the committed meshes and scripts/plot_sweep.py

# timed LABEL COMMAND...: runs it, appends wall time and peak memory (of the command and its
# children, from getrusage) to summary.txt; a failure is written down, not fatal.
timed() {
  local label=$1
  shift
  python3 - "$summary" "$label" "$@" << 'EOF'
import resource, subprocess, sys, time
summary, label, command = sys.argv[1], sys.argv[2], sys.argv[3:]
start = time.monotonic()
code = subprocess.call(command)
seconds = time.monotonic() - start
peak_gb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1e6
line = f"{label}: {seconds:.2f} s, peak {peak_gb:.2f} GB" + ("" if code == 0 else f", FAILED (exit {code})")
print(line, file=sys.stderr)
open(summary, "a").write(line + "\n")
EOF
}

# run_case LABEL MESH ARGS...: one `run` into OUT_DIR/LABEL, then what its report says.
run_case() {
  local label=$1 mesh=$2
  shift 2
  [[ $label =~ ${ONLY:-.} ]] || return 0
  timed "$label" "$bin" run "$mesh" --no-cache --out "$out/$label" -q "$@"
  [ -f "$out/$label/report.json" ] || return 0
  python3 - "$out/$label/report.json" >> "$summary" << 'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
d, s, ms = r["distances"], r["seconds"], [t["ms"] for t in r["trace"]]
print(f"    {r['device']}; {d['store']} distances", end="")
if d["store"] == "local":
    print(f" (cutoff {d['cutoff']}, {d['balls_computed']} balls of {d['mean_ball_size']:.0f}, "
          f"{d['peak_ball_bytes'] / 1e9:.2f} GB)", end="")
print(f"; geodesics {s['geodesics']:.2f} s, particles {s['particles']:.2f} s, "
      f"quality {s['quality']:.2f} s; {r['iterations_run']} iterations, first {ms[0] if ms else 0:.0f} ms, "
      f"slowest after it {max(ms[1:], default=0):.0f} ms, "
      f"{sum('redone_as' in t for t in r['trace'])} redone; energy {r['final_energy']:.9g}")
EOF
}

# generated KIND VERTICES: the path of that generated mesh, made once per WORK folder.
generated() {
  local folder="$work/$1_$2"
  ls "$folder"/*.off > /dev/null 2>&1 || "$bin" generate "$1" --vertices "$2" --out-dir "$folder" >&2
  ls "$folder"/*.off
}

echo "device: $("$bin" devices 2>&1 | grep -m1 selected)" | tee -a "$summary"

for stage in ${stages[*]}; do
  case $stage in
  paper)
    timed sweep_paper "$bin" sweep -n 1024 --kernel naive,tiled --wg 8,16,32,64,128,256 \
      --tile 32,64,128,256,512 --iterations 40 --save --tuning-file "$out/tuning.json" \
      --csv "$out/sweep.csv" --json "$out/sweep.json" -q
    timed bench "$bin" bench --backend serial,naive,tiled,field,serial-field --iterations 100 \
      --tuning-file "$out/tuning.json" --csv "$out/bench.csv" --json "$out/bench.json" -q
    timed sweep_field "$bin" sweep -n 1024 --kernel field --wg 1,4,16,32,64,128,256,512,1024 \
      --iterations 40 --csv "$out/sweep_field.csv" --json "$out/sweep_field.json" -q
    python3 scripts/plot_sweep.py "$out/sweep.json" "$out/bench.json" --out "$out" || true
    ;;
  large)
    for r in 1 2 3; do
      for b in field serial-field; do
        run_case "atrium1024_local_${b}_$r" meshes/atrium.off -n 1024 --distances local --backend $b
      done
      run_case "atrium1024_dense_field_$r" meshes/atrium.off -n 1024 --distances dense --backend field
    done
    atrium100k=$(generated atrium 100000)
    sphere10k=$(generated sphere 10000) sphere100k=$(generated sphere 100000) sphere1m=$(generated sphere 1000000)
    for b in field serial-field; do
      run_case "atrium100k_$b" "$atrium100k" -n 10000 --distances local --backend $b
      run_case "sphere10k_c5_$b" "$sphere10k" -n 1000 --distances local --cutoff 5 --backend $b
      run_case "sphere100k_c5_$b" "$sphere100k" -n 10000 --distances local --cutoff 5 --backend $b
      run_case "sphere1m_c5_$b" "$sphere1m" -n 100000 --distances local --cutoff 5 --backend $b
    done
    for b in field serial-field; do
      run_case "sphere1m_c7_$b" "$sphere1m" -n 100000 --distances local --backend $b
    done
    ;;
  *) echo "unknown stage '$stage' (paper or large)" >&2; exit 2 ;;
  esac
done
cat "$summary"
