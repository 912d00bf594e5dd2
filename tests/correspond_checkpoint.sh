#!/usr/bin/env bash
# correspond_checkpoint.sh MESHPARTICLES SHIM WORKDIR: `correspond`'s
# checkpoint and outputs against kills, damage and a second run, on a small
# population (generate --population --family ellipsoid). SHIM is
# tests/kill_at_rename_shim.cpp's library: it kills (or stops) the run at
# the rename that completes a chosen file, before or after it.
#   kills    killed as each checkpoint entry and each output is written,
#            before and after its rename, then run again: the outputs of one
#            run that nothing interrupted, byte for byte, and no checkpoint left
#   damage   a checkpoint edited, cut short, moved or of another request: the
#            run says it is damaged and starts anew; values that pass the
#            digest yet no run could have written (an id past the mesh, a row
#            short, a particle count other than -n, weights outside [0, 1] or
#            not summing to 1, an entry of another shape's mesh, two shapes'
#            entries swapped): one line, exit 2, the checkpoint removed; an
#            entry made a folder: damaged, run anew; never a crash
#   lock     a second run into the --out of one in progress is refused in one
#            line; the first ends with its own outputs
set -euo pipefail
# Under the sanitizer build, its runtime wants to come first; the shim only wraps rename().
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
bin=$1 shim=$2 work=$3
# Kills and reruns test the checkpoint, not the fit: the quicker deformation
# (the default's bytes across processes: mpi_shape_share_test.sh).
deformation=smooth
source "$(dirname "${BASH_SOURCE[0]}")/correspond_reference.sh"

# killed_at SUFFIX WHEN OUT: the run into OUT killed at the rename onto SUFFIX.
# (Through a second bash, whose note of the kill goes to the log.)
killed_at() {
  local status=0
  KILL_AT_RENAME="$1" KILL_AT_RENAME_WHEN="$2" LD_PRELOAD="$shim" \
    bash -c '"$@"; exit $?' _ "$bin" correspond "${options[@]}" --out "$3" > /dev/null 2> "$3.killed.log" || status=$?
  [ "$status" -eq 137 ] || fail "killed at $1 ($2): exit $status, not SIGKILL: the rename never came"
}

# --- kills: every checkpoint entry and every output, before and after its rename
for target in checkpoint/request.json checkpoint/template.json checkpoint/transfer/002.json \
  checkpoint/iterated/001.json checkpoint/iterated.json checkpoint/packed/003.json checkpoint/packed.json \
  checkpoint/settled/001.json /shapes /model /summary.json; do
  for when in before after; do
    out="$work/killed_$(echo "$target" | tr -c 'a-z0-9\n' _)_$when"
    killed_at "$target" "$when" "$out"
    "$bin" correspond "${options[@]}" --out "$out" > /dev/null 2> "$out.log" || { cat "$out.log"; fail "run again after $target ($when) failed"; }
    same "$out" "killed $when $target, run again"
  done
done
# Stages kept are not run again: after the packing's record, no refinement.
grep -q "resuming from" "$work/killed_checkpoint_packed_json_after.log" || fail "the run again did not resume"
if grep -E "^(refine|pack):" "$work/killed_checkpoint_packed_json_after.log"; then fail "the resumed run refined again"; fi

# --- damage: a whole checkpoint (killed as the outputs begin), then changed
killed="$work/killed_whole"
killed_at /shapes before "$killed"
# damaged NAME EDIT...: a copy of it with EDIT (a python statement on `values`,
# the entry's values, or `lines`, its two lines of text) done to entry NAME;
# with FORGE=1 the header's size and SHA-256 are made to match the edit.
damaged() {
  local name=$1 edit=$2 out="$work/damaged"
  rm -rf "$out" && cp -r "$killed" "$out"
  FORGE=${FORGE:-0} /usr/bin/python3 - "$out/checkpoint/$name" "$edit" <<'PY'
import hashlib, json, os, sys
path, edit = sys.argv[1], sys.argv[2]
lines = open(path).read().split("\n")[:2]
values = json.loads(lines[1])
rows = lambda v: v["locations"] if isinstance(v, dict) else v  # a stage's shape entry: its rows
if edit != "pass":
    exec(edit)
    if "lines" not in edit:
        lines[1] = values if isinstance(values, str) else json.dumps(values, separators=(",", ":"))
if os.environ["FORGE"] == "1":
    header = json.loads(lines[0])
    header["bytes"] = len(lines[1].encode())
    header["sha256"] = hashlib.sha256(lines[1].encode()).hexdigest()
    lines[0] = json.dumps(header, separators=(",", ":"))
open(path, "w").write("\n".join(lines) + "\n")
PY
}
# Starts anew: says why, and is stopped once the template is written again.
anew() {  # anew WHAT
  local out="$work/damaged" status=0
  KILL_AT_RENAME=checkpoint/template.json LD_PRELOAD="$shim" \
    bash -c '"$@"; exit $?' _ "$bin" correspond "${options[@]}" --out "$out" > /dev/null 2> "$out.log" || status=$?
  grep -q "is damaged (.*): removed it: starting anew" "$out.log" || { cat "$out.log"; fail "$1: not found damaged"; }
  [ "$status" -eq 137 ] || { cat "$out.log"; fail "$1: it did not start anew (exit $status)"; }
  echo "ok: $1: $(grep -o 'damaged (.*)' "$out.log")"
}
damaged packed/001.json 'rows(values)[5][0] = 99999999'
anew "a triangle id edited"
damaged template.json 'values["particles"][0] = -5'
anew "a template corner edited"
damaged packed/001.json 'del rows(values)[-1]'
anew "a row cut"
damaged packed/001.json 'values = json.dumps(values).replace(",", ",,", 1)'
anew "a number missing"
damaged settled/001.json 'values["locations"][3][7] += 1e-9'
anew "a coordinate edited"
damaged settled/002.json 'lines[1] = lines[1].replace("1", "2", 1)'
anew "a digit changed, the size kept"
damaged iterated.json 'lines[0] = lines[0].replace("\"bytes\":", "\"bytes\":1")'
anew "a header's size edited"
damaged transfer/002.json 'lines = [lines[0]]'
anew "an entry cut short"
damaged packed.json 'lines = ["", ""]'
anew "an entry emptied"
cp "$killed/checkpoint/packed/001.json" "$killed/checkpoint/packed/002.json.moved"
damaged packed/001.json 'pass'
mv "$work/damaged/checkpoint/packed/002.json.moved" "$work/damaged/checkpoint/packed/002.json"
rm "$killed/checkpoint/packed/002.json.moved"
anew "an entry moved onto another shape's"
damaged packed/001.json 'pass'
touch "$work/damaged/checkpoint/notes.txt"
anew "a file that is no entry"
# An entry made a folder: damaged like any other, never an internal error.
for name in template.json request.json packed.json packed/002.json; do
  damaged packed/001.json 'pass'
  rm "$work/damaged/checkpoint/$name" && mkdir "$work/damaged/checkpoint/$name"
  anew "$name made a folder"
done
# The whole damaged run goes on to the reference's outputs.
damaged transfer/002.json 'values["alignment"]["scale"] *= 2'
"$bin" correspond "${options[@]}" --out "$work/damaged" > /dev/null 2> "$work/damaged.log"
grep -q "is damaged" "$work/damaged.log" || fail "an edited scale was taken"
same "$work/damaged" "an edited checkpoint, run anew"

# Forged: the digest matches, the values cannot be this run's.
refused() {  # refused WHAT PATTERN
  local out="$work/damaged" status=0
  "$bin" correspond "${options[@]}" -q --out "$out" > /dev/null 2> "$out.log" || status=$?
  [ "$status" -eq 2 ] || { cat "$out.log"; fail "$1: exit $status, not 2"; }
  [ "$(wc -l < "$out.log")" -eq 1 ] || { cat "$out.log"; fail "$1: not one line"; }
  grep -q "is damaged (.*$2.*): removed .*checkpoint; run the command again" "$out.log" || { cat "$out.log"; fail "$1: unclear refusal"; }
  [ -e "$out/checkpoint" ] && fail "$1: the damaged checkpoint was kept"
  echo "ok: $1: $(cat "$out.log")"
}
FORGE=1 damaged packed/001.json 'rows(values)[5][0] = 99999999'
refused "a forged triangle id" "triangle 99999999 of"
FORGE=1 damaged packed/001.json 'rows(values)[5][0] = 2**32'
refused "a forged triangle id of 2^32" "triangle 4294967296 of"
FORGE=1 damaged template.json 'values["particles"][0] = -5'
refused "a forged template corner" "vertex -5"
FORGE=1 damaged template.json 'values["particles"][0:3] = values["particles"][2::-1]'
refused "forged template corners, a triangle turned over" "are no triangle of the template"
FORGE=1 damaged packed/001.json 'del rows(values)[-1]'
refused "a forged row cut" "47 rows for 48 particles"
FORGE=1 damaged packed/001.json 'rows(values)[5] = rows(values)[5][:3]'
refused "a forged number missing" "json.exception"
FORGE=1 damaged settled/001.json 'values["locations"][2][6] = 5000'
refused "a forged settled vertex" "vertex 5000 of"
FORGE=1 damaged transfer/002.json 'del values["alignment"]["rotation"]'
refused "a forged alignment without rotation" "rotation"
# Forged against what the request fixes: the count of -n, barycentric
# weights, the mesh of each shape's slot.
FORGE=1 damaged template.json 'values["particles"] = values["particles"][:-6]'
# As killed once the template was kept: the shapes' entries would have 48 rows.
find "$work/damaged/checkpoint" -mindepth 1 ! -name request.json ! -name template.json -delete
refused "a forged template one particle short" "47 particles, not the 48 of -n"
FORGE=1 damaged template.json 'values["particles"][3:6] = [0.5, 0.5, 0.5]'
refused "forged template weights that sum to 1.5" "that sum to 1.5, not 1"
FORGE=1 damaged packed/001.json 'rows(values)[5][1] += 0.25'
refused "forged weights that sum to 1.25" "that sum to .*, not 1"
FORGE=1 damaged settled/001.json 'values["locations"][4][3:6] = [1.5, -0.25, -0.25]'
refused "a forged weight outside [0, 1], the sum 1" "weight 1.5 outside \\[0, 1\\]"
# swapped A B: entries A and B of the whole checkpoint swapped, each re-signed under its own name.
swapped() {
  rm -rf "$work/damaged" && cp -r "$killed" "$work/damaged"
  /usr/bin/python3 - "$work/damaged/checkpoint" "$1" "$2" <<'PY'
import hashlib, json, sys
folder, a, b = sys.argv[1:]
text = {name: open(f"{folder}/{name}.json").read().split("\n")[:2] for name in (a, b)}
for name, other in ((a, b), (b, a)):
    header, values = json.loads(text[name][0]), text[other][1]
    header["bytes"], header["sha256"] = len(values.encode()), hashlib.sha256(values.encode()).hexdigest()
    open(f"{folder}/{name}.json", "w").write(json.dumps(header, separators=(",", ":")) + "\n" + values + "\n")
PY
}
swapped settled/001 settled/002
refused "two shapes' settled entries swapped, re-signed" "an entry of mesh .*ellipsoid_00[12].off.*, not .*ellipsoid_00[12].off"
swapped transfer/003 transfer/001
refused "two shapes' transfers swapped, re-signed" "an entry of mesh .*ellipsoid_00[13].off.*, not .*ellipsoid_00[13].off"
swapped packed/002 packed/004
refused "two shapes' packed entries swapped, re-signed" "an entry of mesh .*ellipsoid_00[24].off.*, not .*ellipsoid_00[24].off"
# A checkpoint of other parameters is not taken.
rm -rf "$work/other" && cp -r "$killed" "$work/other"
"$bin" correspond "$work/shapes" -n 40 --samples 10 --refine-iterations 60 --out "$work/other" > /dev/null 2> "$work/other.log"
grep -q "of other inputs or parameters: starting anew" "$work/other.log" || fail "a checkpoint of other parameters was taken"
echo "ok: a checkpoint of other parameters, run anew"

# --- lock: the first run stopped as its template is written, holding --out
out="$work/locked"
KILL_AT_RENAME=checkpoint/template.json KILL_AT_RENAME_SIGNAL=STOP LD_PRELOAD="$shim" \
  "$bin" correspond "${options[@]}" --out "$out" > /dev/null 2> "$out.first.log" &
first=$!
until [ "$(ps -o stat= -p "$first" | cut -c1)" = T ]; do
  kill -0 "$first" 2> /dev/null || fail "the first run ended before it held --out"
  sleep 0.05
done
status=0
"$bin" correspond "$work/shapes" -n 40 --samples 10 --out "$out" > /dev/null 2> "$out.second.log" || status=$?
kill -CONT "$first"
wait "$first" || fail "the first run failed after the second was refused"
[ "$status" -eq 2 ] || { cat "$out.second.log"; fail "a second run into a busy --out: exit $status, not 2"; }
grep -q "is in use by another correspond" "$out.second.log" || { cat "$out.second.log"; fail "unclear refusal of a busy --out"; }
same "$out" "a second run into a busy --out refused; the first's outputs are its own"
