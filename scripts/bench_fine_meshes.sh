#!/usr/bin/env bash
# scripts/bench_fine_meshes.sh [--quick | --scale MODELS] [--threads T] [--repeat K] [--only REGEX]
#                              [--budget MINUTES] [--cgal K] [--force] OUT_DIR
#
# What: the default run, `meshparticles run MESH -n N` (method spread), on fine meshes against
# MeshLab's vertex Poisson-disk sampling (pymeshlab generate_sampling_poisson_disk(samplenum=n,
# exactnumflag=True, subsample=True)), and issue 35's targets for each case:
#   time     the whole default run (wall time of the process) at most 5x MeshLab's filter call
#   memory   peak memory of the run at most 1 GiB at 200k / 4,096 and 4 GiB at 1M / 4,096
#   cv       nn_cv at most 0.8x MeshLab's
#   rho      rho at least MeshLab's + 0.05
#   cover    cover at most MeshLab's
# (nn_cv, rho = nn_min / d_hex, cover = covering radius / d_hex, all from `meshparticles
# quality`, docs/QUALITY.md).
#
# Why: on a fine mesh spread needs no refinement and MeshLab's vertex sampler has plenty of
# vertices to choose from, so this is where the peer is at its strongest and our run at its
# costliest; the committed meshes (scripts/compare_samplers.py) do not show it.
#
# Cases (mesh, then n):
#   default  generated sphere and atrium (`meshparticles generate sphere|atrium --vertices V`) at
#            V = 100k, 200k (198,812) and 1M (998,562), and the --cgal K (default 4) largest meshes
#            of Debian's libcgal-demo (found and unpacked as `compare_samplers.py --corpus` does),
#            each subdivided by uniform midpoint rounds (pymeshlab
#            meshing_surface_subdivision_midpoint, threshold 0, in the peer venv: the CLI has no
#            refinement output) until it has at least 200,000 vertices; n = 64, 256, 1024, 4096;
#            the generated meshes first (smallest first), then the CGAL ones
#   --quick  the generated meshes at 100k and 200k only, n = 256 and 4096 (8 cases, about 4 min
#            on 2 cores)
#   --scale MODELS  issue 58's scale rows instead: a 35k-vertex scan at 4,096 (CGAL's bunny00,
#            37,706 vertices), a 134k-vertex scan at 20,000 (MODELS/data/igea.ply, from a clone of
#            github.com/alecjacobson/common-3d-test-models; 134,345 vertices) and the generated
#            1M sphere at 100,000; memory limits 1 GiB (the scan) and 4 GiB (1M)
#   --threads T  ours with `--threads T` (0: every core, the default); the labels end in -tT
#
# How: per case, one call of scripts/compare_samplers.py MESH -n N --vertex-only --no-farthest
# --no-warmup --repeat K (default K = 1): ours (the whole `run`, wall time and the process's peak
# memory from wait4, like bench_device.sh's `timed`), then MeshLab's filter, alternating K times
# in the same session, then both samples measured by `meshparticles quality` (at --cutoff 3 on the
# 1M meshes at 100,000, where its default balls of 7 spacings would ask 27 GiB). Times in the table
# are the fastest of the K repetitions, and the ratio is ours' fastest over MeshLab's fastest.
# The binary is copied to WORK first, so that a rebuild during the benchmark cannot mix two.
#
# Output: OUT_DIR/cases/CASE.json (compare_samplers.py's JSON plus a "bench" block: the figures
# of the table and the target verdicts), OUT_DIR/cases/CASE.report.json (our run's report.json),
# OUT_DIR/summary.md (the Markdown table and the targets, also printed to stdout at the end).
# Progress goes to stderr. Resumable: a case whose JSON was made by the same binary with the same
# K is kept, not run again (--force runs everything again). --only REGEX runs the cases whose
# label (e.g. atrium-200k-n4096, refined_elephant-x2-n64) matches; --budget MINUTES starts no
# case after that many minutes (those are listed as not run). Run one at a time: every case is
# timed, and the machine's other load shows in the times (the load average is in each JSON).
#
# Environment: MESHPARTICLES_BINARY (default build/meshparticles), WORK (the generated and
# subdivided meshes, the copied binary; default /tmp/meshparticles_bench_fine),
# MESHPARTICLES_PEER_VENV (MeshLab's venv, as for compare_samplers.py, made on first use).
# Exit status: 0; 1 when a case failed (its row says why); 2 bad arguments or set-up.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
COMPARE="$ROOT/scripts/compare_samplers.py"
export PYTHONDONTWRITEBYTECODE=1  # importing compare_samplers below leaves nothing in scripts/

usage() {
  echo "usage: $0 [--quick | --scale MODELS] [--threads T] [--repeat K] [--only REGEX] [--budget MINUTES] [--cgal K] [--force] OUT_DIR" >&2
  exit 2
}
quick=0 scale='' threads='' repeat=1 only=. budget='' cgal=4 force=0 out=''
while (($#)); do
  case "$1" in
    --quick) quick=1 ;;
    --scale) scale=${2:?}; shift ;;
    --threads) threads=${2:?}; shift ;;
    --repeat) repeat=${2:?}; shift ;;
    --only) only=${2:?}; shift ;;
    --budget) budget=${2:?}; shift ;;
    --cgal) cgal=${2:?}; shift ;;
    --force) force=1 ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) usage ;;
    *) [ -z "$out" ] || usage; out=$1 ;;
  esac
  shift
done
[ -n "$out" ] || usage
[[ $repeat =~ ^[1-9][0-9]*$ && $cgal =~ ^[0-9]+$ && $budget =~ ^[0-9]*$ && $threads =~ ^[0-9]*$ ]] || usage
((quick == 0)) || [ -z "$scale" ] || usage

progress() { echo "bench_fine_meshes: $*" >&2; }
die() { progress "error: $*"; exit 2; }

work=${WORK:-/tmp/meshparticles_bench_fine}
source_bin=${MESHPARTICLES_BINARY:-$ROOT/build/meshparticles}
[ -x "$source_bin" ] || die "$source_bin: no meshparticles binary (build first: cmake --build build)"
mkdir -p "$out/cases" "$work/bin" "$work/generated" "$work/cgal"
out=$(realpath "$out") work=$(realpath "$work")
bin="$work/bin/meshparticles"
cp "$source_bin" "$bin.new" && mv "$bin.new" "$bin"
"$bin" info "$ROOT/meshes/sphere.off" > /dev/null || die "$bin: the copied binary does not run"
binary_sha=$(sha256sum "$bin" | cut -c1-16)
progress "binary $source_bin (sha256 $binary_sha..., copied to $bin); results in $out"

# generated KIND VERTICES: the path of that generated mesh, made once per WORK folder.
generated() {
  local folder="$work/generated/$1_$2"
  ls "$folder"/*.off > /dev/null 2>&1 || "$bin" generate "$1" --vertices "$2" --out-dir "$folder" >&2
  ls "$folder"/*.off
}

# compare_samplers PYTHON-EXPRESSION: evaluated with compare_samplers.py imported as c (its
# corpus and peer venv helpers), printed.
compare_samplers() {
  python3 -c "import sys; sys.path.insert(0, '$ROOT/scripts'); import compare_samplers as c; print($1)"
}

# subdivided MESH: MESH after uniform midpoint rounds up to 200,000 vertices, made once per WORK.
subdivided() {
  local stem made
  stem=$(basename "${1%.*}")
  made=$(find "$work/cgal" -name "${stem}_x*.off" | head -1)
  if [ -z "$made" ]; then
    progress "subdividing $(basename "$1") (pymeshlab midpoint rounds up to 200,000 vertices)"
    made=$("$peer" - "$1" "$work/cgal/$stem" 200000 << 'EOF'
import sys
import pymeshlab
source, stem, minimum = sys.argv[1], sys.argv[2], int(sys.argv[3])
meshes = pymeshlab.MeshSet()
meshes.load_new_mesh(source)
rounds = 0
while meshes.current_mesh().vertex_number() < minimum:
    # threshold 0: every edge is split, one round makes each triangle four
    meshes.meshing_surface_subdivision_midpoint(iterations=1, threshold=pymeshlab.PercentageValue(0))
    rounds += 1
path = f"{stem}_x{rounds}.off"
meshes.save_current_mesh(path, save_vertex_normal=False)
print(path)
EOF
    )
  fi
  echo "$made"
}

# The plan: one line per case, tab-separated: label, mesh file, n, memory limit in bytes (or -),
# where the mesh comes from, quality's --cutoff (or -: its default).
plan="$out/plan.tsv"
: > "$plan"
GiB=1073741824
add_cases() {  # MESH_LABEL MESH SOURCE N...
  local name=$1 mesh=$2 source=$3 n limit cutoff
  shift 3
  for n in "$@"; do
    limit=- cutoff=-
    [[ $name == *-200k && $n == 4096 ]] && limit=$GiB
    [[ $name == *-1m && $n == 4096 ]] && limit=$((4 * GiB))
    [[ $name == scan-134k && $n == 20000 ]] && limit=$GiB
    # quality's default balls of 7 spacings would ask 27 GiB there
    [[ $name == *-1m && $n == 100000 ]] && limit=$((4 * GiB)) cutoff=3
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name-n$n${threads:+-t$threads}" "$mesh" "$n" "$limit" "$source" "$cutoff" \
      >> "$plan"
  done
}
if [ -n "$scale" ]; then
  [ -f "$scale/data/igea.ply" ] || die "$scale/data/igea.ply: not there (git clone https://github.com/alecjacobson/common-3d-test-models)"
  bunny=$(compare_samplers "c.corpus_directory() / 'bunny00.off'")
  [ -f "$bunny" ] || die "$bunny: not there (CGAL's meshes: scripts/cgal_meshes.sh unpacks them)"
  add_cases scan-35k "$bunny" "CGAL bunny00.off (a 35k-vertex scan)" 4096
  add_cases scan-134k "$scale/data/igea.ply" "igea.ply (a 134k-vertex scan), common-3d-test-models" 20000
  add_cases sphere-1m "$(generated sphere 1000000)" "generate sphere --vertices 1000000" 100000
  counts=() large=() cgal=0
elif ((quick)); then
  counts=(256 4096) large=() cgal=0
else
  counts=(64 256 1024 4096) large=(1000000)
fi
peer=$(compare_samplers "c.peer_venv_python()")
for size in ${counts[@]:+100000 200000}; do
  for kind in sphere atrium; do
    add_cases "$kind-$((size / 1000))k" "$(generated $kind "$size")" "generate $kind --vertices $size" "${counts[@]}"
  done
done
for size in "${large[@]}"; do
  for kind in sphere atrium; do
    add_cases "$kind-1m" "$(generated $kind "$size")" "generate $kind --vertices $size" "${counts[@]}"
  done
done
if ((cgal > 0)); then
  # The corpus as compare_samplers.py --corpus finds it (every mesh `info` accepts), largest first.
  mapfile -t largest < <(compare_samplers "'\n'.join(str(mesh) for mesh, vertices in sorted(
    c.corpus_cases(c.Path('$bin'), [1], None, None), key=lambda case: -case[1])[:$cgal])")
  for mesh in "${largest[@]}"; do
    fine=$(subdivided "$mesh")
    rounds=${fine##*_x} rounds=${rounds%.off}
    add_cases "$(basename "${mesh%.*}")-x$rounds" "$fine" \
      "CGAL $(basename "$mesh"), $rounds midpoint rounds (pymeshlab)" "${counts[@]}"
  done
fi
awk -F'\t' -v only="$only" '$1 ~ only' "$plan" > "$plan.only"
mv "$plan.only" "$plan"
total=$(wc -l < "$plan")
((total > 0)) || die "no case matches --only '$only'"
progress "$total cases; $repeat timing repetition(s) each; budget ${budget:-none} min"

# case_json LABEL MESH N LIMIT SOURCE STATUS LOAD_BEFORE: OUT_DIR/cases/LABEL.json from
# compare_samplers.py's JSON and our run's report.json (both under $scratch).
case_json() {
  python3 - "$out" "$scratch" "$binary_sha" "$repeat" "$@" << 'EOF'
import json, os, sys, time
from pathlib import Path
out, scratch, binary_sha, repeat, label, mesh, n, limit, source, status, load_before = sys.argv[1:]
scratch = Path(scratch)
try:
    compared = json.loads((scratch / "compare.json").read_text())
except (OSError, ValueError):
    compared = {"rows": [], "checks": []}
rows = {row["kind"]: row for row in compared["rows"]}
ours, meshlab = rows.get("ours", {}), rows.get("meshlab", {})
check = (compared["checks"] or [{}])[0]
report_path = next(scratch.glob("keep/*/n*/ours-0/report.json"), None)
report = json.loads(report_path.read_text()) if report_path else {}
if report:
    (Path(out) / "cases" / f"{label}.report.json").write_text(json.dumps(report, indent=1) + "\n")
errors = [row["error"] for row in compared["rows"] if "error" in row]
if status != "0" and not errors:
    errors.append(f"compare_samplers.py exited {status}")
if not compared["rows"]:
    errors.append("no rows")

def fastest(row, key):
    values = [x for x in row.get(key, []) if x is not None]
    return min(values) if values else None

def quality(row):
    return {key: row.get("quality", {}).get(key) for key in ("nn_cv", "rho", "cover")}

ours_s, meshlab_s = fastest(ours, "seconds"), fastest(meshlab, "seconds")
peak = max(ours.get("peak_rss_bytes") or [0]) or None
ratio = ours_s / meshlab_s if ours_s and meshlab_s else None
sweeps = report.get("sweeps", [])
seconds = report.get("seconds", {})
passes = check.get("pass", {})
bench = {
    "label": label, "mesh": mesh, "source": source, "n": int(n), "vertices": ours.get("vertices"),
    "binary_sha256": binary_sha, "repeat": int(repeat), "ran_at": time.strftime("%Y-%m-%d %H:%M:%S"),
    "loadavg_before": float(load_before), "loadavg_after": float(open("/proc/loadavg").read().split()[0]),
    "ours_seconds": ours.get("seconds"), "ours_peak_rss_bytes": ours.get("peak_rss_bytes"),
    "report_seconds": seconds, "working_mesh": report.get("working_mesh"),
    "sweeps": len(sweeps), "sweeps_seconds": sum(s["ms"] for s in sweeps) / 1000, "stopped": report.get("stopped"),
    "meshlab_seconds": meshlab.get("seconds"), "meshlab_load_seconds": meshlab.get("load_seconds"),
    "meshlab_points": meshlab.get("points"), "pymeshlab": compared.get("pymeshlab"),
    "ours_quality": quality(ours), "meshlab_quality": quality(meshlab),
    "ratio": ratio, "memory_limit_bytes": None if limit == "-" else int(limit),
    "cv_ratio": check.get("cv_ratio"), "rho_gain": check.get("rho_gain"),
    "targets": {
        "time": None if ratio is None else ratio <= 5,
        "memory": None if limit == "-" or peak is None else peak <= int(limit),
        "cv": passes.get("cv_ratio"), "rho": passes.get("rho_gain"), "cover": passes.get("cover_vs_meshlab"),
    },
    "errors": errors,
}
compared["bench"] = bench
(Path(out) / "cases" / f"{label}.json").write_text(json.dumps(compared, indent=1) + "\n")
EOF
}

# reusable JSON: made by this binary with this many repetitions, without errors.
reusable() {
  ((force == 0)) && [ -f "$1" ] && python3 - "$1" "$binary_sha" "$repeat" << 'EOF'
import json, sys
bench = json.load(open(sys.argv[1])).get("bench", {})
sys.exit(0 if bench.get("binary_sha256") == sys.argv[2] and bench.get("repeat") == int(sys.argv[3])
         and not bench.get("errors") else 1)
EOF
}

failed=0 index=0
: > "$out/not_run.txt"
while IFS=$'\t' read -r label mesh n limit source cutoff; do
  index=$((index + 1))
  json="$out/cases/$label.json"
  if reusable "$json"; then
    progress "[$index/$total] $label: kept from an earlier run ($json)"
    continue
  fi
  if [ -n "$budget" ] && ((SECONDS >= budget * 60)); then
    progress "[$index/$total] $label: not run, past the budget of $budget min"
    echo "$label" >> "$out/not_run.txt"
    continue
  fi
  progress "[$index/$total] $label: $source, n = $n (at $((SECONDS / 60)) min)"
  scratch=$(mktemp -d "$work/case.XXXXXX")
  load_before=$(cut -d' ' -f1 /proc/loadavg)
  status=0
  quality_cutoff=${cutoff#-}
  python3 "$COMPARE" "$mesh" -n "$n" --vertex-only --no-farthest --no-warmup --repeat "$repeat" \
    ${threads:+--ours-args "--threads $threads"} ${quality_cutoff:+--quality-cutoff $quality_cutoff} --binary "$bin" --json "$scratch/compare.json" --keep "$scratch/keep" > "$scratch/compare.txt" || status=$?
  case_json "$label" "$mesh" "$n" "$limit" "$source" "$status" "$load_before"
  rm -rf "$scratch"
  if ((status != 0)); then
    failed=1
    progress "[$index/$total] $label: compare_samplers.py exited $status (see $json)"
  fi
done < "$plan"

# The summary: every planned case, in the plan's order, from its JSON.
python3 - "$out" "$plan" "$(nproc)" > "$out/summary.md" << 'EOF'
import json, sys
from pathlib import Path
out, plan, cores = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
not_run = set((out / "not_run.txt").read_text().split())
TARGETS = [("time", "whole run <= 5x MeshLab"), ("memory", "peak <= 1 GiB (200k/4096), 4 GiB (1M/4096)"),
           ("cv", "nn_cv <= 0.8x MeshLab"), ("rho", "rho >= MeshLab + 0.05"), ("cover", "cover <= MeshLab")]

def f(x, pattern):
    return "–" if x is None else format(x, pattern)

def pair(a, b, key, pattern):
    return f"{f(a.get(key), pattern)} / {f(b.get(key), pattern)}"

lines = ["| case | V | n | working V | ours s | particles (sweeps) + quality s | peak MB | MeshLab s (+ load) "
         "| ours / MeshLab | nn_cv ours / ML | rho ours / ML | cover ours / ML | misses |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
tally = {name: {"met": 0, "missed": []} for name, _ in TARGETS}
loads, versions, missing = [], set(), []
for line in open(plan):
    label, mesh, n, limit, source, cutoff = line.rstrip("\n").split("\t")
    path = out / "cases" / f"{label}.json"
    if not path.exists():
        missing.append(label)
        why = "not run (past the budget)" if label in not_run else "not run"
        lines.append(f"| {label} | | {n} | {why} | | | | | | | | | |")
        continue
    b = json.loads(path.read_text())["bench"]
    if b["errors"]:
        lines.append(f"| {label} | {b['vertices']} | {n} | FAILED: {'; '.join(b['errors'])} | | | | | | | | | |")
        continue
    loads += [b["loadavg_before"], b["loadavg_after"]]
    versions.add(b["pymeshlab"])
    s, w = b["report_seconds"], b["working_mesh"] or {}
    peak = max(b["ours_peak_rss_bytes"] or [0])
    ours_s, ml_s = min(b["ours_seconds"]), min(b["meshlab_seconds"])
    misses = []
    for name, _ in TARGETS:
        ok = b["targets"][name]
        if ok is None:
            continue
        if ok:
            tally[name]["met"] += 1
            continue
        figure = {"time": f"{b['ratio']:.2f}x", "memory": f"{peak / 2**30:.2f} GiB",
                  "cv": f"{b['cv_ratio']:.2f}x", "rho": f"{b['rho_gain']:+.3f}",
                  "cover": f"{b['ours_quality']['cover']:.3f} > {b['meshlab_quality']['cover']:.3f}"}[name]
        tally[name]["missed"].append(f"{label} {figure}")
        misses.append(f"{name} {figure}")
    n_cell = n if b["meshlab_points"] in (None, int(n)) else f"{n} (ML {b['meshlab_points']})"
    working = w.get("vertices")
    rounds = w.get("refinement_rounds")
    working_cell = "–" if working is None else f"{working}" + (f", {rounds} round{'s' * (rounds > 1)}" if rounds else "")
    ml_load = min((x for x in b["meshlab_load_seconds"] or [] if x is not None), default=None)
    lines.append(
        f"| {label} | {b['vertices']} | {n_cell} | {working_cell} | {ours_s:.2f} "
        f"| {s.get('particles', 0):.2f} ({b['sweeps_seconds']:.2f}, {b['sweeps']}) + {s.get('quality', 0):.2f} "
        f"| {peak / 1e6:.0f} | {ml_s:.2f} (+ {f(ml_load, '.2f')}) | {f(b['ratio'], '.2f')} "
        f"| {pair(b['ours_quality'], b['meshlab_quality'], 'nn_cv', '.4f')} "
        f"| {pair(b['ours_quality'], b['meshlab_quality'], 'rho', '.3f')} "
        f"| {pair(b['ours_quality'], b['meshlab_quality'], 'cover', '.3f')} | {', '.join(misses) or '–'} |")
print("\n".join(lines))
print()
print("| target | met | missed | where missed |")
print("|---|---|---|---|")
for name, text in TARGETS:
    t = tally[name]
    print(f"| {name}: {text} | {t['met']} | {len(t['missed'])} | {'; '.join(t['missed']) or '–'} |")
print()
print(f"{cores} cores; pymeshlab {', '.join(sorted(v for v in versions if v)) or '?'}; "
      f"load average {f(min(loads, default=None), '.2f')} to {f(max(loads, default=None), '.2f')} around the cases; "
      "n (ML k): MeshLab's sample had k points, measured as k; times: the fastest repetition (each case's JSON has them all); MeshLab: the filter call alone, "
      "its mesh load beside it; particles (sweeps): report.json's seconds.particles, and of it the "
      "sweeps' time and count.")
if missing:
    print(f"not run: {', '.join(missing)}")
EOF
cat "$out/summary.md"
progress "wrote $out/summary.md"
exit $failed
