#!/usr/bin/env bash
# scripts/memory_limits.sh [MESH] [OUT_DIR]
#
# What: `meshparticles run MESH` (default meshes/sphere.off) with each backend, and the
# default (spread) run, under an address-space limit (`ulimit -v`) from 256 MiB to 2 GiB in
# 256 MiB steps, each with a cold kernel cache (fresh $POCL_CACHE_DIR and $XDG_CACHE_HOME).
# Prints a Markdown table: "ok" with the seconds when the run completed; else the exit code,
# whether the error was one line, and a number for its message, listed under the table. A run
# still going after 120 s is a hang.
#
# Why: clusters run jobs under a virtual-memory limit. Issue 34 asked that each such run
# either completes or refuses in one line naming the limit: never a hang, never a crash.
# The table in docs/PERFORMANCE.md ("Under memory limits") comes from this script.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
mesh=${1:-$here/meshes/sphere.off}
out=${2:-$(mktemp -d)}
bin=$here/build/meshparticles
[ -x "$bin" ] || { echo "build first: scripts/setup.sh" >&2; exit 2; }
mkdir -p "$out"

runs=("spread:" "serial:--method paper --backend serial" "naive:--method paper --backend naive"
      "tiled:--method paper --backend tiled" "field:--method paper --backend field"
      "serial-field:--method paper --backend serial-field")
declare -A notes=()  # message -> its number under the table
order=()
printf '| ulimit -v |'
for run in "${runs[@]}"; do printf ' %s |' "${run%%:*}"; done
printf '\n|---|'
for _ in "${runs[@]}"; do printf -- '---|'; done
printf '\n'
for mib in 256 512 768 1024 1280 1536 1792 2048; do
  printf '| %d MiB |' "$mib"
  for run in "${runs[@]}"; do
    name=${run%%:*} options=${run#*:}
    cold=$out/cold_${mib}_$name
    rm -rf "$cold" && mkdir -p "$cold"
    started=$(date +%s.%N)
    # shellcheck disable=SC2086
    errors=$(ulimit -v $((mib * 1024)) && POCL_CACHE_DIR=$cold/pocl XDG_CACHE_HOME=$cold/xdg \
             timeout 120 "$bin" run "$mesh" $options -q --out "$out/run_${mib}_$name" 2>&1 >/dev/null)
    code=$?
    seconds=$(echo "$(date +%s.%N) - $started" | bc)
    lines=$(grep -c '' <<<"$errors")
    if [ "$code" -eq 0 ]; then
      printf ' ok, %.1f s |' "$seconds"
    elif [ "$code" -eq 124 ]; then
      printf ' **hang** (killed at 120 s) |'
    else
      message=$(head -1 <<<"$errors" | sed 's/^meshparticles: error: //')
      [ -n "${notes[$message]:-}" ] || { notes[$message]=$((${#notes[@]} + 1)); order+=("$message"); }
      printf ' exit %d in %.1f s, %s [%d] |' "$code" "$seconds" \
        "$([ "$lines" -le 1 ] && echo "one line" || echo "**$lines lines**")" "${notes[$message]}"
    fi
  done
  printf '\n'
done
printf '\n'
for message in "${order[@]}"; do printf '[%d] %s\n' "${notes[$message]}" "$message"; done
