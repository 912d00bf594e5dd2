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
# Each row: the spread of particle i (median / 90th percentile, in particle
# spacings; scripts/correspondence_error.py, FAUST by its map), the worst
# shape's particles' mean offset from particle i's mean place, the shapes
# turned more than 60 degrees from the others (generated families: the
# yardstick's per-shape turn, the largest in brackets), the CPD baseline's
# spread (scripts/cpd_baseline.py), and the evenness of both, each shape by
# `meshparticles quality MESH FILE --distances local --cutoff 1.5` as
# summary.json measures it: rho (the closest pair over the hexagonal spacing;
# the target is at least 0.7), least / median over the shapes, and cover over
# the same shape's own run's (`meshparticles run MESH -n N`; the target is at
# most 1.15x), median / most.
#
# Stages whose outputs are there are not run again, so an interrupted or
# partial board resumes: OUT_DIR/POPULATION/{shapes,NNNN/...}. CPD is slow
# (pure numpy: about 20 minutes a population at n = 256 on 2 cores);
# SCOREBOARD_CPD=0 leaves it out (its columns read "-"), and
# SCOREBOARD_POPULATIONS picks populations (default "radii5 radii6 ellipsoid5
# bent5 bent6 either5 faust faust-poses"). Progress on stderr; the table on stdout and in
# OUT_DIR/scoreboard.md, every figure in OUT_DIR/scoreboard.json.
# Why: the targets of docs/CORRESPONDENCE.md (spread median 0.3 and 90th percentile 0.6, no
# shape over 1 spacing off, rho 0.7, cover 1.15x, better than CPD) checked on
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
    as cpd_baseline.py lists its evenness); None where not measured."""
    own = sorted((run / "figures").glob("own_*.json"))
    if kind == "cpd":
        figures = cpd["evenness"] if cpd else []
    else:
        files = [run / "figures" / f"ours_{file.name[len('own_'):]}" for file in own]
        figures = [quality(file) for file in files if file.exists()]
    if not own or len(figures) != len(own):
        return None
    rho = [f["rho"] for f in figures]
    cover = [f["cover"] / quality(file)["cover"] for f, file in zip(figures, own)]
    return {"rho_least": min(rho), "rho_median": float(np.median(rho)), "cover_ratio_median": float(np.median(cover)),
            "cover_ratio_most": max(cover)}


def pair(a, b, digits=2):
    return f"{a:.{digits}f} / {b:.{digits}f}"


rows, board = [], []
for name in populations:
    if (out / f"{name}.skipped.json").exists():
        rows.append(f"| {LABELS.get(name, name)} | skipped: no data (FAUST_REPO) | | | | | | | | |")
        continue
    for n in ns:
        run = out / name / f"{n:04d}"
        spread_file = run / "figures/ours_spread.json"
        if not spread_file.exists():
            continue
        ours = json.loads(spread_file.read_text())
        worst = max(ours["per_shape"], key=lambda shape: shape["mean"])
        turns = [shape.get("turn_degrees") for shape in ours["per_shape"]]
        turned = "" if turns[0] is None else (f"{sum(t > 60 for t in turns)} ({max(turns):.0f}°)")
        cpd_file = run / "cpd/figures.json"
        cpd = json.loads(cpd_file.read_text())["cpd"] if cpd_file.exists() else None
        entry = {"population": name, "n": n, "ours": {k: ours[k] for k in ("median", "mean", "p90")},
                 "worst_shape": {"file": Path(worst["file"]).name, "mean": worst["mean"]},
                 "turn_degrees": turns, "ours_evenness": evenness(run, "ours"),
                 "cpd": {k: cpd["spread"][k] for k in ("median", "mean", "p90")} if cpd else None,
                 "cpd_evenness": evenness(run, "cpd", cpd)}
        board.append(entry)
        even, cpd_even = entry["ours_evenness"], entry["cpd_evenness"]
        rows.append(
            f"| {LABELS.get(name, name)} | {n} | {pair(ours['median'], ours['p90'])} | {worst['mean']:.2f} | {turned} | "
            + (pair(cpd["spread"]["median"], cpd["spread"]["p90"]) if cpd else "-") + " | "
            + (f"{pair(even['rho_least'], even['rho_median'])} | {pair(even['cover_ratio_median'], even['cover_ratio_most'])}x"
               if even else "- | -") + " | "
            + (f"{pair(cpd_even['rho_least'], cpd_even['rho_median'])} | "
               f"{pair(cpd_even['cover_ratio_median'], cpd_even['cover_ratio_most'])}x" if cpd_even else "- | -") + " |")
table = "\n".join([
    "| population | n | ours: spread median / p90 | worst shape's mean offset | shapes turned > 60° (most) | "
    "CPD: spread median / p90 | ours: rho least / median | ours: cover / own run's, median / most | "
    "CPD: rho least / median | CPD: cover / own run's, median / most |",
    "|---|---|---|---|---|---|---|---|---|---|", *rows])
print(table)
(out / "scoreboard.md").write_text(table + "\n")
(out / "scoreboard.json").write_text(json.dumps(board, indent=2) + "\n")
PY
