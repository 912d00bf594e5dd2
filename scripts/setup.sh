#!/usr/bin/env bash
# Shared set-up for scripts/run.sh and scripts/test.sh: install the Debian
# packages that are missing (silent when all are present), then configure and
# build Release into build/, showing the build's progress on stderr. Sourced,
# not run: the callers go on in their own directory, with $ROOT set.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

PACKAGES=(
  build-essential cmake pkg-config
  opencl-headers opencl-clhpp-headers ocl-icd-opencl-dev pocl-opencl-icd
  libopenmesh-dev libgtest-dev libcli11-dev nlohmann-json3-dev
  python3-matplotlib python3-numpy python3-meshio
  clang-14 libclc-14 libclang-rt-14-dev
  libssl-dev openmpi-bin libopenmpi-dev libnanoflann-dev libexpat1-dev zlib1g-dev
  pybind11-dev python3-dev python3-venv libeigen3-dev
  ccache
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
done
if ((${#missing[@]})); then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    SUDO="sudo"
  fi
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq >/dev/null
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

BUILD_TYPE="${BUILD_TYPE:-Release}"
# Extra -D options from the caller (scripts/test.sh builds with warnings as errors).
read -r -a cmake_options <<< "${CMAKE_OPTIONS:-}"
if [ ! -x "$ROOT/build/meshparticles" ]; then
  echo "setup: building into $ROOT/build (the first build takes about 3 to 6 minutes on 2 cores)" >&2
fi
cmake -S "$ROOT" -B "$ROOT/build" -DCMAKE_BUILD_TYPE="$BUILD_TYPE" "${cmake_options[@]}" >/dev/null
# The build's own progress lines ([ 42%] Building ...) on stderr, so a long
# first build is visibly moving; its errors come through as they are.
cmake --build "$ROOT/build" --parallel "$(nproc)" -- --no-print-directory | sed -n 's/^\(\[ *[0-9]*%\]\)/setup: \1/p' >&2
