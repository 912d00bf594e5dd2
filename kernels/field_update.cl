// The field backend's decision: one work-item per particle of the sub-step
// (field_decide in field.h). Writes and claims the chosen vertex like the
// other update kernels.
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
  if (c >= particle_count) return;  // no barriers in field_decide
  field_decide(c, field, weights, vertex_count, ring_offsets, ring_neighbors, occupancy, positions, rank_stacks,
               chosen, claims);
}
