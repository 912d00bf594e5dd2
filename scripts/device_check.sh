#!/usr/bin/env bash
# The device check, for a GPU machine lent for minutes, the most wanted
# first: spread's device tests on its OpenCL; the host path on 1, 2, 4, 8 and
# every core (THREADS_CASES: "MESH N" lines, default the scan and bunny00 at
# 4,096); spread timed on the host path (all cores) and with --device case by
# case (each case by both in turn, their particles compared); the scan and
# the 1M sphere (SPHERE_DEVICE=0: the sphere on the host path only); then the
# rest of the device suite (REST=0: not). Every step runs inside what is
# left of BUDGET seconds (default 520); the threads step and the cases leave
# RESERVE seconds (default 230) for the scan and the sphere (RESERVE=0: the
# cases to the end, neither of those; RESERVE over BUDGET: neither step).
#
#   BUDGET=520 scripts/device_check.sh DIR
#
# DIR: what scripts/pack_device_check.sh packed. Results go to $OUT (the
# device tool's folder; default DIR/out): env.txt, tests_spread.log,
# runs.tsv (case, path, exit status, wall s, rho; then "bytes same" or
# "differ"), threads.tsv (case, threads, whether the particles are 1
# thread's bytes), tests_rest.log and reports.tgz (every run's report.json
# and summary). MESHPARTICLES_DEVICE picks the device (default NVIDIA),
# SPREAD_TESTS the first tests (a gtest filter). Where NVIDIA's OpenCL
# library is found, the loader that DIR carries is pointed at it.
set -uo pipefail
dir="$(cd "${1:?usage: $0 DIR}" && pwd)"
OUT="${OUT:-$dir/out}"
mkdir -p "$OUT"
budget=${BUDGET:-520} reserve=${RESERVE:-230}
start=$(date +%s)
left() { echo $((start + budget - $(date +%s))); }
export LD_LIBRARY_PATH="$dir/lib"
nvidia_icd=""
for library in /usr/local/nvidia/lib64/libnvidia-opencl.so.1 /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1; do
  if [ -z "$nvidia_icd" ] && [ -e "$library" ]; then nvidia_icd=$library; fi
done
if [ -n "$nvidia_icd" ]; then
  mkdir -p /tmp/device_check_icd
  echo "$nvidia_icd" > /tmp/device_check_icd/nvidia.icd
  export OCL_ICD_VENDORS=/tmp/device_check_icd
fi
export MESHPARTICLES_DEVICE="${MESHPARTICLES_DEVICE:-NVIDIA}" MESHPARTICLES_CGAL_MESHES="$dir/meshes"
bin="$dir/bin/meshparticles" tests="$dir/bin/device_tests" work=/tmp/device_check
mkdir -p "$work"
{ date; nvidia-smi -L 2>&1; echo "cores $(nproc)"; echo "icd $nvidia_icd"; "$bin" --version; "$bin" devices; } \
  > "$OUT/env.txt" 2>&1
cat "$OUT/env.txt"
# Stops at once where the device cannot be had (a run that asks for it exits 2).
"$bin" run -n 16 --iterations 0 --device "$MESHPARTICLES_DEVICE" -q --out "$work/probe" > /dev/null || exit 1

spread_tests="${SPREAD_TESTS:-*DeviceSpreadMeasurement*:*DeviceVoronoi*:*DeviceEvening*:*DeviceRun*:*DeviceBalls*}"
timeout $(( $(left) < 170 ? $(left) : 170 )) "$tests" --gtest_filter="$spread_tests" > "$OUT/tests_spread.log" 2>&1
echo "spread's device tests: exit $? at $(( $(date +%s) - start )) s"
tail -3 "$OUT/tests_spread.log"

# timed LABEL RUN_DIR ARGS...: one run, a line of runs.tsv.
timed() {
  local label=$1 run=$2
  shift 2
  local began=$EPOCHREALTIME
  timeout $(( $(left) > 5 ? $(left) : 5 )) "$bin" run "$@" --out "$run" -q --no-cache > "$run.log" 2>&1
  local status=$? ended=$EPOCHREALTIME rho
  rho=$(grep -o 'rho [0-9.]*' "$run.log" | head -1)
  awk -v l="$label" -v s=$status -v a="$began" -v b="$ended" -v q="$rho" \
    'BEGIN { printf "%s\t%s\t%.3f\t%s\n", l, s, b - a, q }' | tee -a "$OUT/runs.tsv"
}
# both MESH N: the host path, then --device, then whether their particles are the same bytes.
both() {
  local mesh=$1 n=$2 name
  name=$(basename "${mesh%.*}")-$n
  timed "$name host" "$work/$name-host" "$mesh" -n "$n"
  timed "$name device" "$work/$name-device" "$mesh" -n "$n" --device "$MESHPARTICLES_DEVICE"
  if cmp -s "$work/$name-host/particles.particles" "$work/$name-device/particles.particles"; then
    printf '%s bytes\tsame\n' "$name" | tee -a "$OUT/runs.tsv"
  else
    printf '%s bytes\tdiffer\n' "$name" | tee -a "$OUT/runs.tsv"
  fi
}
# The host path on 1, 2, 4, 8 and every core (THREADS_CASES: "MESH N" lines,
# default the scan and bunny00 at 4,096): wall s in threads.tsv, whether the
# particles are 1 thread's bytes, each run's report.json (per stage) in reports.tgz.
cores=$(nproc)
threads_cases="${THREADS_CASES:-$(cat "$dir/scans.txt" 2>/dev/null; echo "bunny00.off 4096")}"
while read -r mesh n; do
  [ -n "$mesh" ] || continue
  name=$(basename "${mesh%.*}")-$n
  for t in $(printf "%s\n" 1 2 4 8 "$cores" | sort -nu); do  # every core once, where it is 2, 4 or 8
    [ "$(left)" -lt $((reserve + 60)) ] && break 2
    timed "$name threads $t" "$work/$name-t$t" "$dir/meshes/$mesh" -n "$n" --threads "$t"
    if cmp -s "$work/$name-t1/particles.particles" "$work/$name-t$t/particles.particles"; then same=same; else same=differ; fi
    printf '%s\t%s\t%s\n' "$name" "$t" "$same" | tee -a "$OUT/threads.tsv"
  done
done <<< "$threads_cases"
while read -r mesh n; do
  [ "$(left)" -lt $((reserve + 30)) ] && break
  both "$dir/meshes/$mesh" "$n"
done < "$dir/cases.txt"
if [ -f "$dir/scans.txt" ] && [ "$(left)" -gt 200 ]; then
  while read -r mesh n; do both "$dir/meshes/$mesh" "$n"; done < "$dir/scans.txt"
fi
if [ "$(left)" -gt 150 ]; then
  "$bin" generate sphere --vertices 1000000 --out-dir "$work/large" > /dev/null 2>&1
  if [ "$(left)" -gt 60 ]; then
    if [ "${SPHERE_DEVICE:-1}" = 0 ]; then
      timed "sphere_998562-100000 host" "$work/sphere_998562-100000-host" "$work/large/sphere_998562.off" -n 100000
    else
      both "$work/large/sphere_998562.off" 100000
    fi
  fi
fi
if [ "${REST:-1}" != 0 ] && [ "$(left)" -gt 20 ]; then
  timeout "$(left)" "$tests" --gtest_filter="-$spread_tests" > "$OUT/tests_rest.log" 2>&1
  echo "the rest of the device suite: exit $? at $(( $(date +%s) - start )) s"
  tail -3 "$OUT/tests_rest.log"
fi
(cd "$work" && tar czf "$OUT/reports.tgz" ./*/report.json ./*.log 2>/dev/null)
echo "done at $(( $(date +%s) - start )) s"
