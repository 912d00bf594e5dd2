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
// computes, and only the candidates that read such an input; one that
// changed tells its dependents. A vertex's distance, owner and when it last
// changed lie together (vertex_state): a neighbour costs one read. The three dirty buffers
// rotate: a round reads one, marks the next, and clears the one after. A
// vertex that changed in the last round copies itself into the buffer this
// round writes; the rest leave both buffers as they are.
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

// A vertex's state, one 16-byte read for a neighbour's candidate:
// VertexState in particles/device_surface_voronoi.cpp, the same layout.
// `stamp`: round + 2 in the state a round writes where the vertex changed,
// copied on otherwise; 1 marks the seeds ("changed" before round 0).
typedef struct {
  float distance;
  uint owner;
  uint stamp;
  uint unused;
} vertex_state;

__kernel void surface_voronoi_round(uint vertex_count, uint round, __global const uint* ring_offsets,
                                    __global const uint* ring_neighbors, __global const float* edge_lengths,
                                    __global const uint* pull_offsets, __global const pull_update* pulls,
                                    __global const uint* dependent_offsets, __global const uint* dependents,
                                    __global const vertex_state* state_in, __global vertex_state* state_out,
                                    __global const uchar* dirty_in, __global uchar* dirty_out,
                                    __global uchar* dirty_clear, __global uint* round_changed, uint flag) {
  const uint v = (uint)get_global_id(0);
  if (v >= vertex_count) return;
  dirty_clear[v] = 0;
  const int dirty = dirty_in[v] != 0;
  // A candidate reads the vertices it is computed from; one none of which
  // changed in the last round (stamp round + 1) was taken or beaten when
  // they last did: skipping it changes nothing.
  const uint recent = round + 1u;
  const vertex_state was = state_in[v];
  // Not dirty, and not changed in the last round: both buffers hold v already.
  if (!dirty && was.stamp != recent) return;
  float best = was.distance;
  uint best_owner = was.owner;
  if (dirty) {
    for (uint k = ring_offsets[v]; k < ring_offsets[v + 1]; ++k) {
      const vertex_state w = state_in[ring_neighbors[k]];
      if (w.stamp != recent || w.owner == NO_POINT) continue;
      const float candidate = w.distance + edge_lengths[k];
      if (candidate < best || (candidate == best && w.owner < best_owner)) {
        best = candidate;
        best_owner = w.owner;
      }
    }
    for (uint k = pull_offsets[v]; k < pull_offsets[v + 1]; ++k) {
      const pull_update p = pulls[k];
      const vertex_state x = state_in[p.x], y = state_in[p.y];
      if ((x.stamp != recent && y.stamp != recent) || x.owner == NO_POINT || y.owner != x.owner) continue;
      const float candidate = point_source_update(p.frame[0], p.frame[1], p.frame[2], x.distance, y.distance);
      if (!(candidate < INFINITY)) continue;
      if (candidate < best || (candidate == best && x.owner < best_owner)) {
        best = candidate;
        best_owner = x.owner;
      }
    }
  }
  const int changed = best != was.distance || best_owner != was.owner;
  vertex_state now;
  now.distance = best;
  now.owner = best_owner;
  now.stamp = changed ? round + 2u : was.stamp;
  now.unused = 0;
  state_out[v] = now;
  if (changed) {
    for (uint k = dependent_offsets[v]; k < dependent_offsets[v + 1]; ++k) dirty_out[dependents[k]] = 1;
    round_changed[flag] = 1;  // every writer stores the same value
  }
}
