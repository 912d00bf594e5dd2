#!/usr/bin/env bash
# non_utf8_paths.sh MESHPARTICLES MESH WORKDIR: a mesh file and an output
# folder whose names are not UTF-8 (Linux allows any bytes but / and NUL)
# run like any other: `info --json`, `run` and `batch` write valid JSON with
# the stray bytes as \xHH, and an error naming such a file is one valid
# UTF-8 line (issue 50, item 13).
set -uo pipefail
bin=$1 mesh=$2 work=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || exit 1
odd=$work/$'\xff'.off
cp "$mesh" "$odd" || exit 1

# valid_json FILE: the JSON parses (Python's reader is strict about UTF-8) and holds PATTERN.
valid_json() {
  python3 -c 'import json, sys; json.loads(open(sys.argv[1], "rb").read().decode("utf-8"))' "$1" ||
    fail "$1: not valid UTF-8 JSON"
  grep -Fq -- "$2" "$1" || fail "$1 does not hold $2: $(cat "$1")"
}

"$bin" info "$odd" --json >"$work/info.json" || fail "info --json: exit $?"
valid_json "$work/info.json" '\\xff.off'
echo "ok: info --json"

"$bin" run "$odd" -n 2 --no-cache -q --out "$work/"$'\xfe'-out || fail "run: exit $?"
valid_json "$work/"$'\xfe'-out/report.json '\\xff.off'
valid_json "$work/"$'\xfe'-out/report.json '\\xfe-out'
echo "ok: run"

"$bin" batch "$odd" -n 2 --no-cache -q --out "$work/batch" >/dev/null || fail "batch: exit $?"
valid_json "$work/batch/summary.json" '\\xff.off'
# Run again, the output is kept: the path it recorded (escaped) is the mesh's.
"$bin" batch "$odd" -n 2 --no-cache --out "$work/batch" >/dev/null 2>"$work/batch_again.log" || fail "batch again: exit $?"
grep -q "ok (kept: an earlier output" "$work/batch_again.log" || fail "batch again recomputed: $(cat "$work/batch_again.log")"
echo "ok: batch, and again"

errors=$("$bin" info "$work/"$'\xfd'-missing.off 2>&1 >/dev/null)
code=$?
[ "$code" -eq 2 ] || fail "missing file: exit $code, expected 2: $errors"
grep -Fq -- '\xfd-missing.off: no such file' <<<"$errors" || fail "missing file: '$errors' does not name it escaped"
python3 -c 'import sys; sys.stdin.buffer.read().decode("utf-8")' <<<"$errors" || fail "missing file: message not UTF-8"
echo "ok: missing file: $errors"
