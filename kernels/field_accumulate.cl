// Keeps F(v) = sum_i W[p_i][v] and the occupancy (particles per vertex) of
// every vertex up to date. Each work-item owns VERTICES_PER_ITEM consecutive
// vertices and reads them from each row as one vector: rows are streamed,
// never gathered, neighbouring work-items read neighbouring bytes (a GPU
// coalesces them), and a CPU gets a SIMD load, convert and add per row.
#include "field.h"

#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 64
#endif
#define VERTICES_PER_ITEM 8  // the width of field_units8

// F and the occupancy of the vertices [first, first + 8) ∩ [0, V), from
// scratch: n rows.
static inline void sum_rows(__global const weight_t* weights, uint vertex_count, __global const uint* positions,
                            uint particle_count, uint first, __global long* field, __global uint* occupancy) {
  const uint end = min(first + VERTICES_PER_ITEM, vertex_count);
  for (uint v = first; v < end; ++v) occupancy[v] = 0;
  if (end - first == VERTICES_PER_ITEM) {
    long8 sum = 0;
    for (uint i = 0; i < particle_count; ++i) {
      const uint p = positions[i];
      sum += field_units8(stored_weights8(weights, (ulong)p * vertex_count + first));
      if (p - first < VERTICES_PER_ITEM) ++occupancy[p];
    }
    vstore8(sum, 0, field + first);
    return;
  }
  for (uint v = first; v < end; ++v) field[v] = 0;  // the last, partial chunk
  for (uint i = 0; i < particle_count; ++i) {
    const uint p = positions[i];
    for (uint v = first; v < end; ++v) field[v] += field_units(stored_weight(weights, (ulong)p * vertex_count + v));
    if (p >= first && p < end) ++occupancy[p];
  }
}

__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void field_rebuild(__global const weight_t* weights, uint vertex_count, __global const uint* positions,
                   uint particle_count, __global long* field, __global uint* occupancy) {
  const uint first = (uint)get_global_id(0) * VERTICES_PER_ITEM;
  if (first < vertex_count) sum_rows(weights, vertex_count, positions, particle_count, first, field, occupancy);
}

// After apply_moves of one colour: each move from a to b adds row b and
// subtracts row a (two rows), unless the colour moved more than half the
// particles, when summing all n rows again costs less. Both give the same bits.
__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void field_apply_moves(__global const weight_t* weights, uint vertex_count, __global const uint* positions,
                       uint particle_count, uint color, uint colors, __global const uint* move_counts,
                       __global const uint2* moves, __global long* field, __global uint* occupancy) {
  const uint first = (uint)get_global_id(0) * VERTICES_PER_ITEM;
  if (first >= vertex_count) return;
  const uint count = move_counts[color];
  if (count == 0) return;
  if (2 * count > particle_count) {
    sum_rows(weights, vertex_count, positions, particle_count, first, field, occupancy);
    return;
  }
  __global const uint2* list = moves + color * ((particle_count + colors - 1) / colors);  // as apply_moves.cl
  const uint end = min(first + VERTICES_PER_ITEM, vertex_count);
  for (uint k = 0; k < count; ++k) {  // the vertices a move leaves and enters
    const uint2 move = list[k];         // (from, to)
    if (move.x >= first && move.x < end) --occupancy[move.x];
    if (move.y >= first && move.y < end) ++occupancy[move.y];
  }
  if (end - first == VERTICES_PER_ITEM) {
    long8 sum = vload8(0, field + first);
    for (uint k = 0; k < count; ++k) {
      const uint2 move = list[k];
      sum += field_units8(stored_weights8(weights, (ulong)move.y * vertex_count + first)) -
             field_units8(stored_weights8(weights, (ulong)move.x * vertex_count + first));
    }
    vstore8(sum, 0, field + first);
    return;
  }
  for (uint v = first; v < end; ++v) {  // the last, partial chunk
    long sum = field[v];
    for (uint k = 0; k < count; ++k) {
      const uint2 move = list[k];
      sum += field_units(stored_weight(weights, (ulong)move.y * vertex_count + v)) -
             field_units(stored_weight(weights, (ulong)move.x * vertex_count + v));
    }
    field[v] = sum;
  }
}

// E_c(p_c) = F(p_c) - W[p_c][p_c] in field units, per particle: half their
// sum is the total pair energy.
__kernel void field_energies(__global const weight_t* weights, uint vertex_count, __global const uint* positions,
                             uint particle_count, __global const long* field, __global long* energies) {
  const uint c = (uint)get_global_id(0);
  if (c >= particle_count) return;
  const uint p = positions[c];
  energies[c] = field[p] - field_units(stored_weight(weights, (ulong)p * vertex_count + p));
}
