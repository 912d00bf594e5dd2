#!/usr/bin/env bash
# replaced_outputs.sh MESHPARTICLES SHIM FULL_DISK_SHIM MESHES WORKDIR:
# `correspond` and `batch` writing over an older complete set of outputs
# (docs/OUTPUTS.md). SHIM is tests/kill_at_rename_shim.cpp's library,
# FULL_DISK_SHIM tests/full_disk_shim.cpp's.
#   kills      correspond (-n 48 over a set of -n 24) killed at every write:
#              checkpoint entries, shapes/, model/ and summary.json of the
#              set being built, and the swap of the whole set; before and
#              after each rename. After each kill the outputs are the whole
#              old set or the whole new one, never a mix; run again, the new
#              one, and no temporary anywhere. batch the same at each mesh's
#              folder and at its summary.
#   full disk  correspond over the old set with its writes cut short by a
#              full disk: exit 2, the old set whole
#   leftovers  temporaries inside --out (and beside it) named with another
#              host and a living PID (this shell's), or with this host and
#              PID 1 (a run that was PID 1 of its container): the rerun of
#              correspond and of batch removes them and goes on; a set that
#              a swap without exchange retired on another host, --out gone,
#              is put back (correspond resumes from its checkpoint, batch
#              keeps the folder)
set -euo pipefail
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
bin=$1 shim=$2 disk_shim=$3 meshes=$4 work=$5
fail() { echo "FAIL: $*" >&2; exit 1; }  # on stderr: it may come from inside $(which_set)
rm -rf "$work" && mkdir -p "$work"
work=$(cd "$work" && pwd)
"$bin" generate --population 4 --family ellipsoid --vertices 300 --seed 5 --out-dir "$work/shapes" 2> /dev/null
# The quicker deformation: these runs test the writes, not the fit.
old_options=("$work/shapes" -n 24 --samples 10 --refine-iterations 20 --deformation smooth)
new_options=("$work/shapes" -n 48 --samples 10 --refine-iterations 20 --deformation smooth)
"$bin" correspond "${old_options[@]}" -q --out "$work/old" > /dev/null
"$bin" correspond "${new_options[@]}" -q --out "$work/new" > /dev/null

# which OUT: "old" or "new" when OUT's outputs are that whole set, else fails naming what differs.
which_set() {
  local set
  for set in old new; do
    if diff -r -x checkpoint -x '.*.tmp-*' "$work/$set" "$1" > /dev/null 2>&1; then echo "$set"; return; fi
  done
  diff -r -q -x checkpoint -x '.*.tmp-*' "$work/old" "$1" | head -3 >&2
  fail "$2: $1 holds neither whole set: $(ls -A "$1" | tr '\n' ' ')"
}
no_temporaries() {
  local left
  left=$(find "$work" -name '.*.tmp-*' -o -name '.*.old-*')
  [ -z "$left" ] || fail "$1: temporaries left: $left"
}

# --- kills: correspond over the old set, at every write
kills=0
for target in checkpoint/request.json checkpoint/template.json checkpoint/transfer/001.json \
  checkpoint/iterated/002.json checkpoint/iterated.json checkpoint/packed/003.json checkpoint/packed.json \
  checkpoint/settled/000.json /shapes /model /summary.json swap; do
  for when in before after; do
    out="$work/killed_$(echo "$target" | tr -c 'a-z0-9\n' _)_$when"
    cp -r "$work/old" "$out"
    at=$target
    [ "$target" = swap ] && at=$out  # the rename onto --out itself
    status=0
    KILL_AT_RENAME="$at" KILL_AT_RENAME_WHEN="$when" LD_PRELOAD="$shim" \
      bash -c '"$@"; exit $?' _ "$bin" correspond "${new_options[@]}" --out "$out" > /dev/null 2> "$out.killed.log" || status=$?
    [ "$status" -eq 137 ] || { cat "$out.killed.log"; fail "killed at $target ($when): exit $status, not SIGKILL"; }
    found=$(which_set "$out" "killed at $target ($when)")
    "$bin" correspond "${new_options[@]}" --out "$out" > /dev/null 2> "$out.log" || { cat "$out.log"; fail "run again after $target ($when)"; }
    [ "$(which_set "$out" "run again after $target ($when)")" = new ] || fail "run again after $target ($when): the old set"
    [ -e "$out/checkpoint" ] && fail "run again after $target ($when): the checkpoint was left"
    echo "ok: correspond killed at $target ($when): the $found set whole; run again, the new one"
    kills=$((kills + 1))
  done
done
no_temporaries "correspond, after the kills and a run again"

# --- full disk: the new set cut short while it is written
full="$work/full"
cp -r "$work/old" "$full"
# A whole checkpoint first (killed as the set is swapped in), so that only the set is written.
KILL_AT_RENAME="$full" KILL_AT_RENAME_WHEN=before LD_PRELOAD="$shim" \
  bash -c '"$@"; exit $?' _ "$bin" correspond "${new_options[@]}" --out "$full" > /dev/null 2>&1 || true
status=0
LD_PRELOAD="$disk_shim" FULL_DISK_DIR="$work" FULL_DISK_BYTES=30000 \
  "$bin" correspond "${new_options[@]}" -q --out "$full" > /dev/null 2> "$work/full.log" || status=$?
[ "$status" -eq 2 ] && [ "$(wc -l < "$work/full.log")" -eq 1 ] || { cat "$work/full.log"; fail "full disk: exit $status"; }
grep -q "No space left on device" "$work/full.log" || fail "full disk: unclear: $(cat "$work/full.log")"
[ "$(which_set "$full" "full disk")" = old ] || fail "full disk: the new set was put in place"
"$bin" correspond "${new_options[@]}" -q --out "$full" > /dev/null || fail "full disk: the run again failed"
[ "$(which_set "$full" "full disk, run again")" = new ] || fail "full disk, run again: the old set"
echo "ok: correspond on a full disk: exit 2, the old set whole; run again, the new one"

# --- kills: batch over an older batch (-n 16 over -n 8), at each mesh's folder and the summary
batch_inputs=("$meshes/patch.off" "$meshes/sphere.off" "$meshes/torus.off")
"$bin" batch "${batch_inputs[@]}" -n 8 -q --out "$work/batch_old" > /dev/null
"$bin" batch "${batch_inputs[@]}" -n 16 -q --out "$work/batch_new" > /dev/null
# batch_set OUT WHAT: each mesh's folder the whole old one or the whole new one.
batch_set() {
  local mesh name set found
  for mesh in patch sphere torus; do
    found=""
    for set in old new; do
      found=$set
      for name in particles.particles particles.csv particles.ply mesh_distance.vtk mesh_distance.vtp; do
        cmp -s "$work/batch_$set/$mesh/$name" "$1/$mesh/$name" || { found=""; break; }
      done
      [ -n "$found" ] && break
    done
    [ -n "$found" ] || fail "$2: $mesh's folder is neither whole set: $(ls -A "$1/$mesh" | tr '\n' ' ')"
    local n=$([ "$found" = old ] && echo 8 || echo 16)
    grep -q "\"n\": $n," "$1/$mesh/report.json" || fail "$2: $mesh's particles are of -n $n, its report.json is not"
    [ "$#" -lt 3 ] || [ "$found" = "$3" ] || fail "$2: $mesh's folder is the $found set, not the $3"
  done
}
for target in /sphere /torus /summary.json; do
  for when in before after; do
    out="$work/batch_killed_$(echo "$target" | tr -c 'a-z0-9\n' _)_$when"
    cp -r "$work/batch_old" "$out"
    status=0
    KILL_AT_RENAME="$target" KILL_AT_RENAME_WHEN="$when" LD_PRELOAD="$shim" \
      bash -c '"$@"; exit $?' _ "$bin" batch "${batch_inputs[@]}" -n 16 -q --out "$out" > /dev/null 2>&1 || status=$?
    [ "$status" -eq 137 ] || fail "batch killed at $target ($when): exit $status, not SIGKILL"
    batch_set "$out" "batch killed at $target ($when)"
    "$bin" batch "${batch_inputs[@]}" -n 16 -q --out "$out" > /dev/null || fail "batch: run again after $target ($when)"
    batch_set "$out" "batch: run again after $target ($when)" new
    echo "ok: batch killed at $target ($when): every folder whole; run again, the new ones"
    kills=$((kills + 1))
  done
done
no_temporaries "batch, after the kills and a run again"

# --- leftovers of another host, a living PID, or PID 1 of a container
host=$(/usr/bin/python3 -c 'import re, socket; print(re.sub("[^A-Za-z0-9]", "_", socket.gethostname()))')
other=node${host}x  # never this host
out="$work/leftovers"
cp -r "$work/new" "$out"
mkdir "$out/.shapes.tmp-$other-$$-0" "$out/.model.tmp-$host-1-1" "$work/.leftovers.tmp-$other-$$-2"
touch "$out/.summary.tmp-$other-$$-3.json" "$out/.shapes.tmp-$other-$$-0/000_ellipsoid_000.csv"
cp -r "$work/old/shapes" "$out/.shapes.old-$other-$$-4"
"$bin" correspond "${new_options[@]}" --out "$out" > /dev/null 2> "$work/leftovers.log" ||
  { cat "$work/leftovers.log"; fail "correspond: another host's leftovers stopped the rerun"; }
[ "$(which_set "$out" "correspond, leftovers")" = new ] || fail "correspond, leftovers: not the new set"
no_temporaries "correspond, another host's leftovers"
echo "ok: correspond: leftovers of another host, a living PID and PID 1 removed; the run went on"
# A swap without exchange (NFS) killed between its renames on another node:
# --out gone, the old set and its whole checkpoint retired beside it. The
# rerun puts them back and goes on from the checkpoint.
out="$work/retired"
cp -r "$work/old" "$out"
KILL_AT_RENAME="$out" KILL_AT_RENAME_WHEN=before LD_PRELOAD="$shim" \
  bash -c '"$@"; exit $?' _ "$bin" correspond "${new_options[@]}" --out "$out" > /dev/null 2>&1 || true
[ -f "$out/checkpoint/packed.json" ] || fail "retired: no whole checkpoint to retire"
mv "$out" "$work/.retired.old-$other-$$-0"
"$bin" correspond "${new_options[@]}" --out "$out" > /dev/null 2> "$work/retired.log" || { cat "$work/retired.log"; fail "retired: the rerun"; }
grep -q "resuming from" "$work/retired.log" || { cat "$work/retired.log"; fail "retired: the old set and checkpoint were not put back"; }
[ "$(which_set "$out" "retired")" = new ] || fail "retired: not the new set"
no_temporaries "correspond, a retired set of another host"
echo "ok: correspond: a set another host retired put back, its checkpoint resumed"
out="$work/batch_leftovers"
cp -r "$work/batch_new" "$out"
mkdir "$out/.sphere.tmp-$other-$$-0" "$out/.torus.tmp-$host-1-1"
touch "$out/.summary.tmp-$other-$$-2.json" "$out/.summary.tmp-$host-1-3.csv"
# A swap without exchange killed between its renames on another host: the folder retired, none in its place.
mv "$out/patch" "$out/.patch.old-$other-$$-4"
"$bin" batch "${batch_inputs[@]}" -n 16 --out "$out" > /dev/null 2> "$work/batch_leftovers.log" ||
  { cat "$work/batch_leftovers.log"; fail "batch: another host's leftovers stopped the rerun"; }
grep -q "patch: ok (kept" "$work/batch_leftovers.log" || fail "batch: the retired folder was not put back"
batch_set "$out" "batch, leftovers" new
no_temporaries "batch, another host's leftovers"
echo "ok: batch: leftovers of another host, a living PID and PID 1 removed, a retired folder put back; the run went on"
echo "ok: $kills kills over an older set, each leaving a whole set"
