// The paper's GPU2: particle positions staged tile by tile in local memory,
// many (particle, candidate) pairs per work-group. Work-item s of a group
// handles pair s: particle s / CANDIDATE_SLOTS of the group, candidate
// s % CANDIDATE_SLOTS. It reads the symmetric table as d(p_i, v), row = the
// staged particle's vertex, so neighbouring work-items (the one-ring of one
// particle, nearby ids after breadth-first numbering) read nearby addresses of
// the same row. Every work-item reaches every barrier the same number of
// times; only the accumulation is masked.
#include "claims.h"
#include "particle_energy.h"

#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 32
#endif
#ifndef TILE_SIZE
#define TILE_SIZE 64
#endif

#define PARTICLES_PER_GROUP (WORK_GROUP_SIZE >= CANDIDATE_SLOTS ? WORK_GROUP_SIZE / CANDIDATE_SLOTS : 1)
#define PAIR_SLOTS (PARTICLES_PER_GROUP * CANDIDATE_SLOTS)
// With fewer work-items than one particle's slots, each takes several.
#define SLOTS_PER_ITEM ((PAIR_SLOTS + WORK_GROUP_SIZE - 1) / WORK_GROUP_SIZE)

__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void tiled_update(__global const float* distances, uint vertex_count,
                  __global const uint* ring_offsets, __global const uint* ring_neighbors,
                  __global const uint* positions, uint particle_count, uint color, uint colors, uint rank_stacks,
                  float inv_two_sigma_sq, __global uint* chosen, __global uint* claims) {
  __local uint tile[TILE_SIZE];
  __local float energies[PAIR_SLOTS];
  __local uchar occupied_slots[PAIR_SLOTS];
  __local uint stack_rank[PARTICLES_PER_GROUP];
  const uint lid = (uint)get_local_id(0);
  const uint color_size = (particle_count - color + colors - 1) / colors;
  const uint first = (uint)get_group_id(0) * PARTICLES_PER_GROUP;  // rank of the group's first particle in its colour

  float energy[SLOTS_PER_ITEM];
  bool occupied[SLOTS_PER_ITEM];
  uint stacked[SLOTS_PER_ITEM];
  uint vertex[SLOTS_PER_ITEM];  // the candidate vertex of each slot
  uint particle[SLOTS_PER_ITEM];
  uint here[SLOTS_PER_ITEM];
  bool active[SLOTS_PER_ITEM];
  for (uint k = 0; k < SLOTS_PER_ITEM; ++k) {
    const uint s = lid + k * WORK_GROUP_SIZE;
    const uint q = s / CANDIDATE_SLOTS;
    const uint j = s % CANDIDATE_SLOTS;
    energy[k] = 0.0f;
    occupied[k] = false;
    stacked[k] = 0;
    active[k] = false;
    if (s < PAIR_SLOTS && first + q < color_size) {
      particle[k] = color + (first + q) * colors;
      here[k] = positions[particle[k]];
      if (j < candidate_count(ring_offsets, here[k])) {
        active[k] = true;
        vertex[k] = candidate_vertex(ring_offsets, ring_neighbors, here[k], j);
      }
    }
  }

  for (uint tile_start = 0; tile_start < particle_count; tile_start += TILE_SIZE) {
    const uint tile_count = min((uint)TILE_SIZE, particle_count - tile_start);
    for (uint t = lid; t < tile_count; t += WORK_GROUP_SIZE) tile[t] = positions[tile_start + t];
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint k = 0; k < SLOTS_PER_ITEM; ++k) {
      if (!active[k]) continue;
      // Branch-free, so the compiler can vectorize over the tile.
      for (uint t = 0; t < tile_count; ++t) {
        const uint i = tile_start + t;
        const uint p = tile[t];
        const float weight = pair_weight(distances[(ulong)p * vertex_count + vertex[k]], inv_two_sigma_sq);
        const bool other = i != particle[k];
        energy[k] += other ? weight : 0.0f;
        occupied[k] |= other & (p == vertex[k]);
        // Only slot 0 (the current vertex) reads its count: the particle's stack rank.
        stacked[k] += stacked_before(i, p, particle[k], here[k]);
      }
    }
    barrier(CLK_LOCAL_MEM_FENCE);  // the next tile overwrites this one
  }

  for (uint k = 0; k < SLOTS_PER_ITEM; ++k) {
    const uint s = lid + k * WORK_GROUP_SIZE;
    if (!active[k]) continue;
    energies[s] = energy[k];
    occupied_slots[s] = occupied[k];
    if (s % CANDIDATE_SLOTS == 0) stack_rank[s / CANDIDATE_SLOTS] = rank_stacks ? stacked[k] : 0;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  for (uint q = lid; q < PARTICLES_PER_GROUP; q += WORK_GROUP_SIZE) {
    if (first + q >= color_size) continue;
    const uint c = color + (first + q) * colors;
    const uint at = positions[c];
    const uint count = candidate_count(ring_offsets, at);
    __local const float* its_energies = energies + q * CANDIDATE_SLOTS;  // particle q's slots
    __local const uchar* its_occupied = occupied_slots + q * CANDIDATE_SLOTS;
    const uint target = candidate_vertex(ring_offsets, ring_neighbors, at,
                                         chosen_candidate_from_local(its_energies, its_occupied, count, stack_rank[q]));
    chosen[c] = target;
    claim_target(claims, c, at, target);
  }
}
