// One vertex's step in a round of the geodesic Voronoi diagram's
// multi-source label-correcting sweep (the fast iterative method's
// updates): written once for the device (surface_voronoi.cl, one
// work-item a vertex) and the host (host/particles/surface_voronoi_rounds,
// a list of the vertices a round touches), so both give the same bits.
//
// Deterministic whatever the device and the order of the vertices: a round
// reads only the states the last one left (Jacobi) and each vertex takes
// the smallest of its candidates, ties to the smaller owner, so
// (distance, owner) only ever falls and the rounds end. The float
// arithmetic is as written: the device builds it without unsafe math and
// with correctly rounded division and square root (FloatMath::exact), and
// nothing is contracted into fused multiply-adds (FP_CONTRACT OFF there,
// -ffp-contract=off on the host: CMakeLists.txt).
//
// A vertex pulls its candidates: along each edge from a neighbour (d(w) +
// |vw|, w's owner), and across each triangle or unfolded virtual triangle
// (X, Y) whose two corners have the same owner (point_source_update, X's
// owner): the updates host/geodesics/fast_iterative pushes, listed by
// target. Only a vertex one of whose inputs changed in the last round
// (`dirty`) computes, and only the candidates that read such an input.
#ifndef SURFACE_VORONOI_ROUND_H
#define SURFACE_VORONOI_ROUND_H

#include "host_or_device.h"
#include "point_source_update.h"

#define VORONOI_NO_POINT 0xFFFFFFFFu

// A candidate of a target vertex from corners x and y: every field 4 bytes.
typedef struct {
  unsigned int x, y;
  float frame[3];  // length_xy, c_x, c_y: the target from (x, y)
} pull_update;

// A vertex's state, one 16-byte read for a neighbour's candidate. `stamp`:
// round + 2 where the vertex changed in that round, kept otherwise; 1
// marks the seeds ("changed" before round 0).
typedef struct {
  float distance;
  unsigned int owner;
  unsigned int stamp;
  unsigned int unused;
} vertex_state;

// The mesh as the rounds read it: one-rings with their edge lengths, and
// each vertex's candidates (pull_offsets into pulls).
typedef struct {
  GLOBAL_MEMORY const unsigned int* ring_offsets;
  GLOBAL_MEMORY const unsigned int* ring_neighbors;
  GLOBAL_MEMORY const float* edge_lengths;
  GLOBAL_MEMORY const unsigned int* pull_offsets;
  GLOBAL_MEMORY const pull_update* pulls;
} voronoi_stencils;

// Vertex v's state after round `round`, from `state_in` (the last round's)
// and whether v is dirty; the caller skips a vertex neither dirty nor
// changed in the last round (its state stays). Returns whether it changed.
static inline int voronoi_vertex_round(voronoi_stencils mesh, unsigned int v, unsigned int round,
                                       GLOBAL_MEMORY const vertex_state* state_in, int dirty, vertex_state* now) {
  // A candidate reads the vertices it is computed from; one none of which
  // changed in the last round (stamp round + 1) was taken or beaten when
  // they last did: skipping it changes nothing.
  const unsigned int recent = round + 1u;
  const vertex_state was = state_in[v];
  float best = was.distance;
  unsigned int best_owner = was.owner;
  if (dirty) {
    for (unsigned int k = mesh.ring_offsets[v]; k < mesh.ring_offsets[v + 1]; ++k) {
      const vertex_state w = state_in[mesh.ring_neighbors[k]];
      if (w.stamp != recent || w.owner == VORONOI_NO_POINT) continue;
      const float candidate = w.distance + mesh.edge_lengths[k];
      if (candidate < best || (candidate == best && w.owner < best_owner)) {
        best = candidate;
        best_owner = w.owner;
      }
    }
    for (unsigned int k = mesh.pull_offsets[v]; k < mesh.pull_offsets[v + 1]; ++k) {
      const pull_update p = mesh.pulls[k];
      const vertex_state x = state_in[p.x], y = state_in[p.y];
      if ((x.stamp != recent && y.stamp != recent) || x.owner == VORONOI_NO_POINT || y.owner != x.owner) continue;
      const float candidate = point_source_update(p.frame[0], p.frame[1], p.frame[2], x.distance, y.distance);
      if (!(candidate < INFINITY)) continue;
      if (candidate < best || (candidate == best && x.owner < best_owner)) {
        best = candidate;
        best_owner = x.owner;
      }
    }
  }
  const int changed = best != was.distance || best_owner != was.owner;
  now->distance = best;
  now->owner = best_owner;
  now->stamp = changed ? round + 2u : was.stamp;
  now->unused = 0;
  return changed;
}

#endif
