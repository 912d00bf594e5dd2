// Commits the vertices the update kernel chose for one colour, in two
// launches after it (so every update work-group read the same snapshot).
// Candidates occupied in the snapshot are never chosen, but two particles of
// one sub-step may choose the same free vertex: the smallest index gets it
// and the others stay (docs/ALGORITHM.md, "Collisions"). `claims` holds
// UINT_MAX everywhere before claim_targets (the host fills it).
__kernel void claim_targets(__global const uint* positions, __global const uint* chosen, uint particle_count,
                            uint color, uint colors, __global uint* claims) {
  const uint c = color + (uint)get_global_id(0) * colors;
  if (c >= particle_count) return;
  if (chosen[c] != positions[c]) atomic_min(&claims[chosen[c]], c);
}

__kernel void apply_moves(__global uint* positions, __global const uint* chosen, uint particle_count, uint color,
                          uint colors, __global const uint* claims, __global uint* moved_count) {
  const uint c = color + (uint)get_global_id(0) * colors;
  if (c >= particle_count) return;
  const uint target = chosen[c];
  if (target != positions[c] && claims[target] == c) {
    positions[c] = target;
    atomic_inc(moved_count);
  }
}
