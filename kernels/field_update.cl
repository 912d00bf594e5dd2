// The field backend's decision: one work-item per particle of the sub-step.
// Every candidate's energy is E_c(v) = F(v) - W[p_c][v], two reads, where the
// direct-sum kernels (naive, tiled) sum over all n particles. W is
// symmetric, so W[p_c][v] is read from row p_c at the candidates' nearby
// columns. Occupancy replaces the scan for occupied candidates; only a
// particle that shares its vertex scans the positions, for its stack rank.
// Writes and claims the chosen vertex like the other update kernels.
#include "field.h"

#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 64
#endif

__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void field_update(__global const long* field, __global const weight_t* weights, uint vertex_count,
                  __global const uint* ring_offsets, __global const uint* ring_neighbors,
                  __global const uint* occupancy, __global const uint* positions, uint particle_count,
                  uint color, uint colors, uint rank_stacks, __global uint* chosen, __global uint* claims) {
  const uint c = color + (uint)get_global_id(0) * colors;
  if (c >= particle_count) return;  // no barriers below

  // One work-item decides for one particle, so its scratch is private: no
  // __local memory, which would limit how many work-groups a GPU runs at once.
  float energies[CANDIDATE_SLOTS];
  uchar occupied[CANDIDATE_SLOTS];
  const uint here = positions[c];
  const uint count = candidate_count(ring_offsets, here);
  __global const weight_t* own_row = weights + (ulong)here * vertex_count;
  for (uint j = 0; j < count; ++j) {
    const uint v = candidate_vertex(ring_offsets, ring_neighbors, here, j);
    energies[j] = field_energy(field[v] - field_units(stored_weight(own_row, v)));
    occupied[j] = occupancy[v] > (j == 0 ? 1u : 0u);  // c itself sits on candidate 0
  }

  choose_and_claim(energies, occupied, count, c, here, ring_offsets, ring_neighbors, occupancy, positions,
                   rank_stacks, chosen, claims);
}
