#!/usr/bin/env bash
# scripts/correspondence_scoreboard.sh OUT_DIR [N...]
#
# What: the correspondence measures of `meshparticles correspond` on every test
# population with a known map, at each N (default 256 512 1024), in one table:
#   - radii, seed 5 and seed 6; the ellipsoid family, seed 5; bent, seed 5
#     and seed 6; bent-either (bent to either side), seed 5
#     (`generate --population 12 --family F --vertices 2000 --seed S`);
#   - FAUST (pose 0 of 10 people, scripts/faust_population.sh) and
#     faust-poses (person 0 in their 10 poses: limbs turned at the joints)
#     where $FAUST_REPO names a copy of llorz/SGA18_orientation_BCICP_dataset;
#     without it, a line says each is skipped (the data is never fetched here).
# One row for each population, N and set of particles: ours (correspond's),
# ZoomOut's (scripts/zoomout_baseline.py) and CPD's (scripts/cpd_baseline.py).
# Each row: the spread of particle i (median / 90th percentile, in particle
# spacings; scripts/correspondence_error.py, FAUST by its map), the worst
# shape's particles' mean offset from particle i's mean place, the shapes
# turned more than 60 degrees from the others (generated families: the
# yardstick's per-shape turn, the largest in brackets), and the evenness,
# each shape by `meshparticles quality MESH FILE --distances local --cutoff 1.5` as
# summary.json measures it: rho (the closest pair over the hexagonal spacing;
# the target is at least 0.7), least / median over the shapes, and cover over
# the same shape's own run's (`meshparticles run MESH -n N`; the target is at
# most 1.15x), median / most.
#
# Stages whose outputs are there are not run again, so an interrupted or
# partial board resumes: OUT_DIR/POPULATION/{shapes,NNNN/...}. CPD is slow
# (pure numpy: about 20 minutes a population at n = 256 on 2 cores);
# SCOREBOARD_CPD=0 does not run it (rows it wrote before stay). ZoomOut runs in
# OUT_DIR/zoomout-venv, made on first use (pip install pyfmaps numpy scipy:
# never into a system Python, never a dependency of the program), about 30 s
# a shape of 5,000 vertices; SCOREBOARD_ZOOMOUT=0 leaves it out. And
# SCOREBOARD_POPULATIONS picks populations (default "radii5 radii6 ellipsoid5
# bent5 bent6 either5 faust faust-poses"). Progress on stderr; the table on stdout and in
# OUT_DIR/scoreboard.md, every figure in OUT_DIR/scoreboard.json.
# Why: the targets of docs/CORRESPONDENCE.md (spread median 0.3 and 90th percentile 0.6, no
# shape over 1 spacing off, rho 0.7, cover 1.15x, better than CPD and ZoomOut) checked on
# every population from one command.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${MESHPARTICLES_BIN:-$here/build/meshparticles}
python=/usr/bin/python3  # Debian's, with numpy
out=${1:?usage: correspondence_scoreboard.sh OUT_DIR [N...]}
shift
ns=("$@")
[ ${#ns[@]} -gt 0 ] || ns=(256 512 1024)
populations=${SCOREBOARD_POPULATIONS:-radii5 radii6 ellipsoid5 bent5 bent6 either5 faust faust-poses}
[ -x "$bin" ] || { echo "build first: scripts/setup.sh" >&2; exit 2; }
mkdir -p "$out"
say() { echo "scoreboard: $*" >&2; }

# POPULATION -> OUT_DIR/POPULATION/shapes with its population.json (or
# population_map.json); returns 1 where the population cannot be made.
make_population() {
  local name=$1 dir=$out/$1
  if [ -s "$dir/shapes/population.json" ] || [ -s "$dir/population_map.json" ]; then return 0; fi
  case $name in
    radii5) "$bin" generate --population 12 --family radii --vertices 2000 --seed 5 --out-dir "$dir/shapes" 2>/dev/null ;;
    radii6) "$bin" generate --population 12 --family radii --vertices 2000 --seed 6 --out-dir "$dir/shapes" 2>/dev/null ;;
    ellipsoid5) "$bin" generate --population 12 --family ellipsoid --vertices 2000 --seed 5 --out-dir "$dir/shapes" 2>/dev/null ;;
    bent5) "$bin" generate --population 12 --family bent --vertices 2000 --seed 5 --out-dir "$dir/shapes" 2>/dev/null ;;
    bent6) "$bin" generate --population 12 --family bent --vertices 2000 --seed 6 --out-dir "$dir/shapes" 2>/dev/null ;;
    either5) "$bin" generate --population 12 --family bent-either --vertices 2000 --seed 5 --out-dir "$dir/shapes" 2>/dev/null ;;
    faust | faust-poses)
      if [ -z "${FAUST_REPO:-}" ] || [ ! -e "$FAUST_REPO" ]; then
        say "$name: skipped, no data (set FAUST_REPO to a copy of llorz/SGA18_orientation_BCICP_dataset)"
        return 1
      fi
      local person=()
      [ "$name" = faust-poses ] && person=(--person 0)
      "$here/scripts/faust_population.sh" "${person[@]}" "$FAUST_REPO" "$dir" ;;
    *) echo "correspondence_scoreboard: unknown population '$name'" >&2; exit 2 ;;
  esac
}

score_json() {  # POPULATION_JSON FILES... -> the yardstick's JSON on stdout
  local figures
  figures=$(mktemp)
  "$python" "$here/scripts/correspondence_error.py" "$@" --json "$figures" >/dev/null
  cat "$figures" && rm -f "$figures"
}

quality_json() {  # MESH FILE -> one shape's evenness, as summary.json measures it
  "$bin" quality "$1" "$2" --json -q --distances local --cutoff 1.5
}

# -> the python of OUT_DIR/zoomout-venv (pyfmaps, numpy, scipy), made on first use; never a system Python's
# packages, never the program's.
make_zoomout_venv() {
  local venv=$out/zoomout-venv
  if ! "$venv/bin/python" -c "import pyFM, numpy, scipy" 2>/dev/null; then
    say "making $venv: pip install pyfmaps numpy scipy"
    rm -rf "$venv"
    "$python" -m venv "$venv" >&2
    "$venv/bin/pip" install -q pyfmaps numpy scipy >&2
  fi
  echo "$venv/bin/python"
}
zoomout_python=

for name in $populations; do
  make_population "$name" || { echo "{\"population\": \"$name\", \"skipped\": true}" >"$out/$name.skipped.json"; continue; }
  rm -f "$out/$name.skipped.json"
  dir=$out/$name
  if [ -s "$dir/population_map.json" ]; then truth=$dir/population_map.json; else truth=$dir/shapes/population.json; fi
  meshes=("$dir"/shapes/*.off)
  for n in "${ns[@]}"; do
    run=$dir/$(printf '%04d' "$n")
    mkdir -p "$run/own" "$run/figures"
    if [ ! -s "$run/correspond/summary.json" ]; then
      say "$name, n = $n: correspond"
      rm -rf "$run/correspond"
      nice -n 10 "$bin" correspond "$dir/shapes" -n "$n" -q --out "$run/correspond" >/dev/null
    fi
    ours=("$run"/correspond/shapes/*.particles)
    [ -s "$run/figures/ours_spread.json" ] || score_json "$truth" "${ours[@]}" >"$run/figures/ours_spread.json"
    say "$name, n = $n: each shape's own run and the evenness"
    for i in "${!meshes[@]}"; do
      stem=$(basename "${meshes[$i]}" .off)
      [ -s "$run/own/$stem/particles.particles" ] ||
        nice -n 10 "$bin" run "${meshes[$i]}" -n "$n" -q --out "$run/own/$stem" >/dev/null
      [ -s "$run/figures/own_$stem.json" ] ||
        quality_json "${meshes[$i]}" "$run/own/$stem/particles.particles" >"$run/figures/own_$stem.json"
      [ -s "$run/figures/ours_$stem.json" ] || quality_json "${meshes[$i]}" "${ours[$i]}" >"$run/figures/ours_$stem.json"
    done
    if [ "${SCOREBOARD_ZOOMOUT:-1}" != 0 ]; then
      [ -n "$zoomout_python" ] || zoomout_python=$(make_zoomout_venv)
      if [ ! -s "$run/zoomout/seconds.json" ]; then
        say "$name, n = $n: the ZoomOut baseline"
        rm -rf "$run/zoomout"
        nice -n 10 "$zoomout_python" "$here/scripts/zoomout_baseline.py" "$dir/shapes" -n "$n" --out "$run/zoomout" \
          --binary "$bin" >/dev/null
      fi
      theirs=("$run"/zoomout/shapes/*.particles)
      [ -s "$run/figures/zoomout_spread.json" ] ||
        score_json "$truth" "${theirs[@]}" >"$run/figures/zoomout_spread.json"
      for i in "${!meshes[@]}"; do
        stem=$(basename "${meshes[$i]}" .off)
        [ -s "$run/figures/zoomout_$stem.json" ] ||
          quality_json "${meshes[$i]}" "${theirs[$i]}" >"$run/figures/zoomout_$stem.json"
      done
    fi
    if [ "${SCOREBOARD_CPD:-1}" != 0 ]; then
      if [ ! -s "$run/cpd/figures.json" ]; then
        say "$name, n = $n: the CPD baseline (slow)"
        map=()
        [ "$truth" = "$dir/population_map.json" ] && map=(--map-population "$truth")
        nice -n 10 "$python" "$here/scripts/cpd_baseline.py" "$dir/shapes" -n "$n" --out "$run/cpd" --binary "$bin" \
          "${map[@]}" --json "$run/cpd/figures.json" >/dev/null
      fi
    fi
  done
done

"$python" - "$out" "$populations" "${ns[@]}" <<'PY'
import json
import sys
from pathlib import Path

import numpy as np

out, populations, ns = Path(sys.argv[1]), sys.argv[2].split(), [int(n) for n in sys.argv[3:]]
LABELS = {"radii5": "radii, seed 5", "radii6": "radii, seed 6", "ellipsoid5": "ellipsoid family, seed 5",
          "bent5": "bent, seed 5", "bent6": "bent, seed 6",
          "either5": "bent either way, seed 5", "faust": "FAUST, 10 people",
          "faust-poses": "FAUST, 1 person in 10 poses"}


def quality(file):
    figures = json.loads(file.read_text())
    return figures.get("quality", figures)


def evenness(run, kind, cpd=None):
    """rho least / median and cover over the shape's own run's, median / most, over the shapes (in name order,
    as cpd_baseline.py lists its evenness); None where not measured. kind: "ours", "zoomout" or "cpd"."""
    own = sorted((run / "figures").glob("own_*.json"))
    if kind == "cpd":
        figures = cpd["evenness"] if cpd else []
    else:
        files = [run / "figures" / f"{kind}_{file.name[len('own_'):]}" for file in own]
        figures = [quality(file) for file in files if file.exists()]
    if not own or len(figures) != len(own):
        return None
    rho = [f["rho"] for f in figures]
    cover = [f["cover"] / quality(file)["cover"] for f, file in zip(figures, own)]
    return {"rho_least": min(rho), "rho_median": float(np.median(rho)), "cover_ratio_median": float(np.median(cover)),
            "cover_ratio_most": max(cover)}


def pair(a, b, digits=2):
    return f"{a:.{digits}f} / {b:.{digits}f}"


def spread_entry(spread):
    """The figures of one set of particles' spread (the yardstick's JSON)."""
    worst = max(spread["per_shape"], key=lambda shape: shape["mean"])
    return {**{k: spread[k] for k in ("median", "mean", "p90")},
            "worst_shape": {"file": Path(worst["file"]).name, "mean": worst["mean"]},
            "turn_degrees": [shape.get("turn_degrees") for shape in spread["per_shape"]]}


def row(label, n, particles, spread, even):
    turns = spread["turn_degrees"]
    turned = "" if not turns or turns[0] is None else f"{sum(t > 60 for t in turns)} ({max(turns):.0f}°)"
    return (f"| {label} | {n:,} | {particles} | {pair(spread['median'], spread['p90'])} | "
            f"{spread['worst_shape']['mean']:.2f} | {turned} | "
            + (f"{pair(even['rho_least'], even['rho_median'])} | "
               f"{pair(even['cover_ratio_median'], even['cover_ratio_most'])}x" if even else "- | -") + " |")


rows, board = [], []
for name in populations:
    label = LABELS.get(name, name)
    if (out / f"{name}.skipped.json").exists():
        rows.append(f"| {label} | skipped: no data (FAUST_REPO) | | | | | | |")
        continue
    for n in ns:
        run = out / name / f"{n:04d}"
        spread_file = run / "figures/ours_spread.json"
        if not spread_file.exists():
            continue
        entry = {"population": name, "n": n, "ours": spread_entry(json.loads(spread_file.read_text())),
                 "ours_evenness": evenness(run, "ours"), "zoomout": None, "zoomout_evenness": None,
                 "cpd": None, "cpd_evenness": None}
        zoomout_file = run / "figures/zoomout_spread.json"
        if zoomout_file.exists():
            entry["zoomout"] = spread_entry(json.loads(zoomout_file.read_text()))
            entry["zoomout_evenness"] = evenness(run, "zoomout")
        cpd_file = run / "cpd/figures.json"
        if cpd_file.exists():
            cpd = json.loads(cpd_file.read_text())["cpd"]
            entry["cpd"] = spread_entry(cpd["spread"])
            entry["cpd_evenness"] = evenness(run, "cpd", cpd)
        board.append(entry)
        for key, particles in (("ours", "ours"), ("zoomout", "ZoomOut"), ("cpd", "CPD")):
            if entry[key]:
                rows.append(row(label, n, particles, entry[key], entry[f"{key}_evenness"]))
table = "\n".join([
    "| population | n | particles | spread: median / p90 | worst shape | turned > 60° (most) | "
    "rho: least / median | cover / own run's: median / most |",
    "|---|---|---|---|---|---|---|---|", *rows])
print(table)
(out / "scoreboard.md").write_text(table + "\n")
(out / "scoreboard.json").write_text(json.dumps(board, indent=2) + "\n")
PY
