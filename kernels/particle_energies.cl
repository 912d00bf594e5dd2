// E_c(p_c) for every particle c: the energy each particle feels where it is.
// Half their sum is the total (pair) energy the run reports per iteration.
#include "particle_energy.h"

__kernel void particle_energies(__global const float* distances, uint vertex_count, __global const uint* positions,
                                uint particle_count, float inv_two_sigma_sq, __global float* energies) {
  const uint c = (uint)get_global_id(0);
  if (c >= particle_count) return;
  __global const float* row = distances + (ulong)positions[c] * vertex_count;
  float energy = 0.0f;
  for (uint i = 0; i < particle_count; ++i) {
    const float weight = pair_weight(row[positions[i]], inv_two_sigma_sq);
    energy += i != c ? weight : 0.0f;  // branch-free: vectorizes
  }
  energies[c] = energy;
}
