// W = w(d) for every pair of vertices, once per (mesh, sigma, potential), with
// the potential every kernel shares. A 2-D range: dimension 0 the columns
// (rounded up to whole work-groups), dimension 1 the rows.
#include "field.h"

#if WEIGHTS_HALF
__kernel void weight_table(__global const float* distances, uint vertex_count, float inv_two_sigma_sq,
                           __global half* weights) {
  const size_t column = get_global_id(0);
  if (column >= vertex_count) return;
  const size_t i = get_global_id(1) * vertex_count + column;
  vstore_half_rte(pair_weight(distances[i], inv_two_sigma_sq), i, weights);
}
#else
// In place: the float32 table takes over the distances' buffer, so the device
// never holds both.
__kernel void weight_table(__global float* table, uint vertex_count, float inv_two_sigma_sq) {
  const size_t column = get_global_id(0);
  if (column >= vertex_count) return;
  const size_t i = get_global_id(1) * vertex_count + column;
  table[i] = pair_weight(table[i], inv_two_sigma_sq);
}
#endif
