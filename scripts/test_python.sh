#!/usr/bin/env bash
# The Python package (docs/PYTHON.md) as a user gets it: a fresh venv in a
# temporary directory, `pip install` of this checkout (scikit-build-core and
# numpy from PyPI), then tests/python against what was installed.
#   scripts/test_python.sh            build, install, test
#   scripts/test_python.sh ARGS       pytest ARGS, e.g. -k geodesics
# The wheel's CMake build is kept in build/python-wheel (git ignores build/);
# a full build takes about 3 minutes on 2 cores.
# Needs python3-venv, python3-dev and pybind11-dev (scripts/setup.sh lists
# them). tests/python compares with build/meshparticles when it is there.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PYTHON="${PYTHON:-python3}"

VENV="$(mktemp -d)"
trap 'rm -rf "$VENV"' EXIT
echo "test_python: creating a venv in $VENV" >&2
"$PYTHON" -m venv "$VENV"
"$VENV/bin/pip" install --quiet --upgrade pip >&2
echo "test_python: installing $ROOT (the build's progress follows)" >&2
# The wheel compiles as build/ did (its compiler, launcher and warnings), so
# that where build/ went through ccache (scripts/test.sh), pip's build finds
# every object there instead of compiling it again (the library's units, files
# of each build directory, only with CCACHE_BASEDIR=build/, as test.sh sets).
same_compile=()
for variable in CMAKE_CXX_COMPILER CMAKE_CXX_COMPILER_LAUNCHER MESHPARTICLES_STRICT; do
  value=$(sed -n "s/^$variable:[A-Z]*=//p" "$ROOT/build/CMakeCache.txt" 2>/dev/null || true)
  [ -n "$value" ] && same_compile+=(--config-settings=cmake.define.$variable="$value")
done
# The build's lines ([12/92] Building ...) on stderr, so a long first build is visibly moving.
"$VENV/bin/pip" install --verbose --config-settings=build-dir="$ROOT/build/python-wheel" "${same_compile[@]}" "$ROOT" 2>&1 |
  sed -n 's/^ *\(\[ *[0-9]*\/[0-9]*\]\)/test_python: \1/p' >&2
"$VENV/bin/pip" install --quiet pytest >&2
echo "test_python: running tests/python" >&2
# From the venv's directory, so that `import meshparticles` finds the
# installed package, not the checkout's python/ folder.
cd "$VENV"
"$VENV/bin/python" -m pytest -q "$ROOT/tests/python" "$@"
