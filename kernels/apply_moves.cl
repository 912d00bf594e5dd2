// Commits the vertices the update kernel chose and claimed for one colour
// (claims.h), in a launch after it, so every update work-group read the same
// snapshot. Candidates occupied in the snapshot are never chosen, but two
// particles of one sub-step may choose the same free vertex: the holder of
// the claim (the smallest index) moves and the others stay.
//
// Every move is appended to the colour's list, moves[color * capacity + k]
// = (from, to), k counted by move_counts[color]: the host sums the counts,
// and the field backend updates F from the list (field_accumulate.cl).
#include "claims.h"

__kernel void apply_moves(__global uint* positions, __global const uint* chosen, uint particle_count, uint color,
                          uint colors, __global uint* claims, __global uint* move_counts, __global uint2* moves) {
  const uint c = color + (uint)get_global_id(0) * colors;
  if (c >= particle_count) return;
  commit_claimed_move(c, color, colors, particle_count, positions, chosen, claims, move_counts, moves);
}
