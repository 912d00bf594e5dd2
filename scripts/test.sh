#!/usr/bin/env bash
# Every test from a fresh Debian 12 machine: installs what is missing, builds,
# and runs the whole suite with ctest on PoCL (the CPU OpenCL device).
set -euo pipefail
# Warnings are errors here, so a change that adds one does not land.
CMAKE_OPTIONS="-DMESHPARTICLES_STRICT=ON ${CMAKE_OPTIONS:-}"
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$ROOT/build"
# Tests run on PoCL whatever else the machine has, unless the caller chose.
export MESHPARTICLES_DEVICE="${MESHPARTICLES_DEVICE:-Portable Computing Language}"
ctest --output-on-failure --parallel "$(nproc)" "$@"
