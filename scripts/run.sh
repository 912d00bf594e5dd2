#!/usr/bin/env bash
# The main job from a fresh Debian 12 machine: installs what is missing,
# builds Release into build/, then runs `meshparticles ARGS` - or, with no
# ARGS, the main job: `meshparticles run` on the committed sphere (1024
# particles spread on the host; `--method paper` runs the paper's field
# backend on the first GPU or else PoCL). It runs where you stand: relative
# paths in ARGS, and the main job's ./out, are yours.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
if (($#)); then
  exec "$ROOT/build/meshparticles" "$@"
fi
exec "$ROOT/build/meshparticles" run "$ROOT/meshes/sphere.off"
