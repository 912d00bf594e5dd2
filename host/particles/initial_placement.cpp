#include "particles/initial_placement.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "common/progress.hpp"
#include "common/random.hpp"
#include "geodesics/solver_factory.hpp"

namespace meshparticles {

namespace {

std::vector<VertexId> distinct_random_vertices(std::size_t vertex_count, std::size_t count, std::uint64_t seed) {
  // The first `count` steps of a Fisher-Yates shuffle.
  std::vector<VertexId> vertices(vertex_count);
  std::iota(vertices.begin(), vertices.end(), VertexId{0});
  SplitMix64 random(seed);
  for (std::size_t i = 0; i < count; ++i) std::swap(vertices[i], vertices[i + random.below(vertex_count - i)]);
  vertices.resize(count);
  return vertices;
}

// Each new sample is the vertex farthest from all samples so far (ties: the
// smaller id), found in the geodesic Voronoi diagram of the samples, sample
// k as particle k. Another component is infinitely far, so each gets a
// sample before any gets a second.
Placement farthest_point_samples(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::size_t count,
                                 VertexId first, bool quiet) {
  Placement placement;
  placement.diagram = std::make_unique<ParticleVoronoi>(mesh, solver, count);
  ParticleVoronoi& diagram = *placement.diagram;
  std::vector<VertexId>& samples = placement.vertices;
  samples.reserve(count);
  ProgressLine progress("farthest-point start", count, quiet || count < 2000);
  VertexId next = first;
  while (true) {
    diagram.insert(std::uint32_t(samples.size()), next);
    samples.push_back(next);
    if (samples.size() == count) break;
    next = *diagram.farthest();  // count <= vertices: one is left
    progress.update(samples.size());
  }
  progress.finish();
  return placement;
}

// `solver`: the farthest start's, or null to make one (v0 and random need none).
Placement place(const SurfaceMesh& mesh, const GeodesicSolver* solver, const PlacementRequest& request, bool quiet) {
  const std::size_t vertex_count = mesh.vertex_count();
  switch (request.init) {
    case Init::v0:
      return {std::vector<VertexId>(request.particle_count, request.start_vertex.value_or(0)), nullptr};
    case Init::random:
      return {distinct_random_vertices(vertex_count, request.particle_count, request.seed), nullptr};
    case Init::farthest: {
      const VertexId first = request.start_vertex ? *request.start_vertex
                                                  : VertexId(SplitMix64(request.seed).below(vertex_count));
      if (solver) return farthest_point_samples(mesh, *solver, request.particle_count, first, quiet);
      // The diagram would outlive the solver made here: not kept.
      return {farthest_point_samples(mesh, *make_geodesic_solver(mesh, request.method), request.particle_count, first,
                                     quiet)
                  .vertices,
              nullptr};
    }
  }
  return {};
}

}  // namespace

std::vector<VertexId> place_particles(const SurfaceMesh& mesh, const PlacementRequest& request, bool quiet) {
  return place(mesh, nullptr, request, quiet).vertices;
}

std::vector<VertexId> place_particles(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                      const PlacementRequest& request, bool quiet) {
  return place(mesh, &solver, request, quiet).vertices;
}

Placement place_particles_with_diagram(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                       const PlacementRequest& request, bool quiet) {
  return place(mesh, &solver, request, quiet);
}

}  // namespace meshparticles
