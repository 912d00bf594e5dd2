// Keeps F(v) = sum_i W[p_i][v] and the occupancy (particles per vertex) of
// every vertex up to date, one work-item per VERTICES_PER_ITEM consecutive
// vertices (field_rows.h).
#include "field_rows.h"

#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 64
#endif

__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void field_rebuild(__global const weight_t* weights, uint vertex_count, __global const uint* positions,
                   uint particle_count, __global long* field, __global uint* occupancy) {
  const uint first = (uint)get_global_id(0) * VERTICES_PER_ITEM;
  if (first < vertex_count) sum_rows(weights, vertex_count, positions, particle_count, first, field, occupancy);
}

// After apply_moves of one colour (apply_color_moves).
__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void field_apply_moves(__global const weight_t* weights, uint vertex_count, __global const uint* positions,
                       uint particle_count, uint color, uint colors, __global const uint* move_counts,
                       __global const uint2* moves, __global long* field, __global uint* occupancy) {
  const uint first = (uint)get_global_id(0) * VERTICES_PER_ITEM;
  if (first >= vertex_count) return;
  apply_color_moves(weights, vertex_count, positions, particle_count, color, colors, move_counts[color], moves,
                    first, field, occupancy);
}

// Each particle's energy where it is, in field units (particle_energy_units).
__kernel void field_energies(__global const weight_t* weights, uint vertex_count, __global const uint* positions,
                             uint particle_count, __global const long* field, __global long* energies) {
  const uint c = (uint)get_global_id(0);
  if (c >= particle_count) return;
  energies[c] = particle_energy_units(c, field, weights, vertex_count, positions);
}
