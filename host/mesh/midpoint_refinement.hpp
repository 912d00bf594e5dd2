#pragma once
// The input surface cut finer at the midpoints of its edges, everywhere
// (each triangle into four, `levels` times over) or where the edges are
// long (each edge longer than a length split, a triangle with one, two or
// three split edges into two, three or four, round after round). The
// refined mesh is the input surface exactly (its vertices lie on the
// input's flat triangles), so particles on its vertices sit anywhere on the
// input at that resolution. Each vertex knows where it lies on the input: a
// SurfaceLocation of the input mesh (a triangle of it and barycentric weights).
#include <cstddef>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Each vertex of `mesh` as a point of it: the first triangle holding it,
// with all the weight on that corner (a SurfaceMesh has no vertex outside
// its triangles).
std::vector<SurfaceLocation> vertex_locations(const SurfaceMesh& mesh);

struct RefinedMesh {
  SurfaceMesh mesh;
  unsigned levels = 0;  // rounds of splitting
  std::vector<SurfaceLocation> on_input;  // per vertex of `mesh`: where it lies on the input
  // refine_by_midpoints_then_long_edges stopped with edges still longer than
  // asked: the next round would have passed its vertex cap.
  bool stopped_at_cap = false;
};

// `levels` rounds of midpoint subdivision. At 0, the input itself (copied).
// Vertices 0..V-1 are the input's, in its order.
RefinedMesh refine_by_midpoints(const SurfaceMesh& input, unsigned levels);

// Splits every edge longer than `longest` at its midpoint, round after
// round, until none is, or until the next round would pass `max_vertices`
// (decided before the round, so the mesh never does). Vertices 0..V-1 are
// the input's. Every vertex has barycentric weights with denominators of at
// most 2^rounds, so it is also a vertex of refine_by_midpoints at `levels`
// = the rounds.
RefinedMesh refine_long_edges(const SurfaceMesh& input, double longest, std::size_t max_vertices);
// `levels` rounds of refine_by_midpoints (they do not count against
// `max_vertices`), then refine_long_edges.
RefinedMesh refine_by_midpoints_then_long_edges(const SurfaceMesh& input, unsigned levels, double longest,
                                                std::size_t max_vertices);

// The vertex count `levels` rounds give, from the input's counts (exact:
// V + E new vertices a round, triangles times four).
std::size_t refined_vertex_count(const SurfaceMesh& input, unsigned levels);

}  // namespace meshparticles
