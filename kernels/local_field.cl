// The field method on local balls (`--backend field --distances local`): the
// device twin of host/backends/local_field_backend. No V x V table: the
// device holds the balls of the particles' candidates as rows of a pool
// (CSR: a row's start and length per vertex, the vertices in increasing id
// with their one-sided distances), and F(v) in field units only where the
// candidate rule reads it: at candidates (candidate[v] != 0).
//
// The weight between u and v is w of the mean of the two one-sided
// distances, each read from the other's row, and 0 unless each lies in the
// other's row: the host's LocalDistances::symmetric_distance, in the same
// float arithmetic, so both twins make the same sums bit for bit.
//
// F after the moves of a colour: each move scatters its rows with atomic
// adds. 64-bit atomics are an extension (cl_khr_int64_base_atomics), so F is
// added to as two 32-bit halves with the carry (core OpenCL 1.1 atomics):
// sums modulo 2^64, exact in any order, so the result is deterministic.

#include "field.h"

#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 64
#endif

// The pool of rows, passed to every kernel in this order.
#define ROWS_PARAMS                                                                                      \
  __global const uint *row_start, __global const uint *row_length, __global const uint *row_vertices,    \
      __global const float *row_distances
#define ROWS row_start, row_length, row_vertices, row_distances

// d_u(v) from u's row, or -1 when v is not in it (rows are sorted by vertex).
static inline float row_distance(ROWS_PARAMS, uint u, uint v) {
  const uint first = row_start[u];
  uint low = 0, high = row_length[u];
  while (low < high) {
    const uint middle = low + (high - low) / 2;
    if (row_vertices[first + middle] < v) {
      low = middle + 1;
    } else {
      high = middle;
    }
  }
  return low < row_length[u] && row_vertices[first + low] == v ? row_distances[first + low] : -1.0f;
}

// W(u, v) in field units when d_u(v) is known (v read from u's row).
static inline long units_with(ROWS_PARAMS, float from_u_to_v, uint u, uint v, float inv_two_sigma_sq) {
  const float back = row_distance(ROWS, v, u);
  return back < 0.0f ? 0 : field_units(pair_weight(0.5f * (from_u_to_v + back), inv_two_sigma_sq));
}

// W(u, v) in field units; both rows resident.
static inline long pair_units(ROWS_PARAMS, uint u, uint v, float inv_two_sigma_sq) {
  const float there = row_distance(ROWS, u, v);
  return there < 0.0f ? 0 : units_with(ROWS, there, u, v, inv_two_sigma_sq);
}

// The decision, as field_update.cl: E_c(v) = F(v) - W(p_c, v).
__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void local_field_update(__global const long* field, ROWS_PARAMS, float inv_two_sigma_sq,
                        __global const uint* ring_offsets, __global const uint* ring_neighbors,
                        __global const uint* occupancy, __global const uint* positions, uint particle_count,
                        uint color, uint colors, uint rank_stacks, __global uint* chosen, __global uint* claims) {
  const uint c = color + (uint)get_global_id(0) * colors;
  if (c >= particle_count) return;  // no barriers below

  float energies[CANDIDATE_SLOTS];
  uchar occupied[CANDIDATE_SLOTS];
  const uint here = positions[c];
  const uint count = candidate_count(ring_offsets, here);
  for (uint j = 0; j < count; ++j) {
    const uint v = candidate_vertex(ring_offsets, ring_neighbors, here, j);
    energies[j] = field_energy(field[v] - pair_units(ROWS, here, v, inv_two_sigma_sq));
    occupied[j] = occupancy[v] > (j == 0 ? 1u : 0u);  // c itself sits on candidate 0
  }

  choose_and_claim(energies, occupied, count, c, here, ring_offsets, ring_neighbors, occupancy, positions,
                   rank_stacks, chosen, claims);
}

// F[x] += delta on the halves of the 64-bit F: the low word's atomic add
// (or subtract) returns the old word, from which the carry (or borrow) into
// the high word follows. Only where the high word changes does it take a
// second atomic: weights below 2^-8 are under 2^32 units.
#ifdef __ENDIAN_LITTLE__
#define LOW_HALF 0
#else
#define LOW_HALF 1
#endif
static inline void add_to_field(__global long* field, uint x, long delta) {
  volatile __global uint* halves = (volatile __global uint*)(field + x);
  const ulong magnitude = delta < 0 ? (ulong)(-delta) : (ulong)delta;
  const uint low = (uint)magnitude, high = (uint)(magnitude >> 32);
  if (delta >= 0) {
    const uint old = atomic_add(&halves[LOW_HALF], low);
    const uint carry = (uint)(old + low < old);
    if (high + carry != 0) atomic_add(&halves[1 - LOW_HALF], high + carry);
  } else {
    const uint old = atomic_sub(&halves[LOW_HALF], low);
    const uint borrow = (uint)(old < low);
    if (high + borrow != 0) atomic_sub(&halves[1 - LOW_HALF], high + borrow);
  }
}

// The moves of one colour (moves[first_move + k] = (from, to)), one
// work-group per move and side: side 0 subtracts the weight of `from` from
// F at every candidate in its row, side 1 adds that of `to`. The first
// work-item moves the occupancy.
__kernel __attribute__((reqd_work_group_size(WORK_GROUP_SIZE, 1, 1)))
void local_field_scatter(__global const uint2* moves, uint first_move, ROWS_PARAMS, float inv_two_sigma_sq,
                         __global const uchar* candidate, __global long* field, __global uint* occupancy) {
  const uint group = (uint)get_group_id(0);
  const uint2 move = moves[first_move + group / 2];
  const bool arriving = (group & 1u) != 0;
  const uint source = arriving ? move.y : move.x;
  if (get_local_id(0) == 0) {
    if (arriving) {
      atomic_inc(&occupancy[source]);
    } else {
      atomic_dec(&occupancy[source]);
    }
  }
  const uint first = row_start[source], length = row_length[source];
  for (uint k = (uint)get_local_id(0); k < length; k += WORK_GROUP_SIZE) {
    const uint x = row_vertices[first + k];
    if (!candidate[x]) continue;
    const long units = units_with(ROWS, row_distances[first + k], source, x, inv_two_sigma_sq);
    if (units != 0) add_to_field(field, x, arriving ? units : -units);
  }
}

// F(x) from scratch for the listed vertices (candidates new since the last
// sums): the particles in x's row, each with its own row resident.
__kernel void local_field_sum(__global const uint* vertices, uint count, ROWS_PARAMS, float inv_two_sigma_sq,
                              __global const uint* occupancy, __global long* field) {
  const uint i = (uint)get_global_id(0);
  if (i >= count) return;
  const uint x = vertices[i];
  const uint first = row_start[x], length = row_length[x];
  long sum = 0;
  for (uint k = 0; k < length; ++k) {
    const uint u = row_vertices[first + k];
    const uint particles = occupancy[u];
    if (particles > 0) sum += (long)particles * units_with(ROWS, row_distances[first + k], x, u, inv_two_sigma_sq);
  }
  field[x] = sum;
}

// Sets where rows live and which vertices are candidates: changes[k] =
// (vertex, row start, row length, candidate), written by the host in one
// upload per colour instead of one write per vertex.
__kernel void local_field_mark(__global const uint4* changes, uint count, __global uint* row_start,
                               __global uint* row_length, __global uchar* candidate) {
  const uint k = (uint)get_global_id(0);
  if (k >= count) return;
  const uint4 change = changes[k];
  row_start[change.x] = change.y;
  row_length[change.x] = change.z;
  candidate[change.x] = (uchar)change.w;
}

// E_c(p_c) = F(p_c) - W(p_c, p_c) in field units, per particle.
__kernel void local_field_energies(__global const uint* positions, uint particle_count, ROWS_PARAMS,
                                   float inv_two_sigma_sq, __global const long* field, __global long* energies) {
  const uint c = (uint)get_global_id(0);
  if (c >= particle_count) return;
  const uint p = positions[c];
  energies[c] = field[p] - pair_units(ROWS, p, p, inv_two_sigma_sq);
}
