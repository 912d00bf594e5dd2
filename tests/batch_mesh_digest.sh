#!/usr/bin/env bash
# batch_mesh_digest.sh MESHPARTICLES SHIM MESHES WORKDIR: report.json's
# mesh sha256 is the digest of the bytes the run read, even when the file is
# replaced right after (tests/replace_after_read_shim.cpp renames another
# mesh onto it as the first read closes it). batch once hashed the file
# after loading it, and gave the tetrahedron's run the other file's digest.
set -euo pipefail
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
bin=$1 shim=$2 meshes=$3 work=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work/in"
cp "$meshes/tetrahedron.off" "$work/in/shape.off"
cp "$meshes/high_valence.off" "$work/replacement.off"
read_digest=$(sha256sum < "$work/in/shape.off" | cut -d' ' -f1)
REPLACE_AFTER_READ="$work/in/shape.off" REPLACE_WITH="$work/replacement.off" LD_PRELOAD="$shim" \
  "$bin" batch "$work/in/shape.off" -n 4 -q --out "$work/out" > /dev/null 2> "$work/batch.log" ||
  fail "batch: $(cat "$work/batch.log")"
[ ! -e "$work/replacement.off" ] || fail "the shim did not replace the mesh"
python3 - "$work/out/shape/report.json" "$read_digest" <<'PY' || fail "report.json's digest is not the read mesh's"
import json, sys
report = json.load(open(sys.argv[1]))
mesh = report["mesh"]
print("vertices", mesh["vertices"], "sha256", mesh["sha256"])
sys.exit(0 if mesh["vertices"] == 4 and mesh["sha256"] == sys.argv[2] else 1)
PY
echo "ok: report.json's digest is the one of the bytes the run read"
