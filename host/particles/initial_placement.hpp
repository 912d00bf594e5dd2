#pragma once
// Where particles start (--init): all on one vertex (the paper's start),
// distinct random vertices, or geodesic farthest-point sampling.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geodesics/geodesic_solver.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/particle_params.hpp"
#include "particles/particle_voronoi.hpp"

namespace meshparticles {

struct PlacementRequest {
  Init init = Init::farthest;
  std::size_t particle_count = 0;  // 1..V for random and farthest
  std::uint64_t seed = 0;
  // v0: the vertex; farthest: the first sample (else a seeded random vertex).
  std::optional<VertexId> start_vertex;
  GeodesicMethod method = GeodesicMethod::fast_marching;  // farthest: the solver that measures
};

// Farthest-point sampling marches from each new sample only over the region
// it takes over (GeodesicSolver::lower_nearest): no distance table needed.
// `quiet`: no progress line.
std::vector<VertexId> place_particles(const SurfaceMesh& mesh, const PlacementRequest& request, bool quiet = true);
// The same, measuring with `solver` (of `mesh`) instead of one of its own:
// for a caller that marches on the mesh again afterwards.
std::vector<VertexId> place_particles(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                      const PlacementRequest& request, bool quiet = true);

// The start with, for a farthest start, the geodesic Voronoi diagram its
// samples were chosen in (sample k as particle k; on `mesh`, by `solver`,
// which must outlive it): farthest-point optimization goes on from it
// instead of marching every region again.
struct Placement {
  std::vector<VertexId> vertices;
  std::unique_ptr<ParticleVoronoi> diagram;  // null unless a farthest start
};
Placement place_particles_with_diagram(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                       const PlacementRequest& request, bool quiet = true);

}  // namespace meshparticles
