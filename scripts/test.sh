#!/usr/bin/env bash
# Every test from a fresh Debian 12 machine: installs what is missing, builds
# (warnings are errors) the program, the tests and the Python module, runs
# the whole suite with ctest on PoCL (the CPU OpenCL device), then the fast
# tests again under AddressSanitizer and UndefinedBehaviorSanitizer, built
# with clang (scripts/sanitize.sh), the Python package installed with pip
# into a fresh venv and its tests (scripts/test_python.sh), 90 core-seconds
# of fuzzing of the mesh readers (scripts/fuzz.sh) and ten real meshes from
# Debian's libcgal-demo (scripts/real_meshes.sh --subset). docs/PERFORMANCE.md
# ("The test command, step by step") has each step's time.
#   scripts/test.sh            everything (what CI runs)
#   scripts/test.sh ARGS       ctest ARGS only, e.g. -L fast or -R Monotone
set -euo pipefail
# Each step's time on stderr (docs/PERFORMANCE.md records a clean clone's).
step_started=$SECONDS
step_done() {
  echo "test.sh: $1 took $((SECONDS - step_started)) s (total $SECONDS s)" >&2
  step_started=$SECONDS
}
# Warnings are errors here, so a change that adds one does not land.
# One compile serves the program, the tests and the Python module: the build
# makes the module too (its objects position-independent), and ccache gives
# pip's build of the wheel, which compiles the same files with the same
# compiler and flags (scripts/test_python.sh), those objects back instead of
# compiling them again. The cache lives in build/ unless CCACHE_DIR says where.
build_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build"
export CCACHE_DIR="${CCACHE_DIR:-$build_dir/ccache}"
# The library compiles eight files to a unit (CMakeLists.txt), and a unit is
# a file of its build directory: with build/ as ccache's base, the unit's
# path is the same relative one in build/ and in pip's build/python-wheel,
# so pip's build finds it in the cache too.
export CCACHE_BASEDIR="$build_dir"
# On a miss, ccache reads the compiler's own dependency list (-MD) rather
# than running the preprocessor a second time.
export CCACHE_DEPEND="${CCACHE_DEPEND:-true}"
CMAKE_OPTIONS="-DMESHPARTICLES_STRICT=ON -DMESHPARTICLES_PYTHON=ON -DCMAKE_CXX_COMPILER_LAUNCHER=ccache ${CMAKE_OPTIONS:-}"
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
step_done "install and build"
cd "$ROOT/build"
# CGAL's meshes, for the tests that read real meshes (installed and unpacked if missing).
MESHPARTICLES_CGAL_MESHES="${MESHPARTICLES_CGAL_MESHES:-$("$ROOT/scripts/cgal_meshes.sh")}"
export MESHPARTICLES_CGAL_MESHES
# Tests run on PoCL whatever else the machine has, unless the caller chose.
export MESHPARTICLES_DEVICE="${MESHPARTICLES_DEVICE:-Portable Computing Language}"
if (($#)); then
  exec ctest --output-on-failure --parallel "$(nproc)" "$@"
fi
ctest --output-on-failure --parallel "$(nproc)"
step_done "ctest"
"$ROOT/scripts/sanitize.sh" fast
step_done "sanitizer build and fast tests"
# Against build/meshparticles too: the module's particles are the program's.
MESHPARTICLES_CLI="$ROOT/build/meshparticles" "$ROOT/scripts/test_python.sh"
step_done "Python package build and tests"
"$ROOT/scripts/fuzz.sh" 90
step_done "fuzz build and run"
"$ROOT/scripts/real_meshes.sh" --subset
step_done "real meshes"
