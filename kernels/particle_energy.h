// The one definition of the particle energy and of the candidate rule that
// every kernel shares (host/particles/energy.hpp mirrors it once, in double,
// for the serial reference). Contract: docs/ALGORITHM.md.
//
// Every helper in kernels/ is `static inline`: a plain (C99) `inline`
// function has no definition unless the compiler chooses to inline it, and a
// call it keeps is an undefined symbol that some vendors refuse. `static` on
// a function needs OpenCL C 1.2, which the host asks for (-cl-std=CL1.2).
#ifndef PARTICLE_ENERGY_H
#define PARTICLE_ENERGY_H

// 1: w(d) = exp(-d^2 / (2 sigma^2)); 0: w(d) = exp(-d / (2 sigma^2)), the paper's.
#ifndef POTENTIAL_GAUSS
#define POTENTIAL_GAUSS 0
#endif

// Room for the candidates of any vertex: the mesh's largest valence + 1.
#ifndef CANDIDATE_SLOTS
#define CANDIDATE_SLOTS 8
#endif

// The interaction of two particles at geodesic distance d. Across components
// d is +inf and the weight is exactly zero.
static inline float pair_weight(float d, float inv_two_sigma_sq) {
#if POTENTIAL_GAUSS
  return exp(-d * d * inv_two_sigma_sq);
#else
  return exp(-d * inv_two_sigma_sq);
#endif
}

// Candidates of a particle at `vertex`: index 0 is the vertex itself, then
// its one-ring in increasing vertex id (the CSR arrays are sorted).
static inline uint candidate_count(__global const uint* ring_offsets, uint vertex) {
  return ring_offsets[vertex + 1] - ring_offsets[vertex] + 1;
}

static inline uint candidate_vertex(__global const uint* ring_offsets, __global const uint* ring_neighbors,
                                    uint vertex, uint candidate) {
  return candidate == 0 ? vertex : ring_neighbors[ring_offsets[vertex] + candidate - 1];
}

// Whether particle i (at position_i) is stacked on `here` before particle c:
// c's stack rank counts these, over all particles, whatever their colour.
// 1 or 0, without a branch, so the loops that count it stay vectorizable.
static inline uint stacked_before(uint i, uint position_i, uint c, uint here) {
  return (uint)(position_i == here) & (uint)(i < c);
}

// The candidate rule below works on one particle's candidates in private
// arrays (float energies[CANDIDATE_SLOTS], uchar occupied[CANDIDATE_SLOTS]):
// OpenCL 1.2 has no generic address space, so one definition serves one
// address space, and private scratch takes none of a GPU's shared memory.
//
// A particle alone on its vertex never moves onto a vertex another particle
// occupies: such a candidate is blocked, its energy recorded as +inf. A
// particle that shares its vertex may (it is stacked already), so a stack
// hemmed in by occupied vertices walks to free space instead of freezing.
// occupied[j]: another particle sits on candidate j (j = 0: shares the vertex).
#define BLOCKED INFINITY

static inline void block_occupied(__private float* energies, __private const uchar* occupied, uint count) {
  if (occupied[0]) return;
  for (uint j = 1; j < count; ++j) {
    if (occupied[j]) energies[j] = BLOCKED;
  }
}

// Candidate a comes before candidate b: lower energy, and among equal
// energies the lower index. The current vertex is index 0, so a particle
// moves only to a strictly lower energy, and ties go to the smaller id.
static inline bool ranks_before(float energy_a, uint a, float energy_b, uint b) {
  return energy_a < energy_b || (energy_a == energy_b && a < b);
}

// The index of the candidate of rank `rank` (0: the best), or 0 (stay) when
// there are not that many candidates or that one is blocked. Stacked
// particles pass their rank in the stack, so they fan out instead of moving
// together forever.
static inline uint candidate_of_rank(__private const float* energies, uint count, uint rank) {
  if (rank >= count) return 0;
  for (uint j = 0; j < count; ++j) {
    uint before = 0;
    for (uint i = 0; i < count; ++i) before += ranks_before(energies[i], i, energies[j], j) ? 1u : 0u;
    if (before == rank) return isinf(energies[j]) ? 0 : j;
  }
  return 0;
}

// The candidate a particle with stack rank `rank` takes (blocking in place).
static inline uint chosen_candidate(__private float* energies, __private const uchar* occupied, uint count,
                                    uint rank) {
  block_occupied(energies, occupied, count);
  return candidate_of_rank(energies, count, rank);
}

// naive and tiled compute one particle's candidates on several work-items,
// so they meet in __local memory; the work-item that decides copies them
// into private arrays and applies the same rule.
static inline uint chosen_candidate_from_local(__local const float* energies, __local const uchar* occupied,
                                               uint count, uint rank) {
  float private_energies[CANDIDATE_SLOTS];
  uchar private_occupied[CANDIDATE_SLOTS];
  for (uint j = 0; j < count; ++j) {
    private_energies[j] = energies[j];
    private_occupied[j] = occupied[j];
  }
  return chosen_candidate(private_energies, private_occupied, count, rank);
}

#endif
