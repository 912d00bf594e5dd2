#!/usr/bin/env bash
# Compiles every kernel offline for an NVIDIA-like target, at every size class
# the sweep uses, with warnings as errors, so a kernel that only PoCL accepts
# cannot land: clang -target nvptx64-nvidia-nvcl with libclc (Debian's
# clang-14 and libclc-14), through to PTX. Fails naming the file and the
# defines. Then every PTX must define every function it calls: a helper the
# compiler kept as a call but never defined (a plain C99 `inline` one) is an
# undefined symbol that some vendors refuse.
#
#   scripts/check_kernels.sh [KERNEL_DIR]     (default: kernels/)
#
# Installs clang-14 and libclc-14 when missing (as root or with sudo). Runs
# from ctest (label `kernels`); JOBS (default 2) compiles run at once.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
KERNELS="$(cd "${1:-$ROOT/kernels}" && pwd)"
JOBS="${JOBS:-2}"
CLANG=clang-14
LIBCLC=/usr/lib/clc/nvptx64--nvidiacl.bc

if ! command -v "$CLANG" >/dev/null || [ ! -f "$LIBCLC" ] || [ ! -f /usr/include/clc/clc.h ]; then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "check_kernels: need clang-14 and libclc-14 (root or sudo to install)" >&2; exit 1; }
    SUDO="sudo"
  fi
  echo "check_kernels: installing clang-14 libclc-14" >&2
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq >/dev/null
  $SUDO apt-get install -y -qq --no-install-recommends clang-14 libclc-14 >/dev/null
fi

# The options of host/opencl/program_builder.cpp, for the target, and:
# - libclc's declarations, not clang's opencl-c.h: clang 14 declares no
#   vload_half for __global pointers under CL1.2 on nvptx. Parsed once per
#   mode into a precompiled header (the same PTX, 2.5x faster);
# - libclc's definitions linked in, so the only undefined functions left in
#   the PTX are our own (libclc spells the same target nvptx64-unknown-
#   nvidiacl, with the same data layout: hence -Wno-linker-warnings);
# - warnings: -Wall -Wextra; -Wpedantic for clang's own extensions (GNU
#   statement expressions, zero-length arrays from a size class) that other
#   compilers refuse; -Wconversion for implicit 64-to-32-bit and float-to-int
#   conversions (the kernels cast explicitly, and it costs no noise);
#   -Wdouble-promotion for a float silently computed in double (slow on a
#   GPU, refused without fp64); -Wundef for a misspelt define read as 0.
#   Not -Wfloat-equal: the tie rule compares energies with == on purpose.
LANGUAGE=(-cl-std=CL1.2 -cl-unsafe-math-optimizations -target nvptx64-nvidia-nvcl)
COMPILE=(
  -Xclang -mlink-builtin-bitcode -Xclang "$LIBCLC" -Wno-linker-warnings
  -Werror -Wall -Wextra -Wpedantic -Wconversion -Wdouble-promotion -Wundef
  -I "$KERNELS" -S
)
# Files the host builds with FloatMath::exact (host/opencl/program_builder):
# without unsafe math, division and square root correctly rounded. Compiled
# so here (without the precompiled header, whose options differ), and their
# PTX may hold no fused multiply-add and no approximate operation.
EXACT_FILES="surface_voronoi.cl cavity_centres.cl"
EXACT_LANGUAGE=(-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt -target nvptx64-nvidia-nvcl)

# Two modes. core: every size class, with no optional extension (libclc's
# header needs the one it keeps), as any conformant OpenCL 1.2 device
# builds them: an extension used without an #ifdef fails. unoptimized: once
# per file, with every extension the target offers (the #ifdef'd paths
# compile too) and without optimization, so that every helper call stays a
# call and one without a definition shows in the PTX.
MODE_core=(-Xclang -cl-ext=-all,+cl_clang_storage_class_specifiers)
MODE_unoptimized=(-cl-opt-disable)

# The size classes of `sweep` (host/cli/sweep_command.cpp), and candidate
# slots (max valence + 1) of the committed meshes: the tetrahedron (4), the
# sphere, atrium and patch (11), high_valence (25).
WORK_GROUP_SIZES=8,16,32,64,128,256
TILE_SIZES=16,32,64,128,256,512,1024
CANDIDATE_SLOTS=4,11,25
BOTH=0,1
# The device balls' tables (host/geodesics/device_balls.cpp): the smallest, and 2,048 and 4,096 vertices.
SLOT_BITS=8,11,12

# One line per compile: FILE then its -D options (a define left out takes the
# file's default). `compiles FILE NAME=V1,V2 ...` adds the full product.
compiles() {
  local file=$1 name values value line
  shift
  local lines=("$file")
  for assignment in "$@"; do
    name=${assignment%%=*} values=${assignment#*=}
    local grown=()
    for line in "${lines[@]}"; do
      for value in ${values//,/ }; do grown+=("$line -D $name=$value"); done
    done
    lines=("${grown[@]}")
  done
  printf '%s\n' "${lines[@]}"
}

# Which defines each file reads (the host passes all of them to every file
# of a program). Each is crossed with every other it meets in the code, and
# only those: TILE_SIZE sizes the tile and its loop, which steps by
# WORK_GROUP_SIZE; the potential and the weight format each swap one helper
# that no size touches.
plan() {
  compiles apply_moves.cl
  compiles particle_energies.cl POTENTIAL_GAUSS=$BOTH
  compiles field_weights.cl POTENTIAL_GAUSS=$BOTH WEIGHTS_HALF=$BOTH
  compiles field_accumulate.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES WEIGHTS_HALF=$BOTH
  compiles field_update.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES CANDIDATE_SLOTS=$CANDIDATE_SLOTS WEIGHTS_HALF=$BOTH
  compiles field_iterations.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES CANDIDATE_SLOTS=$CANDIDATE_SLOTS WEIGHTS_HALF=$BOTH
  compiles local_field.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES CANDIDATE_SLOTS=$CANDIDATE_SLOTS POTENTIAL_GAUSS=$BOTH
  compiles naive_update.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES CANDIDATE_SLOTS=$CANDIDATE_SLOTS POTENTIAL_GAUSS=$BOTH
  compiles tiled_update.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES TILE_SIZE=$TILE_SIZES
  compiles tiled_update.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES CANDIDATE_SLOTS=$CANDIDATE_SLOTS POTENTIAL_GAUSS=$BOTH
  compiles fim_balls.cl WORK_GROUP_SIZE=$WORK_GROUP_SIZES SLOT_BITS=$SLOT_BITS
  compiles surface_voronoi.cl
  compiles cavity_centres.cl
  # core takes every extension away, and this file holds no kernel without
  # cl_khr_fp64: compiled once more with it, optimized, as a GPU builds it.
  echo "cavity_centres.cl -Xclang -cl-ext=+cl_khr_fp64"
}

WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

# Every kernel file must be in the plan; the host builds several files as one
# program, so they must also compile together (no helper defined twice).
plan | sort -u >"$WORK/plan"
all_files="$WORK/every_kernel_in_one_program.cl"
: >"$all_files"
for path in "$KERNELS"/*.cl; do
  file=$(basename "$path")
  grep -q "^$file\( \|$\)" "$WORK/plan" || { echo "check_kernels: $file is not in the plan of scripts/check_kernels.sh" >&2; exit 1; }
  echo "#include \"$file\"" >>"$all_files"
done
{
  sed 's/^/core /' "$WORK/plan"
  echo "core $all_files"
  for path in "$KERNELS"/*.cl; do echo "unoptimized $(basename "$path")"; done
} >"$WORK/jobs"

start=$SECONDS
for mode in core unoptimized; do
  declare -n mode_flags="MODE_$mode"
  "$CLANG" "${LANGUAGE[@]}" "${mode_flags[@]}" -x cl-header /usr/include/clc/clc.h -o "$WORK/$mode.pch"
done

# The names of functions a PTX declares but never defines. NVCL PTX declares
# an external function as a prototype ending in ';' (`.extern` with CUDA);
# a definition opens a body with '{'.
undefined_functions() {
  awk '
    /^(\.(visible|extern|weak) )?\.func/ {
      name = $0
      sub(/^.*\.func[ \t]*/, "", name)
      sub(/^\([^)]*\)[ \t]*/, "", name)  # the return value
      sub(/[ \t]*\(.*$/, "", name)        # the parameters
      pending = 1
      next
    }
    pending && /^;/ { declared[name] = 1; pending = 0 }
    pending && /^\{/ { defined[name] = 1; pending = 0 }
    END { for (f in declared) if (!(f in defined)) print f }
  ' "$1" | sort | tr '\n' ' '
}

# One job: MODE FILE [-D NAME=VALUE...]. Exits 255 on failure: xargs then
# starts no more, so the first failure ends the run.
compile_one() {
  local mode=$1 file=$2
  shift 2
  declare -n mode_flags="MODE_$mode"
  local source="$KERNELS/$file"
  [ "${file#/}" != "$file" ] && source=$file
  local what="$(basename "$file") ($mode${*:+, $*})" ptx log
  ptx="$(mktemp "$WORK/ptx.XXXXXX")"
  log="$ptx.log"
  local command=("$CLANG" "${LANGUAGE[@]}" "${mode_flags[@]}" -include-pch "$WORK/$mode.pch" "${COMPILE[@]}" "$@"
                 -o "$ptx" "$source")
  local exact=0
  [[ " $EXACT_FILES " == *" $file "* ]] && exact=1
  if [ "$exact" = 1 ]; then
    command=("$CLANG" "${EXACT_LANGUAGE[@]}" "${mode_flags[@]}" -include /usr/include/clc/clc.h "${COMPILE[@]}" "$@"
             -o "$ptx" "$source")
  fi
  if ! "${command[@]}" >"$log" 2>&1; then
    { echo "check_kernels: FAILED $what"; cat "$log"; echo "command: ${command[*]}"; } >&2
    exit 255
  fi
  if [ "$exact" = 1 ] && grep -Eq '^\s*(fma|mad)\.|\.approx' "$ptx"; then
    echo "check_kernels: FAILED $what: built with exact math, its PTX fuses or approximates: $(grep -Em3 '^\s*(fma|mad)\.|\.approx' "$ptx" | tr -s ' \t' ' ')" >&2
    exit 255
  fi
  local undefined
  undefined=$(undefined_functions "$ptx")
  if [ -n "$undefined" ]; then
    echo "check_kernels: FAILED $what: calls functions it never defines: $undefined" >&2
    exit 255
  fi
  rm -f "$ptx" "$log"
}
export -f compile_one undefined_functions
export CLANG KERNELS WORK EXACT_FILES

count=$(wc -l <"$WORK/jobs")
# Arrays do not cross into xargs' shells: pass them through declare -p.
arrays=$(declare -p LANGUAGE EXACT_LANGUAGE COMPILE MODE_core MODE_unoptimized)
if ! xargs -P "$JOBS" -L 1 bash -c "$arrays; compile_one \"\$@\"" _ <"$WORK/jobs"; then
  echo "check_kernels: FAILED (above)" >&2
  exit 1
fi
echo "check_kernels: $count compiles for nvptx64-nvidia-nvcl passed in $((SECONDS - start)) s"
