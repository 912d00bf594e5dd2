// The paper's GPU1: one work-group per particle of the sub-step, its
// work-items over the particle's candidates, each summing over every particle
// straight from the distance table in global memory (row = candidate, so
// neighbouring work-items read scattered addresses). Writes the chosen
// vertex of each particle and claims it; apply_moves commits the moves after
// the launch, so every work-group sees the same snapshot.
#include "claims.h"
#include "particle_energy.h"

#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 8
#endif

__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void naive_update(__global const float* distances, uint vertex_count,
                  __global const uint* ring_offsets, __global const uint* ring_neighbors,
                  __global const uint* positions, uint particle_count, uint color, uint colors, uint rank_stacks,
                  float inv_two_sigma_sq, __global uint* chosen, __global uint* claims) {
  __local float energies[CANDIDATE_SLOTS];
  __local uchar occupied[CANDIDATE_SLOTS];
  __local uint stack_rank;
  // Launched with exactly one work-group per particle of this colour.
  const uint c = color + (uint)get_group_id(0) * colors;
  const uint lid = (uint)get_local_id(0);
  const uint here = positions[c];
  const uint count = candidate_count(ring_offsets, here);

  for (uint j = lid; j < count; j += WORK_GROUP_SIZE) {
    const uint v = candidate_vertex(ring_offsets, ring_neighbors, here, j);
    __global const float* row = distances + (ulong)v * vertex_count;
    float energy = 0.0f;
    uint stacked = 0;
    bool taken = false;
    // Branch-free, so the compiler can vectorize over i (see kernel_options).
    for (uint i = 0; i < particle_count; ++i) {
      const uint p = positions[i];
      const float weight = pair_weight(row[p], inv_two_sigma_sq);
      const bool other = i != c;
      energy += other ? weight : 0.0f;
      taken |= other & (p == v);
      stacked += stacked_before(i, p, c, here);  // read for j = 0 only
    }
    energies[j] = energy;
    occupied[j] = taken;
    if (j == 0) stack_rank = rank_stacks ? stacked : 0;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (lid == 0) {
    const uint target = candidate_vertex(ring_offsets, ring_neighbors, here,
                                         chosen_candidate_from_local(energies, occupied, count, stack_rank));
    chosen[c] = target;
    claim_target(claims, c, here, target);
  }
}
