// Geodesic balls by the fast iterative method, one work-group per ball: the
// device twin of host/geodesics/fast_iterative (docs/GEODESICS.md). A ball's
// vertices live in local memory in an open-addressing table of SLOTS
// entries (vertex id, distance bits, active flag), so a ball costs in
// proportion to its size, whatever the mesh's. Each round, the work-items
// share the table's slots; every active vertex pushes its edge, triangle and
// virtual-triangle updates, lowering its neighbours' distances with
// atomic_min on the float bits (non-negative floats order like their bits)
// and making the lowered ones active. Rounds end when none was lowered.
// Then the vertices beyond the radius are dropped, the rest sorted by id
// (bitonic, in local memory) and written out as the host's Ball, packed:
// each ball takes its room where `entries_used` says, with atomic_add, so
// the balls lie in any order but each one's entries are its own.
//
// A ball that outgrows its table, or takes more than MAX_ROUNDS rounds,
// reports BALL_UNSOLVED and the host solves it with the same method.
//
// Compile-time: SLOT_BITS (SLOTS = 2^SLOT_BITS), WORK_GROUP_SIZE.

#include "point_source_update.h"

#ifndef SLOT_BITS
#define SLOT_BITS 12
#endif
#ifndef WORK_GROUP_SIZE
#define WORK_GROUP_SIZE 256
#endif
#define SLOTS (1u << SLOT_BITS)
#define EMPTY_SLOT 0xFFFFFFFFu
#define INFINITY_BITS 0x7F800000
#define MAX_ROUNDS (4u * SLOTS)
#define BALL_UNSOLVED 0xFFFFFFFFu

// One entry of the host's TriangleStencils (triangle_stencils.hpp): the
// same layout, every field 4 bytes.
typedef struct {
  uint a, b;
  float b_from_a[3];  // length_xy, c_x, c_y: B from (X, A)
  float a_from_b[3];  // A from (X, B)
} triangle_at_vertex;

typedef struct {
  uint target, other;
  float frame[3];
} virtual_update;

static inline uint slot_hash(uint v) { return (v * 2654435761u) >> (32 - SLOT_BITS); }

// v's slot, or -1 when v has none yet.
static inline int find_slot(volatile __local uint* keys, uint v) {
  uint s = slot_hash(v);
  for (uint probe = 0; probe < SLOTS; ++probe) {
    const uint k = keys[s];
    if (k == v) return (int)s;
    if (k == EMPTY_SLOT) return -1;
    s = (s + 1u) & (SLOTS - 1u);
  }
  return -1;
}

// v's slot, taken now if it had none; -1 when the table is full.
static inline int claim_slot(volatile __local uint* keys, uint v) {
  uint s = slot_hash(v);
  for (uint probe = 0; probe < SLOTS; ++probe) {
    uint k = keys[s];
    if (k == EMPTY_SLOT) k = atomic_cmpxchg(&keys[s], EMPTY_SLOT, v);
    if (k == EMPTY_SLOT || k == v) return (int)s;
    s = (s + 1u) & (SLOTS - 1u);
  }
  return -1;
}

// The distance of v so far, INFINITY when it has none.
static inline float distance_of(volatile __local uint* keys, volatile __local int* bits, uint v) {
  const int s = find_slot(keys, v);
  return s < 0 ? INFINITY : as_float(bits[s]);
}

// Lowers v to `candidate` when that is smaller and within `keep`.
static inline void lower(volatile __local uint* keys, volatile __local int* bits, volatile __local uchar* active,
                         volatile __local int* lowered, volatile __local int* overflow, uint v, float candidate,
                         float keep) {
  if (!(candidate <= keep)) return;
  const int s = claim_slot(keys, v);
  if (s < 0) {
    *overflow = 1;
    return;
  }
  const int candidate_bits = as_int(candidate);
  if (candidate_bits < atomic_min(&bits[s], candidate_bits)) {
    active[s] = 1;
    *lowered = 1;
  }
}

__kernel void fim_balls(__global const uint* sources, uint ball_count, float radius, float keep,
                        __global const uint* ring_offsets, __global const uint* ring_neighbors,
                        __global const float* edge_lengths, __global const uint* triangle_offsets,
                        __global const triangle_at_vertex* triangles, __global const uint* virtual_offsets,
                        __global const virtual_update* virtual_updates, __global uint* ball_vertices,
                        __global float* ball_distances, __global uint* ball_sizes, __global uint* ball_starts,
                        volatile __global uint* entries_used) {
  volatile __local uint keys[SLOTS];
  volatile __local int bits[SLOTS];
  volatile __local uchar active[SLOTS];
  // The group's shared scalars, as one-element arrays: written by one item
  // and read by all after a barrier (which a compiler's flow analysis of a
  // plain local variable does not see).
  volatile __local int lowered[1], overflow[1];
  volatile __local uint size[1], start[1];
  const uint ball = (uint)get_group_id(0);
  const uint lid = (uint)get_local_id(0);
  if (ball >= ball_count) return;  // uniform: the whole group

  for (uint s = lid; s < SLOTS; s += WORK_GROUP_SIZE) {
    keys[s] = EMPTY_SLOT;
    bits[s] = INFINITY_BITS;
    active[s] = 0;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (lid == 0) {
    const int s = claim_slot(keys, sources[ball]);
    bits[s] = 0;
    active[s] = 1;
    lowered[0] = 1;
    overflow[0] = 0;
  }
  for (uint round = 0;; ++round) {
    barrier(CLK_LOCAL_MEM_FENCE);
    const int go = lowered[0] && !overflow[0] && round < MAX_ROUNDS;
    barrier(CLK_LOCAL_MEM_FENCE);  // every item has read `lowered` before it is reset
    if (!go) break;
    if (lid == 0) lowered[0] = 0;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint s = lid; s < SLOTS; s += WORK_GROUP_SIZE) {
      if (!active[s]) continue;
      active[s] = 0;
      const uint x = keys[s];
      const float dx = as_float(bits[s]);
      for (uint k = ring_offsets[x]; k < ring_offsets[x + 1]; ++k) {
        lower(keys, bits, active, lowered, overflow, ring_neighbors[k], dx + edge_lengths[k], keep);
      }
      for (uint k = triangle_offsets[x]; k < triangle_offsets[x + 1]; ++k) {
        const triangle_at_vertex t = triangles[k];
        const float da = distance_of(keys, bits, t.a), db = distance_of(keys, bits, t.b);
        if (da < INFINITY) {
          lower(keys, bits, active, lowered, overflow, t.b,
                point_source_update(t.b_from_a[0], t.b_from_a[1], t.b_from_a[2], dx, da), keep);
        }
        if (db < INFINITY) {
          lower(keys, bits, active, lowered, overflow, t.a,
                point_source_update(t.a_from_b[0], t.a_from_b[1], t.a_from_b[2], dx, db), keep);
        }
      }
      for (uint k = virtual_offsets[x]; k < virtual_offsets[x + 1]; ++k) {
        const virtual_update u = virtual_updates[k];
        const float d_other = distance_of(keys, bits, u.other);
        if (d_other < INFINITY) {
          lower(keys, bits, active, lowered, overflow, u.target,
                point_source_update(u.frame[0], u.frame[1], u.frame[2], dx, d_other), keep);
        }
      }
    }
  }
  // `overflow` and `lowered` were read by all after the last barrier.
  const int unsolved = overflow[0] || lowered[0];
  if (unsolved) {
    if (lid == 0) ball_sizes[ball] = BALL_UNSOLVED;
    return;  // uniform: the whole group
  }

  // Only the ball stays: the rest of the table sorts after it.
  if (lid == 0) size[0] = 0;
  for (uint s = lid; s < SLOTS; s += WORK_GROUP_SIZE) {
    if (keys[s] != EMPTY_SLOT && !(as_float(bits[s]) <= radius)) keys[s] = EMPTY_SLOT;
  }
  // Bitonic sort by vertex id, distances alongside.
  for (uint span = 2; span <= SLOTS; span <<= 1) {
    for (uint stride = span >> 1; stride > 0; stride >>= 1) {
      barrier(CLK_LOCAL_MEM_FENCE);
      for (uint i = lid; i < SLOTS; i += WORK_GROUP_SIZE) {
        const uint j = i ^ stride;
        if (j <= i) continue;
        const int ascending = (i & span) == 0;
        const uint ki = keys[i], kj = keys[j];
        if ((ki > kj) == ascending) {
          keys[i] = kj;
          keys[j] = ki;
          const int bi = bits[i];
          bits[i] = bits[j];
          bits[j] = bi;
        }
      }
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  // The ball's size, then its place in the packed output.
  for (uint s = lid; s < SLOTS; s += WORK_GROUP_SIZE) {
    if (keys[s] != EMPTY_SLOT && (s + 1 == SLOTS || keys[s + 1] == EMPTY_SLOT)) size[0] = s + 1;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  if (lid == 0) {
    start[0] = atomic_add(entries_used, size[0]);
    ball_sizes[ball] = size[0];
    ball_starts[ball] = start[0];
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  for (uint s = lid; s < size[0]; s += WORK_GROUP_SIZE) {
    ball_vertices[start[0] + s] = keys[s];
    ball_distances[start[0] + s] = as_float(bits[s]);
  }
}
