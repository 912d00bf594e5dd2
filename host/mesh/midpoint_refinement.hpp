#pragma once
// The input surface cut finer: each triangle into four at the midpoints of
// its edges, `levels` times over. The refined mesh is the input surface
// exactly (its vertices lie on the input's flat triangles), with 4^levels
// times the triangles, so particles on its vertices sit anywhere on the
// input at that resolution. Each vertex knows where it lies on the input: a
// triangle of the input and barycentric weights.
#include <array>
#include <cstddef>
#include <vector>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// A point of the input surface: weights[k] of corners[k] (vertex ids of the
// input SurfaceMesh), the weights non-negative and summing to 1.
struct SurfacePoint {
  Triangle corners{};
  std::array<double, 3> weights{};
  // The corner nearest to the point in space (ties: the first).
  VertexId nearest_corner(const SurfaceMesh& input) const;
};

struct RefinedMesh {
  SurfaceMesh mesh;
  unsigned levels = 0;
  std::vector<SurfacePoint> on_input;  // per vertex of `mesh`
};

// `levels` rounds of midpoint subdivision. At 0, the input itself (copied).
// Vertices 0..V-1 are the input's, in its order.
RefinedMesh refine_by_midpoints(const SurfaceMesh& input, unsigned levels);

// The vertex count `levels` rounds give, from the input's counts (exact:
// V + E new vertices a round, triangles times four).
std::size_t refined_vertex_count(const SurfaceMesh& input, unsigned levels);

}  // namespace meshparticles
