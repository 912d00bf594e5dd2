# Sourced by correspond_checkpoint.sh and correspondence/mpi_shape_share_test.sh, with $bin
# (the program) and $work (a fresh folder) set: a population of 5 small
# shapes with a known map in $work/shapes, `options` for correspond, one run
# that nothing interrupted in $work/reference, and `same OUT WHAT`, which
# fails unless OUT's outputs are the reference's, byte for byte.
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
work=$(cd "$work" && pwd)
"$bin" generate --population 5 --family ellipsoid --vertices 900 --seed 3 --out-dir "$work/shapes" 2> /dev/null
# A script that runs correspond dozens of times may set `deformation`
# (smooth: a fifth of the default graph's transfer time) before sourcing.
options=("$work/shapes" -n 48 --samples 10 --refine-iterations 60 --deformation "${deformation:-graph}")
"$bin" correspond "${options[@]}" --out "$work/reference" > /dev/null 2> "$work/reference.log"
[ -d "$work/reference/checkpoint" ] && fail "a finished run left its checkpoint"

same() {
  diff -r "$work/reference" "$1" > "$work/diff.txt" || { head -5 "$work/diff.txt"; fail "$2: outputs differ from one uninterrupted run"; }
  [ -d "$1/checkpoint" ] && fail "$2: the checkpoint was left"
  echo "ok: $2"
}
