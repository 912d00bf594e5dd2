#include "reports/particle_locations.hpp"

#include "mesh/midpoint_refinement.hpp"

namespace meshparticles {

namespace {

// The corner of the location's triangle nearest to its point (ties: the first).
VertexId nearest_corner(const SurfaceMesh& mesh, const SurfaceLocation& location) {
  const Triangle& corners = mesh.triangles()[location.triangle];
  const auto& positions = mesh.positions();
  int best = 0;
  for (int k = 1; k < 3; ++k) {
    if (distance(location.at, positions[corners[k]]) < distance(location.at, positions[corners[best]])) best = k;
  }
  return corners[best];
}

// The input vertex nearest to particle i: a paper particle's own vertex, a
// spread particle's nearest corner of its input triangle.
VertexId nearest_input_vertex(const SurfaceMesh& input, const RunResult& result, std::size_t i,
                              const SurfaceLocation& on_input) {
  switch (result.plan.method) {
    case Method::spread: return nearest_corner(input, on_input);
    case Method::paper: return result.outcome.positions[i];
  }
  return 0;
}

}  // namespace

std::vector<SurfaceLocation> particles_on_input(const SurfaceMesh& input, const RunResult& result) {
  const std::vector<VertexId>& positions = result.outcome.positions;
  std::vector<SurfaceLocation> locations;
  locations.reserve(positions.size());
  switch (result.plan.method) {
    case Method::spread: {
      // Vertices of the working mesh, each at its place on the input.
      const std::vector<SurfaceLocation>& on_input = result.spread->working->on_input;
      for (const VertexId v : positions) locations.push_back(on_input[v]);
      break;
    }
    case Method::paper: {
      // The input's own vertices.
      const std::vector<SurfaceLocation> at_vertices = vertex_locations(input);
      for (const VertexId v : positions) locations.push_back(at_vertices[v]);
      break;
    }
  }
  return locations;
}

std::vector<ParticleLocation> particle_locations(const SurfaceMesh& input, const RunResult& result) {
  const std::vector<VertexId>& positions = result.outcome.positions;
  const SurfaceMesh& surface = result.particle_mesh(input);
  const std::vector<SurfaceLocation> on_input = particles_on_input(input, result);
  std::vector<ParticleLocation> locations(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const SurfaceLocation& point = on_input[i];
    const Triangle& corners = input.triangles()[point.triangle];
    ParticleLocation& location = locations[i];
    location.at = surface.positions()[positions[i]];
    location.input_vertex = input.input_id(nearest_input_vertex(input, result, i, point));
    for (int k = 0; k < 3; ++k) {
      location.on_input.corners[k] = input.input_id(corners[k]);
      location.on_input.weights[k] = point.weights[k];
    }
  }
  return locations;
}

}  // namespace meshparticles
