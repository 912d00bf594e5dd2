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

#endif
