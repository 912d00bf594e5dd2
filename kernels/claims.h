// The collision rule of one sub-step (docs/ALGORITHM.md, "Collisions"). Each
// update kernel claims the vertex a particle chose with atomic_min, so the
// smallest index holds every claimed vertex whatever the order of
// work-items; apply_moves (apply_moves.cl) moves only the holder. `claims`
// is UINT_MAX wherever nobody holds a claim: the host fills it once, and
// apply_moves puts each claim back as it commits the move.
#ifndef CLAIMS_H
#define CLAIMS_H

static inline void claim_target(__global uint* claims, uint c, uint here, uint target) {
  if (target != here) atomic_min(&claims[target], c);
}

// A colour holds at most ceil(n / colors) particles: colour k's list of
// moves starts at k * moves_capacity.
static inline uint moves_capacity(uint particle_count, uint colors) { return (particle_count + colors - 1) / colors; }

// Commits particle c's claimed choice, once every choice of its sub-step is
// made: only the holder of the claim moves, puts the claim back and appends
// (from, to) to its colour's list, counted by move_counts[color].
static inline void commit_claimed_move(uint c, uint color, uint colors, uint particle_count,
                                       __global uint* positions, __global const uint* chosen,
                                       __global uint* claims, __global uint* move_counts, __global uint2* moves) {
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

#endif
