#include "particles/initial_placement.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "common/progress.hpp"
#include "common/random.hpp"
#include "geodesics/solver_factory.hpp"
#include "particles/farthest_vertex.hpp"

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
// smaller id). Another component is infinitely far, so each gets a sample
// before any gets a second.
std::vector<VertexId> farthest_point_samples(const SurfaceMesh& mesh, const GeodesicSolver& solver, std::size_t count,
                                             VertexId first, bool quiet) {
  SolverScratch scratch;
  std::vector<float> nearest(mesh.vertex_count(), std::numeric_limits<float>::infinity());
  FarthestVertex farthest(nearest);
  std::vector<VertexId> samples, lowered;
  samples.reserve(count);
  ProgressLine progress("farthest-point start", count, quiet || count < 2000);
  VertexId next = first;
  while (true) {
    samples.push_back(next);
    farthest.take(next);
    if (samples.size() == count) break;
    solver.lower_nearest(next, nearest, scratch, lowered);
    farthest.lowered(lowered);
    next = *farthest.farthest();  // count <= vertices: one is left
    progress.update(samples.size());
  }
  progress.finish();
  return samples;
}

// `solver`: the farthest start's, or null to make one (v0 and random need none).
std::vector<VertexId> place(const SurfaceMesh& mesh, const GeodesicSolver* solver, const PlacementRequest& request,
                            bool quiet) {
  const std::size_t vertex_count = mesh.vertex_count();
  switch (request.init) {
    case Init::v0:
      return std::vector<VertexId>(request.particle_count, request.start_vertex.value_or(0));
    case Init::random:
      return distinct_random_vertices(vertex_count, request.particle_count, request.seed);
    case Init::farthest: {
      const VertexId first = request.start_vertex ? *request.start_vertex
                                                  : VertexId(SplitMix64(request.seed).below(vertex_count));
      if (solver) return farthest_point_samples(mesh, *solver, request.particle_count, first, quiet);
      return farthest_point_samples(mesh, *make_geodesic_solver(mesh, request.method), request.particle_count, first,
                                    quiet);
    }
  }
  return {};
}

}  // namespace

std::vector<VertexId> place_particles(const SurfaceMesh& mesh, const PlacementRequest& request, bool quiet) {
  return place(mesh, nullptr, request, quiet);
}

std::vector<VertexId> place_particles(const SurfaceMesh& mesh, const GeodesicSolver& solver,
                                      const PlacementRequest& request, bool quiet) {
  return place(mesh, &solver, request, quiet);
}

}  // namespace meshparticles
