#!/usr/bin/env bash
# mpi_shape_share_test.sh MODE MESHPARTICLES WORKDIR [MPIEXEC]: the test of
# host/correspondence/mpi_shape_share.cpp (built only with MPI, so tested
# through the program, `cli.correspond_mpi`): `correspond` on
# a small population with a known map (generate --population --family
# ellipsoid), its outputs compared byte for byte with one run of one
# process that nothing interrupted (correspond_checkpoint.sh kills one
# process at every write):
#   mpi     mpirun -n 2 and -n 3 (more ranks than cores): the same outputs;
#           then mpirun -n 2 killed after the packing, resumed by one process
set -euo pipefail
mode=$1 bin=$2 work=$3 mpiexec=${4:-}
source "$(dirname "${BASH_SOURCE[0]}")/../correspond_reference.sh"
# kill_when FILE COMMAND...: starts COMMAND, kills it (and its children)
# with SIGKILL as soon as FILE exists, or lets it finish.
kill_when() {
  local file=$1
  shift
  setsid "$@" > /dev/null 2>&1 &
  local pid=$!
  while kill -0 "$pid" 2> /dev/null && [ ! -e "$file" ]; do sleep 0.005; done
  kill -9 -- -"$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null || true
  # MPI ranks may sit outside the launcher's process group: none may go on writing.
  pkill -9 -f -- "--out $out\$" 2> /dev/null || true
  while pgrep -f -- "--out $out\$" > /dev/null; do sleep 0.01; done
}
mpi_root=()
[ "$(id -u)" -eq 0 ] && mpi_root=(--allow-run-as-root)

case "$mode" in
mpi)
  for ranks in 2 3; do
    out="$work/ranks_$ranks"
    "$mpiexec" "${mpi_root[@]}" -n "$ranks" --oversubscribe "$bin" correspond "${options[@]}" --out "$out" \
      > /dev/null 2> "$out.log" || { cat "$out.log"; fail "mpirun -n $ranks correspond failed"; }
    same "$out" "mpirun -n $ranks"
  done
  out="$work/ranks_killed"
  kill_when "$out/checkpoint/packed.json" "$mpiexec" "${mpi_root[@]}" -n 2 --oversubscribe "$bin" correspond \
    "${options[@]}" --out "$out"
  [ -e "$out/summary.json" ] && fail "mpirun finished before it could be killed"
  "$bin" correspond "${options[@]}" --out "$out" > /dev/null 2> "$out.log"
  grep -q "resuming from" "$out.log" || fail "one process did not resume what two ranks left"
  same "$out" "mpirun -n 2 killed after the packing, resumed by one process"
  ;;
*) fail "unknown mode $mode" ;;
esac
