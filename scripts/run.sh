#!/usr/bin/env bash
# The main job from a fresh Debian 12 machine: installs what is missing,
# builds Release into build/, then runs `meshparticles ARGS` - or, with no
# ARGS, the embedded default job on the committed sphere and first device.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$ROOT"
if (($#)); then
  exec build/meshparticles "$@"
fi
build/meshparticles info meshes/sphere.off
build/meshparticles devices
