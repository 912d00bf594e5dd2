#!/usr/bin/env bash
# kill_outputs.sh MESHPARTICLES MESHES_DIR WORKDIR [KILLS] [SEED]: kills
# `run`, `geodesics` and `generate` with SIGKILL at random times (a fixed
# seed; half of them once writing has begun) while they
# replace earlier results, and checks after every kill that each output
# holds the complete old set or the complete new one - never a mix, never
# half a file - and after one more complete run of each, that no temporary
# is left anywhere. KILLS (default 21) are shared out in turn:
#   run --out DIR          alternating n = 256 and n = 512 on the sphere
#   geodesics --out FILE   alternating sources 0 and 1; and the cache file
#                          (absent or valid, never truncated)
#   generate --out-dir D   over altered copies of the committed meshes
set -euo pipefail
bin=$1 meshes=$2 work=$3 kills=${4:-21} seed=${5:-14}
rm -rf "$work" && mkdir -p "$work"
work=$(cd "$work" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
RANDOM=$seed
sphere="$meshes/sphere.off" torus="$meshes/torus.off"
# Each output in a directory of its own: the watch for writing looks there.
cache="$work/cache" out="$work/runs/out" distances="$work/distances/d.txt" generated="$work/generated"
mkdir -p "$work/runs" "$work/distances"

run_args() { echo run "$sphere" -n "$1" --iterations 3 --backend serial --cache-dir "$cache" --out "$2" -q; }
geodesics_args() { echo geodesics "$torus" --source "$1" --out "$2" -q; }

# References: each complete set, written without interruption.
for n in 256 512; do "$bin" $(run_args $n "$work/reference_$n") > /dev/null; done
for source in 0 1; do "$bin" $(geodesics_args $source "$work/reference_$source.txt"); done
mkdir -p "$generated"
for mesh in "$meshes"/*.off; do
  { cat "$mesh"; echo "# an earlier version"; } > "$generated/$(basename "$mesh")"
done

# Milliseconds a complete command takes, to spread the kills over it.
duration_ms() {
  local start=$(date +%s%N)
  "$@" > /dev/null 2>&1
  echo $(( ($(date +%s%N) - start) / 1000000 ))
}
# kill_at_random MODE SPAN AREA COMMAND...: starts COMMAND and kills it:
# MODE any: at a random moment of 1.2 x SPAN ms (or not at all if it has
# finished); MODE writing: at a random moment of the first 50 ms after a
# file under AREA appeared or changed (the probe that checks the directory
# is writable aside) - inside the writing, which is a few percent of a run.
kill_at_random() {
  local mode=$1 span=$2 area=$3
  shift 3
  local marker="$work/.marker"
  touch "$marker"
  sleep 0.01  # file times are coarser than this on some file systems
  "$@" > /dev/null 2>&1 &
  local pid=$!
  local delay=$(( RANDOM * RANDOM % (span * 12 / 10 + 1) ))
  if [ "$mode" = writing ]; then
    while kill -0 "$pid" 2> /dev/null &&
      [ -z "$(find "$area" -mindepth 1 -newer "$marker" ! -name '.write-probe*' -print -quit)" ]; do :; done
    delay=$(( RANDOM % 50 ))
    ((writing_kills++)) || true
  fi
  sleep "$(printf '%d.%03d' $((delay / 1000)) $((delay % 1000)))"
  kill -9 "$pid" 2> /dev/null && killed=1 || killed=0
  wait "$pid" 2> /dev/null || true
}
writing_kills=0

same_files() { for name in particles.particles particles.csv particles.ply mesh_distance.vtk mesh_distance.vtp; do cmp -s "$1/$name" "$2/$name" || return 1; done; }
check_run_set() {
  for n in 256 512; do
    if same_files "$out" "$work/reference_$n"; then
      python3 -c "import json,sys; sys.exit(json.load(open('$out/report.json'))['params']['n'] != $n)" ||
        fail "run: the particle files are n = $n but report.json is not"
      return
    fi
  done
  fail "run: $out holds neither complete set: $(ls -A "$out" | tr '\n' ' ')"
}
check_distances() {
  cmp -s "$distances" "$work/reference_0.txt" || cmp -s "$distances" "$work/reference_1.txt" ||
    fail "geodesics: $distances is neither complete file"
}
check_cache() {  # the cache file, if written, loads without a warning
  local report
  report=$("$bin" geodesics "$torus" --cache-dir "$cache" 2> "$work/cache.err")
  if grep -q warning "$work/cache.err"; then cat "$work/cache.err"; fail "geodesics: the cache was left damaged"; fi
  grep -q "^from cache" <<< "$report" || fail "geodesics: no table"
}
check_generated() {
  for mesh in "$meshes"/*.off; do
    local file="$generated/$(basename "$mesh")"
    cmp -s "$mesh" "$file" || { head -c -21 "$file" | cmp -s "$mesh" - && tail -c 21 "$file" | grep -q "an earlier version"; } ||
      fail "generate: $(basename "$mesh") is neither the earlier file nor the new one"
  done
}
no_temporaries() {
  local left
  left=$(find "$work" -name '.*.tmp-*' -o -name '.*.old-*')
  [ -z "$left" ] || fail "temporaries left after a complete run: $left"
}

"$bin" $(run_args 256 "$out") > /dev/null
"$bin" $(geodesics_args 0 "$distances")
run_span=$(duration_ms "$bin" $(run_args 512 "$out"))
geodesics_span=$(duration_ms "$bin" $(geodesics_args 1 "$distances"))
cache_span=$(duration_ms "$bin" geodesics "$torus" --cache-dir "$work/timing_cache" -q) && rm -rf "$work/timing_cache"
generate_span=$(duration_ms "$bin" generate --out-dir "$work/timing_generated") && rm -rf "$work/timing_generated"

declare -A count=([run]=0 [geodesics]=0 [cache]=0 [generate]=0) finished=([run]=0 [geodesics]=0 [cache]=0 [generate]=0)
for ((k = 0; k < kills; ++k)); do
  mode=$( (( (k / 4) % 2 )) && echo any || echo writing )
  case $((k % 4)) in
    0) what=run; kill_at_random "$mode" "$run_span" "$work/runs" "$bin" $(run_args $(( (k / 8) % 2 ? 256 : 512 )) "$out"); check_run_set ;;
    1) what=geodesics; kill_at_random "$mode" "$geodesics_span" "$work/distances" "$bin" $(geodesics_args $(( (k / 8) % 2 )) "$distances"); check_distances ;;
    2) what=cache; rm -f "$cache"/*.dist; kill_at_random "$mode" "$cache_span" "$cache" "$bin" geodesics "$torus" --cache-dir "$cache" -q; check_cache ;;
    3) what=generate; kill_at_random "$mode" "$generate_span" "$generated" "$bin" generate --out-dir "$generated"; check_generated ;;
  esac
  count[$what]=$((count[$what] + 1))
  ((killed)) || finished[$what]=$((finished[$what] + 1))
done

# One complete run of each removes what the killed ones left.
"$bin" $(run_args 256 "$out") > /dev/null
"$bin" $(geodesics_args 0 "$distances")
"$bin" geodesics "$torus" --cache-dir "$cache" -q > /dev/null
"$bin" generate --out-dir "$generated" 2> /dev/null
check_run_set && check_distances && check_generated && no_temporaries
summary=""
for what in run geodesics cache generate; do
  summary+=" $what ${count[$what]} ($((count[$what] - finished[$what])) killed, ${finished[$what]} finished first);"
done
echo "ok: $kills kills ($writing_kills of them once writing had begun), seed $seed:$summary every output was the complete old or new set; no temporary left"
