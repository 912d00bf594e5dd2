#!/usr/bin/env bash
# expect_exit.sh CODE REGEX COMMAND...: runs COMMAND and passes when it exits
# with CODE and its stderr is one line matching REGEX (an extended regex).
# With MULTILINE=1 in the environment, more lines may come (a kernel's build
# log after the error, and whatever the OpenCL compiler prints itself).
set -u
expected_code=$1 pattern=$2
shift 2
stderr_file=$(mktemp)
trap 'rm -f "$stderr_file"' EXIT
"$@" >/dev/null 2>"$stderr_file"
code=$?
lines=$(grep -c '' "$stderr_file")
if [ "$code" -ne "$expected_code" ]; then
  echo "FAIL: exit code $code, expected $expected_code"; cat "$stderr_file"; exit 1
fi
if [ "$expected_code" -ne 0 ] && [ "$lines" -ne 1 ] && [ "${MULTILINE:-0}" != 1 ]; then
  echo "FAIL: expected a one-line error, got $lines lines:"; cat "$stderr_file"; exit 1
fi
if ! grep -Eq -- "$pattern" "$stderr_file"; then
  echo "FAIL: stderr does not match /$pattern/:"; cat "$stderr_file"; exit 1
fi
echo "ok: exit $code, $(head -c 300 "$stderr_file")"
