// W = w(d) for every pair of vertices, once per (mesh, sigma, potential), with
// the potential every kernel shares. One work-item per table entry.
#include "field.h"

#if WEIGHTS_HALF
__kernel void weight_table(__global const float* distances, float inv_two_sigma_sq, __global half* weights) {
  const size_t i = get_global_id(0);
  vstore_half_rte(pair_weight(distances[i], inv_two_sigma_sq), i, weights);
}
#else
// In place: the float32 table takes over the distances' buffer, so the device
// never holds both.
__kernel void weight_table(__global float* table, float inv_two_sigma_sq) {
  const size_t i = get_global_id(0);
  table[i] = pair_weight(table[i], inv_two_sigma_sq);
}
#endif
