#!/usr/bin/env bash
# The main job from a fresh Debian 12 machine: installs what is missing,
# builds Release into build/, then runs `meshparticles ARGS` - or, with no
# ARGS, the main job: `meshparticles run` (the committed sphere, 1024
# particles, the field backend on the first GPU or else PoCL, output in ./out).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$ROOT"
if (($#)); then
  exec build/meshparticles "$@"
fi
exec build/meshparticles run
