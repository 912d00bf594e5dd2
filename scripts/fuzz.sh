#!/usr/bin/env bash
# scripts/fuzz.sh [SECONDS]: builds the libFuzzer targets of the mesh readers
# (cmake/fuzzing.cmake, clang, ASan + UBSan) in build-fuzz/ and runs each
# format's target for an equal share of SECONDS (default 120), starting from
# the committed corpus in fuzz/corpus/FORMAT. Exits non-zero on the first
# finding: a crash, a sanitizer report, a hang (-timeout), an allocation the
# input does not justify (-malloc_limit_mb with -max_len) or output on a
# standard stream (the harness). Findings land in build-fuzz/findings/FORMAT/;
# add each as a regression file (tests/data and fuzz/corpus) once fixed.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SECONDS_TOTAL="${1:-120}"
BUILD="$ROOT/build-fuzz"
FORMATS=(off ply obj stl vtk vtp)
CXX_FOR_FUZZ="${CXX_FOR_FUZZ:-$(command -v clang++-14 || command -v clang++ || true)}"
[ -n "$CXX_FOR_FUZZ" ] || { echo "fuzz: needs clang++ (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 1; }

cmake -S "$ROOT" -B "$BUILD" -DMESHPARTICLES_FUZZ=ON -DCMAKE_CXX_COMPILER="$CXX_FOR_FUZZ" >/dev/null
cmake --build "$BUILD" --parallel 2 -- --no-print-directory >/dev/null

share=$((SECONDS_TOTAL / ${#FORMATS[@]}))
((share >= 1)) || share=1
total_runs=0
for format in "${FORMATS[@]}"; do
  # New inputs go to a working copy, so the committed seeds stay as they are.
  work="$BUILD/corpus/$format" findings="$BUILD/findings/$format"
  mkdir -p "$work" "$findings"
  log="$BUILD/fuzz_$format.log"
  if ! "$BUILD/fuzz_$format" -max_total_time="$share" -timeout=5 -max_len=32768 -malloc_limit_mb=64 \
      -rss_limit_mb=2048 -print_final_stats=1 -dict="$ROOT/fuzz/dicts/$format.dict" \
      -artifact_prefix="$findings/" "$work" "$ROOT/fuzz/corpus/$format" >"$log" 2>&1; then
    echo "fuzz: $format: FINDING (log: $log)" >&2
    grep -E "FINDING|ERROR|SUMMARY|Test unit written" "$log" | head -20 >&2
    exit 1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  total_runs=$((total_runs + ${runs:-0}))
  echo "fuzz: $format: ${runs:-0} inputs in ${share} s, no finding"
done
echo "fuzz: $total_runs inputs in total, no finding"
