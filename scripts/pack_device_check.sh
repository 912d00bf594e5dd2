#!/usr/bin/env bash
# Packs what scripts/device_check.sh needs on a GPU machine that has NVIDIA's
# driver and nothing of ours (a CUDA image, no network): the Release build's
# meshparticles and device_tests, the libraries they load that such an image
# lacks (Debian's OpenCL loader, OpenMesh, Open MPI, ...; not the C and C++
# runtimes, which it has), the 26 benchmark models of docs/PERFORMANCE.md and
# their cases (n = 256, 1,024 and 4,096 where the model has at least 4n vertices), and
# a scan if given. DIR should sit in the checkout and be ignored by git, so
# that the device tool's `carry` takes it along (about 36 MiB with igea).
#
#   scripts/pack_device_check.sh [--scan PATH] DIR
#
# PATH: igea.ply of github.com/alecjacobson/common-3d-test-models (134k
# vertices), run at n = 20,000. Build first (scripts/run.sh, then
# `make -C build device_tests`); the models come from scripts/cgal_meshes.sh.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${MESHPARTICLES_BUILD:-$ROOT/build}"
scan="" dir=""
usage="usage: $0 [--scan PATH] DIR"
while [ $# -gt 0 ]; do
  case "$1" in
    --scan) scan="$2"; shift 2 ;;
    -*) echo "$usage" >&2; exit 2 ;;
    *) dir="$1"; shift ;;
  esac
done
[ -n "$dir" ] || { echo "$usage" >&2; exit 2; }
for program in meshparticles device_tests; do
  [ -x "$BUILD/$program" ] || { echo "no $BUILD/$program: build it first" >&2; exit 1; }
done
models=(cow bull hand elephant camel armadillo bunny00 ChineseDragon-10kv bear cheese diplodocus fandisk homer knot2
        lion lion-head man mannequin-devil turbine blade pig triceratops dino elk mushroom femur)
cgal="${MESHPARTICLES_CGAL_MESHES:-$("$ROOT/scripts/cgal_meshes.sh")}"

rm -rf "$dir"
mkdir -p "$dir/bin" "$dir/lib" "$dir/meshes"
cp "$BUILD/meshparticles" "$BUILD/device_tests" "$dir/bin/"
ldd "$BUILD/meshparticles" "$BUILD/device_tests" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | sort -u |
  while read -r library; do
    case "$(basename "$library")" in
      libc.so.* | libm.so.* | libstdc++.so.* | libgcc_s.so.* | ld-linux*) ;;
      *) cp -L "$library" "$dir/lib/" ;;
    esac
  done
: > "$dir/cases.txt"
for model in "${models[@]}"; do
  cp "$cgal/$model.off" "$dir/meshes/"
  # The vertex count: the first number of the OFF header.
  vertices=$(awk '/^[[:space:]]*(#|$)/ || /^[[:space:]]*[A-Z]*OFF[[:space:]]*$/ { next } { print $1; exit }' \
             "$cgal/$model.off")
  for n in 256 1024 4096; do
    if [ "$vertices" -ge $((4 * n)) ]; then echo "$model.off $n" >> "$dir/cases.txt"; fi
  done
done
if [ -n "$scan" ]; then
  cp "$scan" "$dir/meshes/"
  echo "$(basename "$scan") 20000" > "$dir/scans.txt"
fi
echo "packed $(wc -l < "$dir/cases.txt") cases into $dir ($(du -sh "$dir" | cut -f1))" >&2
