#!/usr/bin/env bash
# scripts/real_meshes.sh [--info-only] [--subset] [--schemes] [--limit V]: the mesh
# readers on real files, the 143 meshes Debian's libcgal-demo ships
# (installed if missing, unpacked under ${XDG_CACHE_HOME:-$HOME/.cache}/meshparticles/).
# For every file: `build/meshparticles info`; then, unless --info-only, a run
# of min(256, V) particles on every mesh of at most V vertices (default: all;
# those over 6,000 vertices run on local distances, the `auto` rule).
# Prints one Markdown row per file: name, vertices, accepted or refused (with
# the reason), the kinds of warning, iterations (spread: sweeps), settled or
# not, seconds. --subset: a
# fixed handful of files for CI (about a minute). --schemes: instead of the
# one run, the default run (field, monotone) and the sequential loop
# (serial-field) from the farthest-point start and from the paper's (v0),
# plus monotone on serial-field and tiled, all on the dense table (so --schemes
# stops at 12,000 vertices unless --limit says otherwise; the table is 0.58 GB
# there): one row per mesh with each run's
# iterations (+ when it stopped at the limit) and its final energy over the
# sequential loop's. Exits 1 when a file other than the expected refusals is
# refused, a run fails, or a default run (--schemes: a monotone run) does not
# converge.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BINARY="${MESHPARTICLES_BINARY:-$ROOT/build/meshparticles}"
info_only=0 subset=0 schemes=0 limit=
while (($#)); do
  case "$1" in
    --info-only) info_only=1 ;;
    --subset) subset=1 ;;
    --schemes) schemes=1 ;;
    --limit) limit="$2"; shift ;;
    *) echo "usage: $0 [--info-only] [--subset] [--schemes] [--limit V]" >&2; exit 2 ;;
  esac
  shift
done
[ -n "$limit" ] || { ((schemes)) && limit=12000 || limit=100000000; }
[ -x "$BINARY" ] || { echo "real_meshes: build first (scripts/test.sh, or cmake --build build)" >&2; exit 2; }

# Files no reader should accept, with why (docs/MESHES.md).
EXPECTED_REFUSALS=(b9.ply)  # a point cloud: its header declares 0 faces
# The CI subset: each reader, each dialect issue 13 named, non-manifold files, the refusal.
SUBSET=(mesh_with_colors.off prim.off cube_poly.off blobby-shuffled.off polygon_mesh.off pig.stl sphere.stl
        colored_tetra.ply sphere.ply b9.ply)

MESHES="$("$ROOT/scripts/cgal_meshes.sh")"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

if ((subset)); then files=("${SUBSET[@]}"); else mapfile -t files < <(ls "$MESHES"); fi

# The kinds of warning a file gave, in a few words each.
warning_kinds() {
  { grep "warning:" "$1" || true; } | sed -E -e 's/.*polygons? with more than 3.*/polygons/' -e 's/.*degenerate.*/degenerate triangles/' \
    -e 's/.*unreferenced.*/unreferenced vertices/' -e 's/.*orientation.*/orientation/' \
    -e 's/.*non-manifold edge.*/non-manifold edges/' -e 's/.*non-manifold vert.*/non-manifold vertices/' \
    -e 's/.*repeated triangle.*/repeated triangles/' -e 's/.*ignored$/content after the faces/' | paste -sd, - | sed 's/,/, /g'
}

json_field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

# schemes_row MESH N: the runs of --schemes, sharing one cached distance table.
schemes_row() {
  local mesh=$1 n=$2 cells="" init backend scheme reference
  for init in farthest v0; do
    for run in "seq serial-field sequential" "default field monotone" "twin serial-field monotone" "tiled tiled monotone"; do
      read -r label backend scheme <<< "$run"
      # One dense table for all four (the device backends need it): the same distances everywhere.
      if ! "$BINARY" run "$mesh" -n "$n" --init "$init" --backend "$backend" --scheme "$scheme" --distances dense \
          --cache-dir "$WORK/cache" --out "$WORK/$label-$init" -q >/dev/null 2>"$WORK/run.err"; then
        unexpected=$((unexpected + 1)); cells+=" RUN FAILED: $(tail -1 "$WORK/run.err") |"; continue
      fi
    done
    reference=$(json_field "$WORK/seq-$init/report.json" final_energy)
    cells+=" $(python3 - "$WORK" "$init" "$reference" <<'PY'
import json, sys
work, init, reference = sys.argv[1], sys.argv[2], float(sys.argv[3])
cells = []
for label in ["seq", "default", "twin", "tiled"]:
    report = json.load(open(f"{work}/{label}-{init}/report.json"))
    iterations = f"{report['iterations_run']}{'' if report['stopped'] == 'converged' else '+'}"
    cells.append(iterations if label == "seq" else f"{iterations}, {report['final_energy'] / reference:.5f}")
print(" | ".join(cells))
PY
) |"
    for label in default twin tiled; do
      [ "$(json_field "$WORK/$label-$init/report.json" stopped)" = converged ] || unexpected=$((unexpected + 1))
    done
  done
  rm -rf "$WORK/cache"
  echo "| $(basename "$mesh") | $vertices | $n |$cells"
}

if ((schemes)); then
  echo "| file | vertices | n | sequential (farthest) | default | serial-field monotone | tiled monotone | sequential (v0) | default | serial-field monotone | tiled monotone |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
else
  echo "| file | vertices | input | warnings | iterations | converged | seconds |"
  echo "|---|---|---|---|---|---|---|"
fi
accepted=0 refused=0 unexpected=0
for name in "${files[@]}"; do
  mesh="$MESHES/$name"
  if "$BINARY" info "$mesh" --json >"$WORK/info.json" 2>"$WORK/info.err"; then
    accepted=$((accepted + 1))
    vertices=$(json_field "$WORK/info.json" vertices)
    warnings=$(warning_kinds "$WORK/info.err")
    input="accepted"
  else
    refused=$((refused + 1))
    reason=$(sed -e 's/^meshparticles: error: //' -e "s|$MESHES/||" "$WORK/info.err" | head -1)
    if [[ " ${EXPECTED_REFUSALS[*]} " != *" $name "* ]]; then unexpected=$((unexpected + 1)); reason="UNEXPECTED: $reason"; fi
    ((schemes)) || echo "| $name | | refused: $reason | | | | |"
    continue
  fi
  iterations="" converged="" seconds=""
  if ((schemes)); then
    ((vertices <= limit)) && schemes_row "$mesh" $((vertices < 256 ? vertices : 256))
    continue
  fi
  if ((!info_only)) && ((vertices <= limit)); then
    particles=$((vertices < 256 ? vertices : 256))
    start=$(date +%s.%N)
    if "$BINARY" run "$mesh" -n "$particles" --out "$WORK/run" --no-cache -q >/dev/null 2>"$WORK/run.err"; then
      seconds=$(python3 -c "print(f'{$(date +%s.%N) - $start:.1f}')")
      iterations=$(json_field "$WORK/run/report.json" iterations_run)
      stopped=$(json_field "$WORK/run/report.json" stopped)
      # Issue 13: every default run settles; one that stops at the limit is a
      # failure. Spread (the default) also settles when a sweep gains next to
      # nothing (stalled) or repeats earlier positions (cycle).
      case "$stopped" in
        converged) converged="yes" ;;
        stalled | cycle) converged="yes ($stopped)" ;;
        *) converged="NOT CONVERGED ($stopped)"; unexpected=$((unexpected + 1)) ;;
      esac
    else
      unexpected=$((unexpected + 1))
      converged="RUN FAILED: $(tail -1 "$WORK/run.err")"
    fi
  elif ((!info_only)); then
    converged="(over $limit vertices: not run)"
  fi
  echo "| $name | $vertices | $input | $warnings | $iterations | $converged | $seconds |"
done
echo
echo "$accepted of ${#files[@]} accepted, $refused refused ($unexpected unexpected)"
((unexpected == 0))
