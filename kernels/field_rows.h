// How F(v) = sum_i W[p_i][v] and the occupancy follow the particles, for the
// 8 vertices [first, first + 8) one work-item owns: read from each row as one
// vector, so rows are streamed, never gathered; neighbouring work-items read
// neighbouring bytes (a GPU coalesces them), and a CPU gets a SIMD load,
// convert and add per row. Shared by the per-colour kernels
// (field_accumulate.cl) and the one-launch iterations (field_iterations.cl).
#ifndef FIELD_ROWS_H
#define FIELD_ROWS_H

#include "field.h"

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

// The `count` moves of `list`, (from, to) each, on the vertices [first,
// first + 8): row `to` added and row `from` subtracted, or the other way
// round when `undo` is set. Integer sums, so either leaves exactly what a
// rebuild would give.
static inline void add_listed_moves(__global const weight_t* weights, uint vertex_count, uint first,
                                    __global const uint2* list, uint count, uint undo, __global long* field,
                                    __global uint* occupancy) {
  const uint end = min(first + VERTICES_PER_ITEM, vertex_count);
  for (uint k = 0; k < count; ++k) {  // the vertices a move leaves and enters
    const uint2 move = undo ? list[k].yx : list[k];
    if (move.x >= first && move.x < end) --occupancy[move.x];
    if (move.y >= first && move.y < end) ++occupancy[move.y];
  }
  if (end - first == VERTICES_PER_ITEM) {
    long8 sum = vload8(0, field + first);
    for (uint k = 0; k < count; ++k) {
      const uint2 move = undo ? list[k].yx : list[k];
      sum += field_units8(stored_weights8(weights, (ulong)move.y * vertex_count + first)) -
             field_units8(stored_weights8(weights, (ulong)move.x * vertex_count + first));
    }
    vstore8(sum, 0, field + first);
    return;
  }
  for (uint v = first; v < end; ++v) {  // the last, partial chunk
    long sum = field[v];
    for (uint k = 0; k < count; ++k) {
      const uint2 move = undo ? list[k].yx : list[k];
      sum += field_units(stored_weight(weights, (ulong)move.y * vertex_count + v)) -
             field_units(stored_weight(weights, (ulong)move.x * vertex_count + v));
    }
    field[v] = sum;
  }
}

// After the commit of one colour: its moves' rows, unless it moved more than
// half the particles, when summing all n rows again costs less. Both give
// the same bits.
static inline void apply_color_moves(__global const weight_t* weights, uint vertex_count,
                                     __global const uint* positions, uint particle_count, uint color, uint colors,
                                     uint count, __global const uint2* moves, uint first, __global long* field,
                                     __global uint* occupancy) {
  if (count == 0) return;
  if (2 * count > particle_count) {
    sum_rows(weights, vertex_count, positions, particle_count, first, field, occupancy);
    return;
  }
  add_listed_moves(weights, vertex_count, first, moves + color * moves_capacity(particle_count, colors), count, 0,
                   field, occupancy);
}

#endif
