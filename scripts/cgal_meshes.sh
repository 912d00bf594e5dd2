#!/usr/bin/env bash
# scripts/cgal_meshes.sh: prints the folder of the 143 meshes Debian's libcgal-demo ships,
# installing the package (apt-get, as root or with sudo) and unpacking its data under
# ${XDG_CACHE_HOME:-$HOME/.cache}/meshparticles/cgal-data first where either is missing.
# scripts/test.sh exports it as $MESHPARTICLES_CGAL_MESHES for the tests that read real meshes;
# scripts/real_meshes.sh runs the program on them.
set -euo pipefail
ARCHIVE=/usr/share/doc/libcgal-dev/data.tar.gz
if [ ! -f "$ARCHIVE" ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "cgal_meshes: installing libcgal-demo" >&2
  $SUDO apt-get update -qq >/dev/null
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends libcgal-demo >/dev/null
fi
CACHE="${XDG_CACHE_HOME:-$HOME/.cache}/meshparticles/cgal-data"
if [ ! -d "$CACHE/data/meshes" ]; then
  mkdir -p "$CACHE"
  # Unpacked beside, then renamed: a kill leaves no half folder that looks whole.
  partial=$(mktemp -d "$CACHE/unpacking.XXXXXX")
  tar -xzf "$ARCHIVE" -C "$partial" data/meshes
  mkdir -p "$CACHE/data"
  mv "$partial/data/meshes" "$CACHE/data/meshes" 2>/dev/null || [ -d "$CACHE/data/meshes" ]
  rm -rf "$partial"
fi
echo "$CACHE/data/meshes"
