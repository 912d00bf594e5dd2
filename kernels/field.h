// The field method's stored weights and fixed-point field: one definition for
// every field kernel (host/particles/field_units.hpp mirrors it for the
// serial twin). Contract: docs/ALGORITHM.md, "The field backend".
#ifndef FIELD_H
#define FIELD_H

#include "claims.h"
#include "particle_energy.h"

// The weight table W[u][v] = w(d(u, v)), row-major, V x V: float32, or half
// precision (1: half the bytes streamed). Half values are only read and
// written through vload_half / vstore_half, which need no cl_khr_fp16.
#ifndef WEIGHTS_HALF
#define WEIGHTS_HALF 0
#endif

#if WEIGHTS_HALF
typedef half weight_t;
static inline float stored_weight(__global const half* weights, ulong index) { return vload_half(index, weights); }
static inline float8 stored_weights8(__global const half* weights, ulong index) {
  return vload_half8(0, weights + index);
}
#else
typedef float weight_t;
static inline float stored_weight(__global const float* weights, ulong index) { return weights[index]; }
static inline float8 stored_weights8(__global const float* weights, ulong index) { return vload8(0, weights + index); }
#endif

// F(v) = sum_i W[p_i][v] is kept in 64-bit integers counting units of 2^-40.
// Integer sums are exact: adding row b and subtracting row a when a particle
// moves from a to b leaves exactly what a rebuild would give, whatever the
// order of the additions, and E_c(v) = F(v) - W[p_c][v] subtracts exactly
// even where particle c's own weight dominates F. A weight is truncated to
// whole units (weights below 2^-40 count as zero; truncation, not rounding,
// because it is one instruction on every device). F <= n * 2^40 < 2^63
// holds for n < 2^23 (the host checks).
#define FIELD_UNITS_PER_WEIGHT 0x1p40f

static inline long field_units(float weight) { return convert_long(weight * FIELD_UNITS_PER_WEIGHT); }
static inline long8 field_units8(float8 weights) { return convert_long8(weights * FIELD_UNITS_PER_WEIGHT); }

// An energy in field units as the float the candidate rule compares: one
// rounding, to nearest.
static inline float field_energy(long units) { return convert_float(units) * (1.0f / FIELD_UNITS_PER_WEIGHT); }

// The field kernels' decision once particle c (at `here`) has its
// candidates' energies and occupancy: occupancy replaces the scan for
// occupied candidates, so only a particle that shares its vertex scans the
// positions, for its stack rank. Writes and claims the chosen vertex.
static inline void choose_and_claim(__private float* energies, __private const uchar* occupied, uint count, uint c,
                                    uint here, __global const uint* ring_offsets, __global const uint* ring_neighbors,
                                    __global const uint* occupancy, __global const uint* positions,
                                    uint rank_stacks, __global uint* chosen, __global uint* claims) {
  uint stack_rank = 0;
  if (rank_stacks && occupancy[here] > 1) {
    for (uint i = 0; i < c; ++i) stack_rank += stacked_before(i, positions[i], c, here);
  }
  const uint target =
      candidate_vertex(ring_offsets, ring_neighbors, here, chosen_candidate(energies, occupied, count, stack_rank));
  chosen[c] = target;
  claim_target(claims, c, here, target);
}

// Particle c's decision from the field: every candidate's energy is
// E_c(v) = F(v) - W[p_c][v], two reads, where the direct-sum kernels sum
// over all n particles. W is symmetric, so W[p_c][v] is read from row p_c at
// the candidates' nearby columns. One work-item decides for one particle, so
// its scratch is private: no __local memory, which would limit how many
// work-groups a GPU runs at once.
static inline void field_decide(uint c, __global const long* field, __global const weight_t* weights,
                                uint vertex_count, __global const uint* ring_offsets,
                                __global const uint* ring_neighbors, __global const uint* occupancy,
                                __global const uint* positions, uint rank_stacks, __global uint* chosen,
                                __global uint* claims) {
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

// E_c(p_c) = F(p_c) - W[p_c][p_c] in field units: what particle c feels
// where it is. Half the sum over particles is the total pair energy.
static inline long particle_energy_units(uint c, __global const long* field, __global const weight_t* weights,
                                         uint vertex_count, __global const uint* positions) {
  const uint p = positions[c];
  return field[p] - field_units(stored_weight(weights, (ulong)p * vertex_count + p));
}

#endif
