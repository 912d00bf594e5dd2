#!/usr/bin/env bash
# scripts/fuzz.sh [SECONDS]: builds the libFuzzer targets of the mesh readers
# (cmake/fuzzing.cmake, clang, ASan + UBSan) in build-fuzz/ and fuzzes them
# for SECONDS of one core in all (default 120), `nproc` targets at a time,
# so the step takes about SECONDS / nproc: each format's target
# (fuzz_FORMAT) one share, from the committed corpus in fuzz/corpus/FORMAT
# with fuzz/dicts/FORMAT.dict, and the structured VTK/VTP target
# (fuzz_vtk_structured, whose inputs are recipes for files, not files) two
# shares, from fuzz/corpus/vtk_structured. Exits non-zero on a finding: a
# crash, a sanitizer report, a hang (-timeout), an allocation the input
# does not justify (-malloc_limit_mb with -max_len), output on a standard
# stream, or (structured) a valid file refused or misread. Findings land in
# build-fuzz/findings/TARGET/; add each as a regression file (tests/data
# and fuzz/corpus) once fixed.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SECONDS_TOTAL="${1:-120}"
BUILD="$ROOT/build-fuzz"
# target:shares:max_len. A recipe is a few dozen bytes; 512 leaves room
# for a hundred tweaks. The longest first, so that the lanes end together.
TARGETS=(vtk_structured:2:512 off:1:32768 ply:1:32768 obj:1:32768 stl:1:32768 vtk:1:32768 vtp:1:32768)
CXX_FOR_FUZZ="${CXX_FOR_FUZZ:-$(command -v clang++-14 || command -v clang++ || true)}"
[ -n "$CXX_FOR_FUZZ" ] || { echo "fuzz: needs clang++ (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 1; }

cmake -S "$ROOT" -B "$BUILD" -DMESHPARTICLES_FUZZ=ON -DCMAKE_CXX_COMPILER="$CXX_FOR_FUZZ" >/dev/null
cmake --build "$BUILD" --parallel "$(nproc)" -- --no-print-directory >/dev/null

shares=0
for target in "${TARGETS[@]}"; do shares=$((shares + $(cut -d: -f2 <<<"$target"))); done

# One target's share of the seconds; its summary line on stdout, and exit 1
# on a finding.
fuzz_target() {
  IFS=: read -r name weight max_len <<<"$1"
  seconds=$((SECONDS_TOTAL * weight / shares))
  ((seconds >= 1)) || seconds=1
  # New inputs go to a working copy, so the committed seeds stay as they are.
  work="$BUILD/corpus/$name" findings="$BUILD/findings/$name"
  mkdir -p "$work" "$findings"
  log="$BUILD/fuzz_$name.log"
  dict=()
  [ -f "$ROOT/fuzz/dicts/$name.dict" ] && dict=(-dict="$ROOT/fuzz/dicts/$name.dict")
  if ! "$BUILD/fuzz_$name" -max_total_time="$seconds" -timeout=5 -max_len="$max_len" -malloc_limit_mb=64 \
      -rss_limit_mb=2048 -print_final_stats=1 "${dict[@]}" \
      -artifact_prefix="$findings/" "$work" "$ROOT/fuzz/corpus/$name" >"$log" 2>&1; then
    echo "fuzz: $name: FINDING (log: $log)" >&2
    grep -E "FINDING|ERROR|SUMMARY|Test unit written" "$log" | head -20 >&2
    return 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  echo "fuzz: $name: ${runs:-0} inputs in ${seconds} s, no finding"
}

# A libFuzzer process uses one core: the targets run `nproc` at a time, each
# for its own share, so the step takes about SECONDS / nproc and fuzzes as
# much as one after another would.
lanes=$(nproc)
summaries="$BUILD/summaries"
: >"$summaries"
failed=0
running=0
for target in "${TARGETS[@]}"; do
  if ((running >= lanes)); then
    wait -n || failed=1
    running=$((running - 1))
  fi
  fuzz_target "$target" >>"$summaries" &
  running=$((running + 1))
done
while ((running > 0)); do
  wait -n || failed=1
  running=$((running - 1))
done
cat "$summaries"
((failed == 0)) || exit 1
total_runs=$(awk '{runs += $3} END {print runs}' "$summaries")
echo "fuzz: $total_runs inputs in total, no finding"
