#!/usr/bin/env bash
# full_disk.sh MESHPARTICLES SHIM MESHES_DIR WORKDIR: every writer on a full
# disk (tests/full_disk_shim.cpp: writes under one directory fail with
# ENOSPC after a byte budget) exits 2 with one line naming the file and "No
# space left on device", leaves the earlier output as it was and no
# temporary behind; the distance cache only warns (it saves time, nothing more).
set -euo pipefail
bin=$1 shim=$2 meshes=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
work=$(cd "$work" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
tetra="$meshes/tetrahedron.off" torus="$meshes/torus.off"

# full BYTES CODE COMMAND...: runs COMMAND with the disk under $work/disk full
# after BYTES bytes; checks the exit code and that stderr names the reason.
full() {
  local bytes=$1 code=$2
  shift 2
  set +e
  # The sanitizer runtime wants to be first; the shim only wraps write().
  ASAN_OPTIONS=verify_asan_link_order=0 LD_PRELOAD="$shim" FULL_DISK_DIR="$work/disk" FULL_DISK_BYTES="$bytes" \
    "$@" > "$work/stdout" 2> "$work/stderr"
  local got=$?
  set -e
  [ "$got" -eq "$code" ] || { cat "$work/stderr"; fail "$* exited $got, expected $code"; }
  grep -q "No space left on device" "$work/stderr" || { cat "$work/stderr"; fail "$*: the reason is not named"; }
}
# No temporary of ours is left in DIR.
no_temporaries() {
  local left
  left=$(find "$1" -name '.*.tmp-*' -o -name '.*.old-*')
  [ -z "$left" ] || fail "temporaries left behind: $left"
}

mkdir -p "$work/disk"
# run: the earlier complete set survives a disk that fills while the new one is written.
"$bin" run "$tetra" -n 2 --backend serial --no-cache --out "$work/disk/run" -q > /dev/null
cp -r "$work/disk/run" "$work/run_before"
for budget in 0 100 2000; do
  full "$budget" 2 "$bin" run "$torus" -n 16 --iterations 2 --backend serial --no-cache --out "$work/disk/run" -q
  [ "$(grep -c '' "$work/stderr")" -eq 1 ] || { cat "$work/stderr"; fail "run: more than one line"; }
  diff -r "$work/run_before" "$work/disk/run" > /dev/null || fail "run: the earlier set changed (budget $budget)"
  no_temporaries "$work/disk"
done

# generate: the good file stays when its replacement cannot be written.
cp "$tetra" "$work/disk/tetrahedron.off"
full 10 2 "$bin" generate tetrahedron --out-dir "$work/disk"
grep -q "tetrahedron.off: cannot write: No space left on device" "$work/stderr" || fail "generate: message"
cmp -s "$tetra" "$work/disk/tetrahedron.off" || fail "generate replaced the good file"
no_temporaries "$work/disk"

# geodesics --source --out: the same for one file.
echo "earlier" > "$work/disk/distances.txt"
full 10 2 "$bin" geodesics "$torus" --source 0 --out "$work/disk/distances.txt" -q
[ "$(cat "$work/disk/distances.txt")" = earlier ] || fail "geodesics replaced the earlier file"
no_temporaries "$work/disk"

# The cache: a warning, the table still computed, no cache file.
full 1000 0 "$bin" geodesics "$torus" --cache-dir "$work/disk/cache"
grep -q "warning: not cached: .*No space left on device" "$work/stderr" || fail "cache: no warning"
[ -z "$(ls -A "$work/disk/cache")" ] || fail "cache: a file was left: $(ls -A "$work/disk/cache")"
echo "ok: run, generate, geodesics --out and the cache on a full disk"
