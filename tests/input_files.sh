#!/usr/bin/env bash
# input_files.sh MESHPARTICLES MESH WORKDIR: every file the program reads,
# given as a FIFO with no writer, is refused at once in one line naming it
# (exit 2), never waited on: particle files (quality, compare), a batch's
# mesh list, --tuning-file and the default tuning file, and the mesh itself.
set -uo pipefail
bin=$1 mesh=$2 work=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work/config/meshparticles" || exit 1
fifo=$work/fifo
mkfifo "$fifo" "$work/list.txt" "$work/config/meshparticles/tuning.json" || exit 1

# expect LABEL PATTERN COMMAND...: exit 2 within 20 s, one line matching PATTERN.
expect() {
  local label=$1 pattern=$2
  shift 2
  local errors code
  errors=$(timeout 20 "$@" 2>&1 >/dev/null)
  code=$?
  [ "$code" -ne 124 ] || fail "$label: still waiting after 20 s"
  [ "$code" -eq 2 ] || fail "$label: exit $code, expected 2: $errors"
  [ "$(grep -c '' <<<"$errors")" -eq 1 ] || fail "$label: not one line: $errors"
  grep -Eq -- "$pattern" <<<"$errors" || fail "$label: '$errors' does not match /$pattern/"
  echo "ok: $label: $errors"
}
refused="not a regular file \(a device, FIFO or socket\), refused"
expect "mesh" "$fifo: $refused" "$bin" info "$fifo"
expect "quality particles" "$fifo: $refused" "$bin" quality "$mesh" "$fifo"
expect "compare particles" "$fifo: $refused" "$bin" compare "$mesh" "$fifo" "$fifo"
expect "batch list" "mesh list $work/list.txt: $refused" "$bin" batch "$work/list.txt" --out "$work/batch"
# A tuning file that cannot be read is set aside with a warning (as a
# malformed one is): the run goes on with the built-in sizes.
errors=$(timeout 60 "$bin" run "$mesh" -n 4 --method paper --backend field --tuning-file "$fifo" --out "$work/run" 2>&1 >/dev/null)
code=$?
[ "$code" -ne 124 ] || fail "--tuning-file FIFO: still waiting after 60 s"
if [ "$code" -eq 0 ]; then
  grep -Eq "warning: tuning file $fifo: $refused.*built-in sizes" <<<"$errors" || fail "--tuning-file FIFO: no warning: $errors"
  echo "ok: --tuning-file FIFO: warned and ran"
elif [ "$code" -eq 3 ]; then
  echo "ok: --tuning-file FIFO: no OpenCL runtime here (exit 3), nothing to tune"
else
  fail "--tuning-file FIFO: exit $code: $errors"
fi
errors=$(XDG_CONFIG_HOME=$work/config timeout 60 "$bin" run "$mesh" -n 4 --method paper --backend field --out "$work/run" 2>&1 >/dev/null)
code=$?
[ "$code" -ne 124 ] || fail "default tuning file FIFO: still waiting after 60 s"
if [ "$code" -eq 0 ]; then
  grep -q "warning: tuning file $work/config/meshparticles/tuning.json: not a regular file" <<<"$errors" ||
    fail "default tuning file FIFO: no warning: $errors"
  echo "ok: default tuning file FIFO: warned and ran"
elif [ "$code" -ne 3 ]; then
  fail "default tuning file FIFO: exit $code: $errors"
fi
echo "every FIFO refused at once"
