#!/usr/bin/env bash
# Our particles against MeshLab, Open3D and point-cloud-utils Poisson-disk
# sampling on the meshes of Debian's libcgal-demo (and --models DIR): quality
# by `meshparticles quality` and time, as two Markdown tables and a summary.
#   scripts/bench_real_models.sh [-n 256,1024,4096] [--only cow,bull] [--limit K] [--max-vertices V]
#                                [--models DIR] [--binary PATH] [--json FILE] [--markdown FILE] [--no-python]
# The peers (and the Python module) go into a venv made on first use,
# $MESHPARTICLES_PEER_VENV or ${XDG_CACHE_HOME:-~/.cache}/meshparticles/peer-venv.
# Everything else: scripts/bench_real_models.py --help, and its docstring.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exec python3 "$ROOT/scripts/bench_real_models.py" "$@"
