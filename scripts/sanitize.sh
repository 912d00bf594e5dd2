#!/usr/bin/env bash
# The suite under AddressSanitizer and UndefinedBehaviorSanitizer: builds
# build-sanitize/ (-DMESHPARTICLES_SANITIZE=ON) and runs the tests labelled
# LABEL (default: fast; `all` for every test but the offline kernel check).
# Any report from project code fails the run. PoCL and the OpenCL loader are
# not built with the sanitizers; their allocations are left to them
# (detect_leaks=0: the ICD loader and PoCL keep allocations until exit).
#   scripts/sanitize.sh [LABEL]      after scripts/setup.sh has installed the packages
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
label=${1:-fast}
build="$ROOT/build-sanitize"
# Clang where there is one (setup.sh installs clang-14 for the fuzz build):
# it compiles the instrumented code in about three quarters of GCC's time, and
# its warnings, errors here too, are a second compiler's opinion of the code.
CXX_FOR_SANITIZE="${CXX_FOR_SANITIZE:-$(command -v clang++-14 || command -v clang++ || command -v c++)}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
echo "sanitize: building $build with $CXX_FOR_SANITIZE (about 5 minutes on 2 cores the first time)" >&2
# -O1 -g1 (line tables, assertions on), as AddressSanitizer's docs advise,
# and half the compile time of -O2 -g (336 s against 617 s here, the tests
# 179 s against 156 s: docs/PERFORMANCE.md, "The test command").
cmake -S "$ROOT" -B "$build" -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" \
  -DCMAKE_CXX_COMPILER="$CXX_FOR_SANITIZE" "${launcher[@]}" -DMESHPARTICLES_STRICT=ON -DMESHPARTICLES_SANITIZE=ON >/dev/null
cmake --build "$build" --parallel "$(nproc)" -- --no-print-directory >/dev/null
# Allocation and free stacks four frames deep and a 16 MiB quarantine: a
# report still gives the faulting access's whole stack; the command tests,
# whose PoCL allocates heavily, ran a fifth faster (cli.command_outputs 46 s
# against 67 s).
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:malloc_context_size=4:quarantine_size_mb=16"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export MESHPARTICLES_DEVICE="${MESHPARTICLES_DEVICE:-Portable Computing Language}"
cd "$build"
# Left out: `kernels` (an offline compile, nothing to sanitize) and `rlimit`
# (runs under `ulimit -v`, where a sanitized binary cannot start).
if [ "$label" = all ]; then
  ctest --output-on-failure --parallel "$(nproc)" -LE 'kernels|rlimit'
else
  ctest --output-on-failure --parallel "$(nproc)" -L "$label" -LE 'kernels|rlimit'
fi
