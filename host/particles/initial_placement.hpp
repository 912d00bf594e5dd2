#pragma once
// Where particles start (--init): all on one vertex (the paper's start),
// distinct random vertices, or geodesic farthest-point sampling.
#include <cstdint>
#include <optional>
#include <vector>

#include "geodesics/distance_store.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

struct PlacementRequest {
  Init init = Init::farthest;
  std::size_t particle_count = 0;  // 1..V for random and farthest
  std::uint64_t seed = 0;
  // v0: the vertex; farthest: the first sample (else a seeded random vertex).
  std::optional<VertexId> start_vertex;
};

std::vector<VertexId> place_particles(const DistanceStore& distances, const PlacementRequest& request);

}  // namespace meshparticles
