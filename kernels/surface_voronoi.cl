// The geodesic Voronoi diagram of points on a surface, sampled at the
// vertices: the device twin of host/particles/surface_voronoi (docs/GEODESICS.md,
// "What runs where"). The host seeds each point's triangle corners (distance,
// owner); rounds of a multi-source label-correcting sweep (the fast iterative
// method's updates, one work-item per vertex) then give every vertex its
// distance to the nearest point and which point that is.
//
// Deterministic whatever the device and the order of work-items: a round
// reads only the previous round's buffers and writes the next ones (Jacobi,
// double-buffered), and each vertex takes the smallest of its candidates,
// ties to the smaller owner: (distance, owner) only ever decreases, so the
// rounds end, and their result cannot depend on which work-item ran first.
// The float arithmetic is as written: the host builds this program without
// unsafe math and with correctly rounded division and square root
// (FloatMath::exact, opencl/program_builder), and nothing is contracted into
// fused multiply-adds, so every conformant device computes the same bits.
//
// A vertex pulls its candidates: along each edge from a neighbour (d(w) +
// |vw|, w's owner), and across each triangle or unfolded virtual triangle
// (X, Y) whose two corners have the same owner (point_source_update, X's
// owner): the updates host/geodesics/fast_iterative pushes, listed by target.
// Only a vertex one of whose inputs changed in the last round (`dirty`)
// computes; one that changed tells its dependents. The three dirty buffers
// rotate: a round reads one, marks the next, and clears the one after. A
// vertex that changed in the last round copies itself into the buffer this
// round writes (`changed_at`); the rest leave both buffers as they are.
// Whether anything changed goes to round_changed[flag], so the host reads one
// flag per batch of rounds, not one per round.
#pragma OPENCL FP_CONTRACT OFF

#include "point_source_update.h"

#define NO_POINT 0xFFFFFFFFu

// A candidate of `target` from corners x and y (host: PullUpdate in
// particles/device_surface_voronoi.cpp): every field 4 bytes.
typedef struct {
  uint x, y;
  float frame[3];  // length_xy, c_x, c_y: target from (x, y)
} pull_update;

__kernel void surface_voronoi_round(uint vertex_count, uint round, __global const uint* ring_offsets,
                                    __global const uint* ring_neighbors, __global const float* edge_lengths,
                                    __global const uint* pull_offsets, __global const pull_update* pulls,
                                    __global const uint* dependent_offsets, __global const uint* dependents,
                                    __global const float* distance_in, __global const uint* owner_in,
                                    __global float* distance_out, __global uint* owner_out,
                                    __global const uchar* dirty_in, __global uchar* dirty_out,
                                    __global uchar* dirty_clear, __global uint* changed_at,
                                    __global uint* round_changed, uint flag) {
  const uint v = (uint)get_global_id(0);
  if (v >= vertex_count) return;
  dirty_clear[v] = 0;
  const int dirty = dirty_in[v] != 0;
  // Unchanged and changed more than a round ago: both buffers hold v already.
  if (!dirty && changed_at[v] + 1u != round) return;
  const float was = distance_in[v];
  const uint was_owner = owner_in[v];
  float best = was;
  uint best_owner = was_owner;
  if (dirty) {
    for (uint k = ring_offsets[v]; k < ring_offsets[v + 1]; ++k) {
      const uint w = ring_neighbors[k];
      const uint o = owner_in[w];
      if (o == NO_POINT) continue;
      const float candidate = distance_in[w] + edge_lengths[k];
      if (candidate < best || (candidate == best && o < best_owner)) {
        best = candidate;
        best_owner = o;
      }
    }
    for (uint k = pull_offsets[v]; k < pull_offsets[v + 1]; ++k) {
      const pull_update p = pulls[k];
      const uint o = owner_in[p.x];
      if (o == NO_POINT || owner_in[p.y] != o) continue;
      const float candidate = point_source_update(p.frame[0], p.frame[1], p.frame[2], distance_in[p.x], distance_in[p.y]);
      if (!(candidate < INFINITY)) continue;
      if (candidate < best || (candidate == best && o < best_owner)) {
        best = candidate;
        best_owner = o;
      }
    }
  }
  distance_out[v] = best;
  owner_out[v] = best_owner;
  if (best != was || best_owner != was_owner) {
    changed_at[v] = round;
    for (uint k = dependent_offsets[v]; k < dependent_offsets[v + 1]; ++k) dirty_out[dependents[k]] = 1;
    round_changed[flag] = 1;  // every writer stores the same value
  }
}
