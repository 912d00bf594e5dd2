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

// A colour holds at most ceil(n / colors) particles.
static inline uint moves_capacity(uint particle_count, uint colors) { return (particle_count + colors - 1) / colors; }

__kernel void apply_moves(__global uint* positions, __global const uint* chosen, uint particle_count, uint color,
                          uint colors, __global uint* claims, __global uint* move_counts, __global uint2* moves) {
  const uint c = color + (uint)get_global_id(0) * colors;
  if (c >= particle_count) return;
  const uint here = positions[c];
  const uint target = chosen[c];
  // A particle that lost the claim reads the holder's index, or UINT_MAX once
  // the holder has reset it: either way not its own.
  if (target == here || claims[target] != c) return;
  claims[target] = UINT_MAX;
  positions[c] = target;
  const uint k = atomic_inc(&move_counts[color]);
  moves[color * moves_capacity(particle_count, colors) + k] = (uint2)(here, target);
}
