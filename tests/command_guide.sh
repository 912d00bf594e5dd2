#!/usr/bin/env bash
# command_guide.sh MESHPARTICLES VERSION: what a new user meets first.
# `--version` names the build's version; a bare `meshparticles` prints the
# commands and exits 2; a misspelt command is named with the closest one;
# `completion bash` is valid bash that completes commands and each command's
# own options, and leaves file names to bash.
set -euo pipefail
bin=$1 version=$2
fail() { echo "FAIL: $*"; exit 1; }

[ "$("$bin" --version)" = "meshparticles $version" ] || fail "--version printed '$("$bin" --version)'"

set +e
usage=$("$bin" 2>&1 >/dev/null); code=$?
set -e
[ "$code" -eq 2 ] || fail "bare meshparticles exited $code, expected 2"
for command in run batch quality compare completion; do
  grep -Eq "^  $command +[A-Z]" <<<"$usage" || fail "the usage does not list '$command' with its description"
done

set +e
typo=$("$bin" rnu mesh.off 2>&1 >/dev/null); code=$?
set -e
[ "$code" -eq 2 ] || fail "a misspelt command exited $code"
[ "$(grep -c '' <<<"$typo")" -eq 1 ] || fail "a misspelt command answered in more than one line: $typo"
grep -q "unknown command 'rnu'; did you mean 'run'? (commands: info, " <<<"$typo" || fail "misspelt command: $typo"
set +e
far=$("$bin" frobnicate 2>&1 >/dev/null)
set -e
grep -q "unknown command 'frobnicate' (commands: " <<<"$far" || fail "a word far from every command: $far"

script=$("$bin" completion bash)
bash -n <<<"$script" || fail "the completion script is not valid bash"
# shellcheck disable=SC1090
source <(printf '%s\n' "$script")
complete_words() {  # complete_words WORD...: COMPREPLY for the last word, space-separated
  COMP_WORDS=("$@")
  COMP_CWORD=$(($# - 1))
  COMPREPLY=()
  _meshparticles
  echo "${COMPREPLY[*]}"
}
[ "$(complete_words meshparticles ru)" = "run" ] || fail "'ru' completes to '$(complete_words meshparticles ru)'"
[ "$(complete_words meshparticles --vers)" = "--version" ] || fail "'--vers' completes to '$(complete_words meshparticles --vers)'"
[ "$(complete_words meshparticles run --iter)" = "--iterations" ] || fail "run --iter: '$(complete_words meshparticles run --iter)'"
[ "$(complete_words meshparticles info --iter)" = "" ] || fail "info has no --iterations, got '$(complete_words meshparticles info --iter)'"
[ "$(complete_words meshparticles run mesh)" = "" ] || fail "a file name is left to bash"
echo "ok: version, usage, misspelt commands and bash completion"
