// The geodesic Voronoi diagram of points on a surface, sampled at the
// vertices: the device twin of host/particles/surface_voronoi_rounds, the
// same rounds (docs/GEODESICS.md, "What runs where"). The host seeds each
// point's triangle corners (distance, owner); rounds of a multi-source
// label-correcting sweep (surface_voronoi_round.h, one work-item per
// vertex) then give every vertex its distance to the nearest point and
// which point that is.
//
// A round reads one state buffer and writes the other (double-buffered). A
// vertex's distance, owner and when it last changed lie together
// (vertex_state): a neighbour costs one read. The three dirty buffers
// rotate: a round reads one, marks the next, and clears the one after. A
// vertex that changed in the last round copies itself into the buffer this
// round writes; the rest leave both buffers as they are. Whether anything
// changed goes to round_changed[flag], so the host reads one flag per batch
// of rounds, not one per round.
#pragma OPENCL FP_CONTRACT OFF

#include "surface_voronoi_round.h"

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
  // Not dirty, and not changed in the last round: both buffers hold v already.
  if (!dirty && state_in[v].stamp != round + 1u) return;
  const voronoi_stencils mesh = {ring_offsets, ring_neighbors, edge_lengths, pull_offsets, pulls};
  vertex_state now;
  const int changed = voronoi_vertex_round(mesh, v, round, state_in, dirty, &now);
  state_out[v] = now;
  if (changed) {
    for (uint k = dependent_offsets[v]; k < dependent_offsets[v + 1]; ++k) dirty_out[dependents[k]] = 1;
    round_changed[flag] = 1;  // every writer stores the same value
  }
}
