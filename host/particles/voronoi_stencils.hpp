#pragma once
// What the rounds of the geodesic Voronoi diagram read
// (kernels/surface_voronoi_round.h), built once per mesh for the host
// (particles/surface_voronoi_rounds) and the device
// (particles/device_surface_voronoi): fast marching's and the fast
// iterative method's stencils (geodesics/triangle_stencils) listed by the
// vertex they update, and for each vertex the vertices whose candidates
// read it (a vertex that changes marks them for the next round).
#include <cstdint>
#include <vector>

#include "mesh/surface_mesh.hpp"
#include "surface_voronoi_round.h"

namespace meshparticles {

struct VoronoiStencils {
  std::vector<float> edge_lengths;  // per entry of the mesh's one-rings
  std::vector<std::uint32_t> pull_offsets;
  std::vector<pull_update> pulls;
  std::vector<std::uint32_t> dependent_offsets;
  std::vector<VertexId> dependents;

  // The view the shared round reads (valid while this lives, with `mesh`).
  voronoi_stencils view(const SurfaceMesh& mesh) const;
};

VoronoiStencils voronoi_stencils_of(const SurfaceMesh& mesh);

}  // namespace meshparticles
